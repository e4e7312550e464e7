#pragma once
// The checkpoint of one relaxation (`mesochain run` with task relax, docs/command-line.md): where
// the relaxation stands (RelaxProgress: atoms, T search, evaluations), written atomically as a scan
// checkpoint of a single point in progress, so that the identity checks of scans apply: the
// checkpoint records the input identity (the calculator settings, the relax settings, the tables
// and the cell: scanIdentity) and a checkpoint of other settings is refused naming each change.
#include <memory>
#include <string>

#include "dftb/calculator.hpp"
#include "objective/drivers/relax.hpp"

namespace mesochain::objective {

// What identifies the relaxation of `cell` with `calculator` and `relax` (tables: the text of
// parameterIdentity); the progress callbacks of `relax` do not count.
struct RelaxInput {
  const ObjectiveCell& cell;
  const dftb::CalculatorSettings& calculator;
  const RelaxSettings& relax;
  std::string tables;
};

void writeRelaxCheckpoint(const std::string& path, const RelaxInput& input, const RelaxProgress& progress);

// The progress recorded in `path`. InputError naming the file: not a relaxation checkpoint, or one
// of other settings (naming each changed setting with both values), or of another cell.
std::shared_ptr<const RelaxProgress> readRelaxCheckpoint(const std::string& path, const RelaxInput& input);

}  // namespace mesochain::objective
