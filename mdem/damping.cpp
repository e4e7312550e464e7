#include "mdem/damping.hpp"

namespace mesochain::mdem {

namespace {
inline double sign(double v) { return (v > 0.0) - (v < 0.0); }
}  // namespace

void LocalDamping::dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const {
  const double a = alpha_;
  for (int d = 0; d < 3; ++d) force[d] -= a * std::abs(force[d]) * sign(s.velocity[i][d]);
  Vec3 tb = rotateInverse(s.orientation[i], torque);
  const Vec3 wb = s.angularVelocityBody(i);
  for (int d = 0; d < 3; ++d) tb[d] -= a * std::abs(tb[d]) * sign(wb[d]);
  torque = rotate(s.orientation[i], tb);
}

void LocalDamping::addForces(State& state) {
  Bodies& s = state.bodies;
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) dampElement(s, i, s.force[i], s.torque[i]);
}

void ViscousDamping::dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const {
  force -= rate_ * s.mass[i] * s.velocity[i];
  // I omega_body is the body angular momentum.
  torque -= rate_ * rotate(s.orientation[i], s.angularMomentumBody[i]);
}

void ViscousDamping::addForces(State& state) {
  Bodies& s = state.bodies;
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) dampElement(s, i, s.force[i], s.torque[i]);
}

}  // namespace mesochain::mdem
