#include "input/cell_calculator.hpp"

#include <fstream>
#include <sstream>
#include <utility>

#include <fmt/format.h>

namespace mesochain::objective {

std::shared_ptr<const dftb::ParameterSet> loadParameters(const CellInput& in) {
  return std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      in.cell.speciesNames, in.parameterFiles, in.source, in.maxAngularMomentum));
}

dftb::CalculatorSettings calculatorSettings(const CellInput& in) {
  dftb::CalculatorSettings s;
  // The structs the tables' readers filled (dftb/band_table.hpp, dispersion_table.hpp,
  // scc_table.hpp), handed over as they are.
  s.band = in.band;
  s.dispersion = in.dispersion.lj;
  s.kc = in.dispersion.kc;
  s.scc = in.scc;
  return s;
}

dftb::Calculator makeCalculator(const CellInput& in, parallel::Communicator comm) {
  return dftb::Calculator(loadParameters(in), calculatorSettings(in), std::move(comm));
}

std::string parameterIdentity(const CellInput& cell) {
  std::string s;
  for (const auto& [pair, file] : cell.parameterFiles) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    s += fmt::format("table {} {}\n", pair, content.str());
  }
  // The basis of each species (the tables hold up to d; l_max may restrict it).
  for (const auto& [species, lmax] : cell.maxAngularMomentum)
    s += fmt::format("max_angular_momentum {} {}\n", species, lmax);
  return s;
}

}  // namespace mesochain::objective
