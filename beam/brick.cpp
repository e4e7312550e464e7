#include "beam/brick.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::beam {

Brick discretise(const Beam& beam, int n, double cellMass, const std::string& source) {
  if (n < 1) throw InputError(source, "cells per brick", std::to_string(n), "an integer >= 1");
  if (!std::isfinite(cellMass) || cellMass <= 0.0)
    throw InputError(source, "cell mass", fmt::format("{:.6g} Da", cellMass), "a finite mass > 0");
  Brick b;
  b.cellsPerBrick = n;
  b.length = n * beam.cellLength;
  b.mass = n * cellMass;
  const double l2 = b.length * b.length;
  if (beam.shape == "rectangle") {
    const double h2 = beam.thickness * beam.thickness, w2 = beam.width * beam.width;
    b.inertia = b.mass / 12.0 * Eigen::Vector3d(w2 + l2, h2 + l2, h2 + w2);
    b.section = beam.section;
    b.thickness = beam.thickness;
    b.width = beam.width;
    b.young = beam.young;
    b.shear = beam.shear;
  } else {
    // Equivalent solid disc: I / A = r^2 / 4 keeps D / C, J = 2 I keeps K / D.
    b.radius = std::sqrt(4.0 * beam.section.ix / beam.section.area);
    b.section = circleSection(b.radius);
    b.young = beam.young * beam.section.area / b.section.area;
    b.shear = beam.shear * beam.section.polar / b.section.polar;
    const double r2 = b.radius * b.radius;
    b.inertia = Eigen::Vector3d(b.mass / 12.0 * (3.0 * r2 + l2), b.mass / 12.0 * (3.0 * r2 + l2),
                                0.5 * b.mass * r2);
  }
  b.normalStiffness = b.young / b.length;
  b.shearStiffness = b.shear / b.length;
  return b;
}

}  // namespace mesochain::beam
