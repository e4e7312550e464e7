#include "objective/core/symmetry.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

using units::kPi;

Eigen::Matrix3d rotationZ(double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  Eigen::Matrix3d r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

Eigen::Matrix3d rotationZDerivative(double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  Eigen::Matrix3d r;
  r << -s, -c, 0, c, -s, 0, 0, 0, 0;
  return r;
}

Symmetry Symmetry::screw(double translation, double twist, int rotationOrder) {
  requireFinite(translation, "<symmetry>", "translation");
  requireFinite(twist, "<symmetry>", "twist");
  if (!(translation > 0.0))
    throw InputError("<symmetry>", "translation", std::to_string(translation),
                     "a positive screw translation (use a ring for T = 0)");
  if (rotationOrder < 1)
    throw InputError("<symmetry>", "rotation_order", std::to_string(rotationOrder),
                     "an integer >= 1");
  return Symmetry(translation, twist, rotationOrder);
}

Symmetry Symmetry::ring(int rotationOrder) {
  if (rotationOrder < 1)
    throw InputError("<symmetry>", "rotation_order", std::to_string(rotationOrder),
                     "an integer >= 1");
  return Symmetry(0.0, 2.0 * kPi / rotationOrder, rotationOrder);
}

Symmetry Symmetry::fromParameters(double translation, double twist, int rotationOrder,
                                  const char* source) {
  requireFinite(translation, source, "symmetry.translation");
  requireFinite(twist, source, "symmetry.twist");
  if (rotationOrder < 1)
    throw InputError(source, "symmetry.rotation_order", std::to_string(rotationOrder),
                     "an integer >= 1");
  if (translation < 0.0)
    throw InputError(source, "symmetry.translation", std::to_string(translation),
                     "a translation >= 0 (0 closes a ring)");
  if (translation > 0.0) return screw(translation, twist, rotationOrder);
  // Closed ring: the screw must be an element of C_{N_a}.
  const double step = 2.0 * kPi / rotationOrder;
  const double m = twist / step;
  if (std::abs(m - std::round(m)) > 1e-9)
    throw InputError(source, "symmetry.twist",
                     std::to_string(twist * 180.0 / kPi) + " degrees with translation 0",
                     "a multiple of 360/N_a = " + std::to_string(360.0 / rotationOrder) +
                         " degrees (a closed ring of N_a images)");
  return ring(rotationOrder);
}

double Symmetry::angle(const GroupElement& g) const {
  return static_cast<double>(g.zeta) * twist_ + 2.0 * kPi * g.c / rotationOrder_;
}

Eigen::Matrix3d Symmetry::rotation(const GroupElement& g) const { return rotationZ(angle(g)); }

Eigen::Vector3d Symmetry::apply(const GroupElement& g, const Eigen::Vector3d& x) const {
  Eigen::Vector3d y = rotation(g) * x;
  y.z() += static_cast<double>(g.zeta) * translation_;
  return y;
}

Symmetry Symmetry::withTranslation(double translation) const {
  return fromParameters(translation, twist_, rotationOrder_);
}

Symmetry Symmetry::withTwist(double twist) const {
  Symmetry s = *this;
  s.twist_ = twist;
  return s;
}

}  // namespace mesochain::objective
