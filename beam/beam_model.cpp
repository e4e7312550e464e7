#include "beam/beam_model.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::beam {

namespace {

constexpr double kPi = units::kPi;

void requirePositive(double x, const std::string& source, const std::string& what) {
  if (!std::isfinite(x) || x <= 0.0)
    throw InputError(source, what, fmt::format("{:.6g}", x), "a finite value > 0");
}

double relative(double model, double target) { return model / target - 1.0; }

Beam rectangleFrom(const BeamConstants& c, double h, double w, const std::string& closure) {
  Beam b;
  b.shape = "rectangle";
  b.closure = closure;
  b.thickness = h;
  b.width = w;
  b.cellLength = c.cellLength;
  b.section = rectangleSection(h, w);
  b.young = c.stretch / (b.section.area * c.cellLength);   // C = Y A T0
  b.shear = c.twist * c.cellLength / b.section.polar;       // K = G J / T0
  b.residuals = residualsOf(b, c);
  return b;
}

}  // namespace

Section rectangleSection(double h, double w) {
  Section s;
  s.area = h * w;
  s.ix = h * w * w * w / 12.0;
  s.iy = w * h * h * h / 12.0;
  s.polar = s.ix + s.iy;
  return s;
}

Section circleSection(double r) {
  Section s;
  s.area = kPi * r * r;
  s.ix = s.iy = kPi * r * r * r * r / 4.0;
  s.polar = 2.0 * s.ix;
  return s;
}

Section annulusSection(double meanRadius, double wall) {
  const double ro = meanRadius + 0.5 * wall, ri = meanRadius - 0.5 * wall;
  Section s;
  s.area = kPi * (ro * ro - ri * ri);
  s.ix = s.iy = kPi * (ro * ro * ro * ro - ri * ri * ri * ri) / 4.0;
  s.polar = 2.0 * s.ix;
  return s;
}

BeamConstants predictConstants(const Beam& b) {
  BeamConstants c;
  c.cellLength = b.cellLength;
  c.stretch = b.young * b.section.area * b.cellLength;
  c.twist = b.shear * b.section.polar / b.cellLength;
  c.bendSoft = b.young * b.section.iy * b.cellLength;
  c.bendHard = b.young * b.section.ix * b.cellLength;
  return c;
}

Residuals residualsOf(const Beam& b, const BeamConstants& t) {
  const BeamConstants m = predictConstants(b);
  Residuals r;
  r.stretch = relative(m.stretch, t.stretch);
  r.twist = relative(m.twist, t.twist);
  r.bendSoft = relative(m.bendSoft, t.bendSoft);
  r.bendHard = relative(m.bendHard, t.bendHard);
  return r;
}

Beam rectangleFourConstants(const BeamConstants& c, const std::string& source) {
  requirePositive(c.cellLength, source, "T0");
  requirePositive(c.stretch, source, "C (stretching)");
  requirePositive(c.twist, source, "K (twisting)");
  requirePositive(c.bendSoft, source, "D_s (soft bending)");
  requirePositive(c.bendHard, source, "D_h (hard bending)");
  const double h = std::sqrt(12.0 * c.bendSoft / c.stretch);  // D_s / C = h^2 / 12
  const double w = std::sqrt(12.0 * c.bendHard / c.stretch);  // D_h / C = w^2 / 12
  return rectangleFrom(c, h, w, "four_constants");
}

Beam rectangleMeasuredThickness(const BeamConstants& c, double thickness, const std::string& source) {
  requirePositive(c.cellLength, source, "T0");
  requirePositive(c.stretch, source, "C (stretching)");
  requirePositive(c.twist, source, "K (twisting)");
  requirePositive(c.bendHard, source, "D_h (hard bending)");
  requirePositive(thickness, source, "measured thickness");
  const double w = std::sqrt(12.0 * c.bendHard / c.stretch);
  Beam b = rectangleFrom(c, thickness, w, "measured_thickness");
  if (!(c.bendSoft > 0.0)) b.residuals.bendSoft = std::nan("");  // nothing to compare with
  return b;
}

Beam solidCircle(const BeamConstants& c, const std::string& source) {
  requirePositive(c.cellLength, source, "T0");
  requirePositive(c.stretch, source, "C (stretching)");
  requirePositive(c.twist, source, "K (twisting)");
  requirePositive(c.bendSoft, source, "D (bending)");
  Beam b;
  b.shape = b.closure = "circle";
  b.cellLength = c.cellLength;
  b.radius = std::sqrt(4.0 * c.bendSoft / c.stretch);  // I / A = r^2 / 4
  b.section = circleSection(b.radius);
  b.young = c.stretch / (b.section.area * c.cellLength);
  b.shear = c.twist * c.cellLength / b.section.polar;
  b.residuals = residualsOf(b, c);
  if (!(c.bendHard > 0.0)) b.residuals.bendHard = std::nan("");
  return b;
}

Beam annulus(const BeamConstants& c, double wall, const std::string& source) {
  requirePositive(c.cellLength, source, "T0");
  requirePositive(c.stretch, source, "C (stretching)");
  requirePositive(c.twist, source, "K (twisting)");
  requirePositive(c.bendSoft, source, "D (bending)");
  requirePositive(wall, source, "wall thickness");
  // I / A = (R_o^2 + R_i^2) / 4 = R^2 / 2 + t^2 / 8 with R_o,i = R +- t/2.
  const double r2 = 2.0 * (c.bendSoft / c.stretch - wall * wall / 8.0);
  if (!(r2 > 0.25 * wall * wall))
    throw InputError(source, "wall thickness",
                     fmt::format("{:.6g} Bohr, too thick for D / C = {:.6g} Bohr^2", wall,
                                 c.bendSoft / c.stretch),
                     fmt::format("a wall with t^2 / 4 < D / C (t < {:.6g} Bohr)",
                                 2.0 * std::sqrt(c.bendSoft / c.stretch)));
  Beam b;
  b.shape = b.closure = "annulus";
  b.cellLength = c.cellLength;
  b.radius = std::sqrt(r2);
  b.wall = wall;
  b.section = annulusSection(b.radius, wall);
  b.young = c.stretch / (b.section.area * c.cellLength);
  b.shear = c.twist * c.cellLength / b.section.polar;
  b.residuals = residualsOf(b, c);
  if (!(c.bendHard > 0.0)) b.residuals.bendHard = std::nan("");
  return b;
}

}  // namespace mesochain::beam
