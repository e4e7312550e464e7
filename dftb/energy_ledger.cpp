#include "dftb/energy_ledger.hpp"

namespace mesochain::dftb {

void EnergyLedger::add(std::string_view name, EnergyKind kind, double value, std::string_view label) {
  if (!addToExisting(name, kind, value))
    entries_.push_back({std::string(name), std::string(label.empty() ? name : label), kind, value});
}

}  // namespace mesochain::dftb
