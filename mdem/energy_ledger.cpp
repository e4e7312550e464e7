#include "mdem/energy_ledger.hpp"

#include <stdexcept>

namespace mesochain::mdem {

void EnergyLedger::add(std::string_view name, EnergyKind kind, double value) {
  for (LedgerEntry& e : entries_)
    if (e.name == name) {
      if (e.kind != kind) throw std::logic_error("energy ledger: entry '" + e.name + "' reported with two kinds");
      e.value += value;
      return;
    }
  entries_.push_back({std::string(name), kind, value});
}

const LedgerEntry* EnergyLedger::find(std::string_view name) const {
  for (const LedgerEntry& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

double EnergyLedger::operator[](std::string_view name) const {
  const LedgerEntry* e = find(name);
  return e ? e->value : 0.0;
}

double EnergyLedger::sum(EnergyKind kind) const {
  double s = 0.0;
  for (const LedgerEntry& e : entries_)
    if (e.kind == kind) s += e.value;
  return s;
}

std::vector<std::string> EnergyLedger::names() const {
  std::vector<std::string> n;
  for (const LedgerEntry& e : entries_) n.push_back(e.name);
  return n;
}

}  // namespace mesochain::mdem
