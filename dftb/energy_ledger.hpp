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
#include <vector>

namespace mesochain::dftb {

enum class EnergyKind { Energy, Entropy, Reported };

struct LedgerEntry {
  std::string name;   // snake_case: the key under energies_hartree in the results JSON
  std::string label;  // the row of the terminal table
  EnergyKind kind = EnergyKind::Energy;
  double value = 0.0;  // Hartree per cell
};

class EnergyLedger {
 public:
  // Adds `value` to the entry `name` (created at the end when new, with `label`; an empty label
  // is the name). The kind of an existing entry must match (a programming error otherwise:
  // std::logic_error).
  void add(std::string_view name, EnergyKind kind, double value, std::string_view label = {});
  // Every entry of `other`, added in its order.
  void merge(const EnergyLedger& other);

  bool has(std::string_view name) const { return find(name) != nullptr; }
  // The value of an entry; 0 when the ledger has no such entry (a term that is not built).
  double operator[](std::string_view name) const;
  // The value of an entry that must be there (std::out_of_range otherwise).
  double at(std::string_view name) const;

  double total() const { return sum(EnergyKind::Energy); }    // E
  double entropy() const { return sum(EnergyKind::Entropy); }  // TS
  double free() const { return total() - entropy(); }         // F = E - TS (Mermin)
  double extrapolated() const { return total() - 0.5 * entropy(); }  // E - TS/2, the T -> 0 estimate

  const std::vector<LedgerEntry>& entries() const { return entries_; }
  bool empty() const { return entries_.empty(); }

 private:
  const LedgerEntry* find(std::string_view name) const;
  double sum(EnergyKind kind) const;
  std::vector<LedgerEntry> entries_;
};

}  // namespace mesochain::dftb
