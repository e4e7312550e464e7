#include "mdem/damping.hpp"

#include "mdem/effect_registry.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "local_damping", 500, "Cundall's local non-viscous damping of each DOF ([local_damping] alpha)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<LocalDamping>(b.scene.localDampingAlpha); }})
MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "viscous_damping", 510, "mass-proportional drag ([viscous_damping] rate_per_ns)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<ViscousDamping>(b.scene.viscousRate); }})

namespace {
inline double sign(double v) { return (v > 0.0) - (v < 0.0); }
}  // namespace

void LocalDamping::dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const {
  const double a = alpha_;
  for (int d = 0; d < 3; ++d) force[d] -= a * std::abs(force[d]) * sign(s.velocity[i][d]);
  Vec3 tb = rotateInverse(s.orientation[i], torque);
  // sign(omega_body) = sign(L_body): the principal moments are positive (no division needed).
  const Vec3& lb = s.angularMomentumBody[i];
  for (int d = 0; d < 3; ++d) tb[d] -= a * std::abs(tb[d]) * sign(lb[d]);
  torque = rotate(s.orientation[i], tb);
}

void ViscousDamping::dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const {
  force -= rate_ * s.mass[i] * s.velocity[i];
  // I omega_body is the body angular momentum.
  torque -= rate_ * rotate(s.orientation[i], s.angularMomentumBody[i]);
}

}  // namespace mesochain::mdem
