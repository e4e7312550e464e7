#pragma once
// `mesochain reduce`: a cell file's cell with its hidden rotation order made explicit
// (objective/core/rotation_reduction.hpp), keeping every other setting.
#include "input/cell_file.hpp"
#include "objective/core/rotation_reduction.hpp"

namespace mesochain::objective {

// True when the cell file's k-points sum every angular quantum number mu = 0..N_a-1 exactly
// (kpoints.angular = "all", or at least N_a samples; a ring: at least N_a/2 + 1, HelicalKGrid).
bool samplesEveryAngularNumber(const CellInput& input);

// The same settings (k-points, temperature, parameters, dispersion, SCC, task) on
// reducedCell(input.cell, reduction), with angular = "all": the reduced cell then sums every
// mu' = 0..N_a m - 1, which is the original's sum over mu block-diagonalised, so the energy per
// atom is the same. InputError naming kpoints.angular when the original samples mu (the reduced
// cell could not reproduce that approximation).
CellInput reducedCellInput(const CellInput& input, const RotationReduction& reduction);

}  // namespace mesochain::objective
