#include "input/cell_reduction.hpp"

#include <string>

#include "common/errors.hpp"

namespace mesochain::objective {

bool samplesEveryAngularNumber(const CellInput& input) {
  const int na = input.cell.symmetry.rotationOrder();
  const int samples = input.band.angular.samples;
  if (samples <= 0) return true;
  return input.cell.symmetry.isRing() ? samples >= na / 2 + 1 : samples >= na;
}

CellInput reducedCellInput(const CellInput& input, const RotationReduction& reduction) {
  if (!samplesEveryAngularNumber(input))
    throw InputError(input.source, "key kpoints.angular",
                     std::to_string(input.band.angular.samples) + " sampled angular quantum numbers of N_a = " +
                         std::to_string(input.cell.symmetry.rotationOrder()),
                     "\"all\": the reduced cell reproduces the energy exactly only when every mu is summed");
  CellInput out = input;
  out.cell = reducedCell(input.cell, reduction);
  out.band.angular.samples = 0;
  return out;
}

}  // namespace mesochain::objective
