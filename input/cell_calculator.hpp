#pragma once
// The dftb::Calculator a cell file asks for: its parameter tables, k-points, electronic
// temperature and dispersion (shared by `mesochain run`, `mesochain scan` and benchmarks).
#include <memory>
#include <string>

#include "dftb/calculator.hpp"
#include "input/cell_file.hpp"

namespace mesochain::objective {

std::shared_ptr<const dftb::ParameterSet> loadParameters(const CellInput& input);
dftb::CalculatorSettings calculatorSettings(const CellInput& input);
// comm: the ranks that share its evaluations (dftb::Calculator).
dftb::Calculator makeCalculator(const CellInput& input,
                                parallel::Communicator comm = parallel::Communicator::world());
// The parameter tables by element pair and content, and the angular momenta used of them: part
// of the input identity of checkpoints (ScanSettings::identity), so that one made with other
// tables is refused while the same tables at another path (a moved or re-cloned project, another
// build) are accepted.
std::string parameterIdentity(const CellInput& input);

}  // namespace mesochain::objective
