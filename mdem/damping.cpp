#include "mdem/damping.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "mdem/binary_io.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

namespace {

#if defined(__SSE2__)
// a |f| sign(v), sign(v) in {-1, 0, +1}: +-(a |f|) exactly, or +0, with SSE2 masks instead of
// forming the sign as a number (no branch: the signs of velocities are not predictable).
inline double dampingTerm(double a, double f, double v) {
  const __m128d m = _mm_mul_sd(_mm_set_sd(a), _mm_andnot_pd(_mm_set_sd(-0.0), _mm_set_sd(f)));
  const __m128d vv = _mm_set_sd(v);
  const __m128d signedM = _mm_or_pd(m, _mm_and_pd(vv, _mm_set_sd(-0.0)));
  return _mm_cvtsd_f64(_mm_and_pd(signedM, _mm_cmpneq_sd(vv, _mm_setzero_pd())));
}
#else
inline double dampingTerm(double a, double f, double v) { return a * std::abs(f) * ((v > 0.0) - (v < 0.0)); }
#endif

// [local_damping] alpha in [0, 1) (optional: the Scene's default).
void readLocalDampingTable(const TomlTable& t, Scene& s) {
  t.allowOnly({"alpha", "track_work"});
  s.localDampingAlpha = t.number("alpha");
  s.localDampingTracksWork = t.booleanOr("track_work", false);
  if (s.localDampingAlpha < 0.0 || s.localDampingAlpha >= 1.0)
    t.fail("alpha", std::to_string(s.localDampingAlpha), "a number in [0, 1)");
}

// [viscous_damping] rate_per_ns > 0 (required).
void readViscousDampingTable(const TomlTable& t, Scene& s) {
  t.allowOnly({"rate_per_ns", "track_work"});
  s.viscousRate = t.positive("rate_per_ns");
  s.viscousDampingTracksWork = t.booleanOr("track_work", false);
}

}  // namespace

MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "local_damping", 500, "Cundall's local non-viscous damping of each DOF ([local_damping] alpha)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr {
      return std::make_unique<LocalDamping>(b.scene.localDampingAlpha, b.scene.localDampingTracksWork, b.scene);
    },
    {"local_damping", false, readLocalDampingTable}, true})
MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "viscous_damping", 510, "mass-proportional drag ([viscous_damping] rate_per_ns)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr {
      return std::make_unique<ViscousDamping>(b.scene.viscousRate, b.scene.viscousDampingTracksWork, b.scene);
    },
    {"viscous_damping", true, readViscousDampingTable}, true})

template <class Damping>
TrackedDamping<Damping>::TrackedDamping(bool trackWork, const Scene& scene)
    : track_(trackWork) {
  if (!track_) return;
  const int n = scene.bodies.size();
  kinematics_.emplace(scene.boundary, n);
  dampForce_.assign(n, Vec3::Zero()), dampTorque_.assign(n, Vec3::Zero()), itemPower_.assign(n, 0.0);
}

template <class Damping>
void TrackedDamping<Damping>::gather(const State& state, double, int lo, int hi, Vec3* force, Vec3* torque) const {
  const Bodies& s = state.bodies;
  const Damping& damping = static_cast<const Damping&>(*this);
  if (!track_) {
    for (int i = lo; i < hi; ++i) damping.dampElement(s, i, force[i], torque[i]);
    return;
  }
  for (int i = lo; i < hi; ++i) {
    const Vec3 f0 = force[i], t0 = torque[i];
    damping.dampElement(s, i, force[i], torque[i]);
    Vec3 df = force[i] - f0, dt = torque[i] - t0;
    kinematics_->clearElement(i, df, dt);
    dampForce_[i] = df, dampTorque_[i] = dt;
    itemPower_[i] = -(df.dot(s.velocity[i]) + dt.dot(s.angularVelocityWorld(i)));
  }
}

template <class Damping>
double TrackedDamping<Damping>::powerAtItemVelocities() const {
  double power = 0.0;  // in the elements' order: independent of the thread count
  for (double p : itemPower_) power += p;
  return power;
}

template <class Damping>
void TrackedDamping<Damping>::finish(const State& state, double time) {
  const double h = work_.stepTo(time);
  if (!(h > 0.0) || state.stepVelocity.size() != dampForce_.size()) return;
  const std::vector<Vec3>& v = state.stepVelocity;
  const std::vector<Vec3>& w = state.stepAngularVelocity;
  double now = 0.0;
  for (std::size_t i = 0; i < dampForce_.size(); ++i) now -= dampForce_[i].dot(v[i]) + dampTorque_[i].dot(w[i]);
  work_.charge(h, now, powerAtItemVelocities());
}

template <class Damping>
void TrackedDamping<Damping>::kickForcesReplaced(const State&) {
  if (track_) work_.forcesReplaced(powerAtItemVelocities());
}

template <class Damping>
void TrackedDamping<Damping>::reportEnergy(const State&, EnergyLedger& ledger) const {
  if (track_) ledger.add(name() + "_dissipated", EnergyKind::Dissipated, work_.reported());
}

template <class Damping>
void TrackedDamping<Damping>::saveState(BinaryWriter& out) const {
  if (track_) out.write(work_.dissipated), out.write(work_.lastTime), out.write(work_.pending), out.write(work_.opening);
}

template <class Damping>
void TrackedDamping<Damping>::loadState(BinaryReader& in) {
  if (!track_ || in.remaining() < 4 * sizeof(double)) return;  // a checkpoint without the work: from 0
  work_.dissipated = in.read<double>(), work_.lastTime = in.read<double>();
  work_.pending = in.read<double>(), work_.opening = in.read<double>();
}

template class TrackedDamping<LocalDamping>;
template class TrackedDamping<ViscousDamping>;

void LocalDamping::dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const {
  const double a = alpha_;
  for (int d = 0; d < 3; ++d) force[d] -= dampingTerm(a, force[d], s.velocity[i][d]);
  Vec3 tb = rotateInverse(s.orientation[i], torque);
  // sign(omega_body) = sign(L_body): the principal moments are positive (no division needed).
  const Vec3& lb = s.angularMomentumBody[i];
  for (int d = 0; d < 3; ++d) tb[d] -= dampingTerm(a, tb[d], lb[d]);
  torque = rotate(s.orientation[i], tb);
}

void ViscousDamping::dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const {
  force -= rate_ * s.mass[i] * s.velocity[i];
  // I omega_body is the body angular momentum.
  torque -= rate_ * rotate(s.orientation[i], s.angularMomentumBody[i]);
}

}  // namespace mesochain::mdem
