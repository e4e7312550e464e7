#pragma once
// The dftb::Calculator a cell file asks for: its parameter tables, k-points, electronic
// temperature and dispersion (shared by `mesochain run`, `mesochain scan` and benchmarks).
#include <memory>

#include "dftb/calculator.hpp"
#include "input/cell_file.hpp"

namespace mesochain::objective {

std::shared_ptr<const dftb::ParameterSet> loadParameters(const CellInput& input);
dftb::CalculatorSettings calculatorSettings(const CellInput& input);
// comm: the ranks that share its evaluations (dftb::Calculator).
dftb::Calculator makeCalculator(const CellInput& input,
                                parallel::Communicator comm = parallel::Communicator::world());

}  // namespace mesochain::objective
