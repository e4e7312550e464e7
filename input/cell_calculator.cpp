#include "input/cell_calculator.hpp"

#include <utility>

namespace mesochain::objective {

std::shared_ptr<const dftb::ParameterSet> loadParameters(const CellInput& in) {
  return std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      in.cell.speciesNames, in.parameterFiles, in.source, in.maxAngularMomentum));
}

dftb::CalculatorSettings calculatorSettings(const CellInput& in) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = in.helicalKPoints;
  s.band.angular = in.angular;
  s.band.electronicTemperature = in.electronicTemperature;
  s.dispersion = in.dispersion.lj;  // the same structs: read by dftb/dispersion_table.hpp
  s.kc = in.dispersion.kc;
  s.scc = in.scc;  // the same struct: read by dftb/scc_table.hpp
  return s;
}

dftb::Calculator makeCalculator(const CellInput& in, parallel::Communicator comm) {
  return dftb::Calculator(loadParameters(in), calculatorSettings(in), std::move(comm));
}

}  // namespace mesochain::objective
