#include "dftb/energy_ledger.hpp"

#include <stdexcept>

namespace mesochain::dftb {

void EnergyLedger::add(std::string_view name, EnergyKind kind, double value,
                       std::string_view label) {
  for (LedgerEntry& e : entries_)
    if (e.name == name) {
      if (e.kind != kind)
        throw std::logic_error("dftb energy ledger: entry '" + e.name + "' reported with two kinds");
      e.value += value;
      return;
    }
  entries_.push_back({std::string(name), std::string(label.empty() ? name : label), kind, value});
}

void EnergyLedger::merge(const EnergyLedger& other) {
  for (const LedgerEntry& e : other.entries_) add(e.name, e.kind, e.value, e.label);
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

double EnergyLedger::at(std::string_view name) const {
  const LedgerEntry* e = find(name);
  if (!e) throw std::out_of_range("dftb energy ledger: no entry '" + std::string(name) + "'");
  return e->value;
}

double EnergyLedger::sum(EnergyKind kind) const {
  double s = 0.0;
  for (const LedgerEntry& e : entries_)
    if (e.kind == kind) s += e.value;
  return s;
}

}  // namespace mesochain::dftb
