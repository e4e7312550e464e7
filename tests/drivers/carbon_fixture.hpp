#pragma once
// Shared set-up for the driver tests: the pbc-0-3 carbon table, calculator settings at 300 K,
// the C-C bond length.
#include <memory>
#include <string>

#include "common/units.hpp"
#include "dftb/calculator.hpp"

namespace mesochain::objective::testing {

inline std::shared_ptr<const dftb::ParameterSet> carbon() {
  return std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C"}, {{"C-C", std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf"}}, "test"));
}

inline dftb::CalculatorSettings settings(int kpoints) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = kpoints;
  s.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
  return s;
}

inline const double kBond = 1.42 * units::kAngstromInBohr;

}  // namespace mesochain::objective::testing
