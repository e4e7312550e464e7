#pragma once
// The results JSON of `mesochain run` (documented key by key in docs/results.md) and the
// human-readable summary printed to the terminal.
#include <iosfwd>

#include <nlohmann/json.hpp>

#include "dftb/calculator.hpp"
#include "input/cell_file.hpp"
#include "objective/drivers/relax.hpp"

namespace mesochain::app {

nlohmann::json resultJson(const objective::CellInput& input, const objective::ObjectiveCell& cell,
                          const dftb::Result& result, const objective::RelaxOutcome* relax);
void printSummary(std::ostream& out, const objective::CellInput& input,
                  const objective::ObjectiveCell& cell, const dftb::Result& result,
                  const objective::RelaxOutcome* relax);

}  // namespace mesochain::app
