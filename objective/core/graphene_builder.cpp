#include "objective/core/graphene_builder.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

using units::kPi;

ObjectiveCell buildGrapheneRingSector(int layers, Direction dir, int rotationOrder,
                                      int cellsAlongArc, double interlayer, double bondLength) {
  const char* source = "<builder>";
  if (layers < 1) throw InputError(source, "layers", std::to_string(layers), "at least one layer");
  if (rotationOrder < 1)
    throw InputError(source, "rotation_order", std::to_string(rotationOrder), "an integer >= 1");
  if (cellsAlongArc < 1)
    throw InputError(source, "cells_along_arc", std::to_string(cellsAlongArc),
                     "at least one cell per sector");
  if (!std::isfinite(bondLength) || !(bondLength > 0.0))
    throw InputError(source, "bond_length", fmt::format("{}", bondLength),
                     "a positive, finite bond length");
  if (layers > 1 && (!std::isfinite(interlayer) || !(interlayer > 0.0)))
    throw InputError(source, "interlayer", fmt::format("{}", interlayer),
                     "a positive, finite interlayer distance");
  const double b = bondLength;
  const double a = std::sqrt(3.0) * b;
  const double px = a, py = 3.0 * b;  // periods along x (zigzag) and y (armchair)
  const bool zigzagArc = dir == Direction::Zigzag;
  const double arcPeriod = zigzagArc ? px : py;
  const double axialPeriod = zigzagArc ? py : px;
  const double rMid = rotationOrder * cellsAlongArc * arcPeriod / (2.0 * kPi);
  const double rInner = rMid - 0.5 * (layers - 1) * interlayer;
  if (!(rInner > 0.0))
    throw InputError(
        source, "rotation_order and cells_along_arc",
        fmt::format("a middle radius of {:.4f} Å for {} layers {:.4f} Å apart",
                    rMid * units::kBohrInAngstrom, layers, interlayer * units::kBohrInAngstrom),
        "an innermost layer at positive radius (more cells per sector)");
  // The rectangular cell of the flat sheet (x zigzag, y armchair).
  const double cellX[4] = {0.0, a / 2, a / 2, 0.0};
  const double cellY[4] = {0.0, b / 2, 1.5 * b, 2.0 * b};
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(axialPeriod, 0.0, rotationOrder);
  for (int k = 0; k < layers; ++k) {
    const double radius = rMid + (k - 0.5 * (layers - 1)) * interlayer;
    const double shiftY = (k % 2 == 1) ? b : 0.0;  // Bernal stacking ABAB...
    for (int c = 0; c < cellsAlongArc; ++c)
      for (int s = 0; s < 4; ++s) {
        double x = cellX[s];
        double y = std::fmod(cellY[s] + shiftY, py);
        double arc = zigzagArc ? x + c * px : y + c * py;
        const double axial = zigzagArc ? y : x;
        const double phi = arc / rMid;
        cell.addAtom("C", {radius * std::cos(phi), radius * std::sin(phi), axial});
      }
  }
  return cell;
}

}  // namespace mesochain::objective
