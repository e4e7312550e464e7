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
#include <vector>

namespace mesochain::mdem {

enum class EnergyKind { Kinetic, Potential, Dissipated };

struct LedgerEntry {
  std::string name;  // snake_case, e.g. "stretching"; the CSV column is name + "_zJ"
  EnergyKind kind = EnergyKind::Potential;
  double value = 0.0;  // zJ
};

class EnergyLedger {
 public:
  // Adds `value` to the entry `name` (created at the end when new). The kind of an existing
  // entry must match (a programming error otherwise: std::logic_error).
  void add(std::string_view name, EnergyKind kind, double value);

  bool has(std::string_view name) const { return find(name) != nullptr; }
  // The value of an entry; 0 when the ledger has no such entry (an effect that is not built
  // stores nothing).
  double operator[](std::string_view name) const;

  double kinetic() const { return sum(EnergyKind::Kinetic); }
  double potential() const { return sum(EnergyKind::Potential); }
  double dissipated() const { return sum(EnergyKind::Dissipated); }
  double total() const { return kinetic() + potential(); }

  const std::vector<LedgerEntry>& entries() const { return entries_; }
  // Entry names in order (the layout of a CSV row).
  std::vector<std::string> names() const;

 private:
  const LedgerEntry* find(std::string_view name) const;
  double sum(EnergyKind kind) const;
  std::vector<LedgerEntry> entries_;
};

class BinaryWriter;
class BinaryReader;
// A ledger in checkpoints (time series samples): entry count, then name, kind, value per entry;
// an unknown kind is the reader's failure (naming the checkpoint).
void writeLedger(BinaryWriter& out, const EnergyLedger& ledger);
EnergyLedger readLedger(BinaryReader& in);

}  // namespace mesochain::mdem
