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
  if (in.dispersion.model == "lj") {
    s.dispersion.enabled = true;
    s.dispersion.epsilon = in.dispersion.epsilon;
    s.dispersion.r0 = in.dispersion.r0;
    s.dispersion.cutoff = in.dispersion.cutoff;
    s.dispersion.ewald = in.dispersion.summation == "ewald";
    s.dispersion.ewaldTolerance = in.dispersion.ewaldTolerance;
    for (const auto& [element, p] : in.dispersion.elements) {
      s.dispersion.elements.push_back(element);
      s.dispersion.elementEpsilon.push_back(p.epsilon);
      s.dispersion.elementR0.push_back(p.r0);
    }
  }
  if (in.dispersion.model == "kc") {
    s.kc.enabled = true;
    s.kc.parameters = in.dispersion.kcParameters;
    s.kc.cutoff = in.dispersion.cutoff;
    s.kc.taperStart = in.dispersion.kcTaperStart;
    s.kc.bondCutoff = in.dispersion.kcBondCutoff;
  }
  s.scc = in.scc;  // the same struct: read by dftb/scc_table.hpp
  return s;
}

dftb::Calculator makeCalculator(const CellInput& in, parallel::Communicator comm) {
  return dftb::Calculator(loadParameters(in), calculatorSettings(in), std::move(comm));
}

}  // namespace mesochain::objective
