#pragma once
// The energy ledger of a dftb evaluation: named energies per cell (Hartree) that the energy
// terms report. Nothing here knows which terms exist: the calculator's totals, the results JSON
// (`energies_hartree`), the terminal table and the tests read whatever entries the built terms
// reported, in their order.
//
// Three kinds of entry:
//   Energy    part of the total energy E (band, repulsive, dispersion, SCC double counting);
//   Entropy   the electronic entropy term T S (>= 0): F = E - TS is the Mermin free energy;
//   Reported  an energy reported beside the total, not part of it (an alternative breakdown
//             such as Tr(rho H0), or an error estimate).
// total() sums the Energy entries in their order, so a term that is built is counted: there is
// no list of term names to keep in step.
#include <string>
#include <string_view>

#include "common/named_ledger.hpp"

namespace mesochain::dftb {

enum class EnergyKind { Energy, Entropy, Reported };

struct LedgerEntry {
  std::string name;   // snake_case: the key under energies_hartree in the results JSON
  std::string label;  // the row of the terminal table
  EnergyKind kind = EnergyKind::Energy;
  double value = 0.0;  // Hartree per cell
};

// has, operator[] (0 for an entry not reported), at, merge, entries, names: common/named_ledger.hpp.
class EnergyLedger : public NamedLedger<LedgerEntry> {
 public:
  EnergyLedger() : NamedLedger("dftb energy ledger") {}
  // Adds `value` to the entry `name` (created at the end when new, with `label`; an empty label
  // is the name). The kind of an existing entry must match (a programming error otherwise:
  // std::logic_error).
  void add(std::string_view name, EnergyKind kind, double value, std::string_view label = {});

  double total() const { return sum(EnergyKind::Energy); }    // E
  double entropy() const { return sum(EnergyKind::Entropy); }  // TS
  double free() const { return total() - entropy(); }         // F = E - TS (Mermin)
  double extrapolated() const { return total() - 0.5 * entropy(); }  // E - TS/2, the T -> 0 estimate
};

}  // namespace mesochain::dftb
