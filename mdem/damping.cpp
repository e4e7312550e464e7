#include "mdem/damping.hpp"

#include "mdem/effect_registry.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

namespace {

inline double sign(double v) { return (v > 0.0) - (v < 0.0); }

// [local_damping] alpha in [0, 1) (optional: the Scene's default).
void readLocalDampingTable(const TomlTable& t, Scene& s) {
  t.allowOnly({"alpha"});
  s.localDampingAlpha = t.number("alpha");
  if (s.localDampingAlpha < 0.0 || s.localDampingAlpha >= 1.0)
    t.fail("alpha", std::to_string(s.localDampingAlpha), "a number in [0, 1)");
}

// [viscous_damping] rate_per_ns > 0 (required).
void readViscousDampingTable(const TomlTable& t, Scene& s) {
  t.allowOnly({"rate_per_ns"});
  s.viscousRate = t.positive("rate_per_ns");
}

}  // namespace

MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "local_damping", 500, "Cundall's local non-viscous damping of each DOF ([local_damping] alpha)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<LocalDamping>(b.scene.localDampingAlpha); },
    {"local_damping", false, readLocalDampingTable}, true})
MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "viscous_damping", 510, "mass-proportional drag ([viscous_damping] rate_per_ns)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<ViscousDamping>(b.scene.viscousRate); },
    {"viscous_damping", true, readViscousDampingTable}, true})

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
