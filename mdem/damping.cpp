#include "mdem/damping.hpp"

namespace mesochain::mdem {

namespace {
inline double sign(double v) { return (v > 0.0) - (v < 0.0); }
}  // namespace

void LocalDamping::addForces(State& state) {
  Bodies& s = state.bodies;
  const double a = alpha_;
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) {
    for (int d = 0; d < 3; ++d) s.force[i][d] -= a * std::abs(s.force[i][d]) * sign(s.velocity[i][d]);
    Vec3 tb = rotateInverse(s.orientation[i], s.torque[i]);
    const Vec3 wb = s.angularVelocityBody(i);
    for (int d = 0; d < 3; ++d) tb[d] -= a * std::abs(tb[d]) * sign(wb[d]);
    s.torque[i] = rotate(s.orientation[i], tb);
  }
}

void ViscousDamping::addForces(State& state) {
  Bodies& s = state.bodies;
  const double g = rate_;
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) {
    s.force[i] -= g * s.mass[i] * s.velocity[i];
    // I omega_body is the body angular momentum.
    s.torque[i] -= g * rotate(s.orientation[i], s.angularMomentumBody[i]);
  }
}

}  // namespace mesochain::mdem
