#pragma once
// The energy ledger: named energies (zJ) that the effects of a simulation report. Nothing here
// knows which effects exist: outputs (CSV columns, terminal lines, plots, checkpoints) are made
// from whatever entries the built effects reported, in their order.
//
// Three kinds of entry:
//   kinetic     the simulation's kinetic energies (translational, rotational);
//   potential   energy stored by an effect (bonds, contacts, loads): part of total();
//   dissipated  work an effect has removed from the system so far (>= 0; dashpots): not stored,
//               so not in total(); total() + dissipated() is conserved without other damping.
#include <string>
#include <string_view>

#include "common/named_ledger.hpp"

namespace mesochain::mdem {

enum class EnergyKind { Kinetic, Potential, Dissipated };

struct LedgerEntry {
  std::string name;  // snake_case, e.g. "stretching"; the CSV column is name + "_zJ"
  EnergyKind kind = EnergyKind::Potential;
  double value = 0.0;  // zJ
};

// has, operator[] (0 for an entry not reported: an effect that is not built stores nothing),
// entries, names (the layout of a CSV row): common/named_ledger.hpp.
class EnergyLedger : public NamedLedger<LedgerEntry> {
 public:
  EnergyLedger() : NamedLedger("energy ledger") {}
  // Adds `value` to the entry `name` (created at the end when new). The kind of an existing
  // entry must match (a programming error otherwise: std::logic_error).
  void add(std::string_view name, EnergyKind kind, double value) {
    if (!addToExisting(name, kind, value)) entries_.push_back({std::string(name), kind, value});
  }

  double kinetic() const { return sum(EnergyKind::Kinetic); }
  double potential() const { return sum(EnergyKind::Potential); }
  double dissipated() const { return sum(EnergyKind::Dissipated); }
  double total() const { return kinetic() + potential(); }
};

class BinaryWriter;
class BinaryReader;
// A ledger in checkpoints (time series samples): entry count, then name, kind, value per entry;
// an unknown kind is the reader's failure (naming the checkpoint).
void writeLedger(BinaryWriter& out, const EnergyLedger& ledger);
EnergyLedger readLedger(BinaryReader& in);

}  // namespace mesochain::mdem
