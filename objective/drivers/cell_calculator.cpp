#include "objective/drivers/cell_calculator.hpp"

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
  if (in.dispersion.model == "lj") {
    s.dispersion.enabled = true;
    s.dispersion.epsilon = in.dispersion.epsilon;
    s.dispersion.r0 = in.dispersion.r0;
    s.dispersion.cutoff = in.dispersion.cutoff;
  }
  return s;
}

dftb::Calculator makeCalculator(const CellInput& in) {
  return dftb::Calculator(loadParameters(in), calculatorSettings(in));
}

}  // namespace mesochain::objective
