#include "mdem/boundary.hpp"

#include <algorithm>
#include <cmath>

#include "mdem/effect_registry.hpp"
#include "mdem/scene.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

// Not listed by name: applied whenever the scene has [[loads]].
MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "loads", 300, "forces and moments applied to elements ([[loads]])", false,
    [](const Scene& s) { return !s.boundary.loads.empty(); },
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<LoadEffect>(b.scene.boundary.loads, b.scene.bodies); },
    EffectTable{}, false})

namespace {
// 0 before the start (t < 0), then linear over `ramp`, then 1.
double rampFactor(double t, double ramp) { return ramp > 0.0 ? std::clamp(t / ramp, 0.0, 1.0) : (t < 0.0 ? 0.0 : 1.0); }
// (1 - cos(2 pi t / T)) / T on [0, T], 0 after: integrates to 1 over [0, T].
double smoothProfile(double t, double duration) {
  if (t < 0.0 || t >= duration) return 0.0;
  return (1.0 - std::cos(2.0 * units::kPi * t / duration)) / duration;
}
}  // namespace

Vec3 Prescribed::velocityAt(double t) const {
  if (duration > 0.0) return smoothProfile(t, duration) * translateBy;
  return rampFactor(t, ramp) * velocity;
}

Vec3 Prescribed::angularVelocityAt(double t) const {
  if (duration > 0.0) return smoothProfile(t, duration) * rotateBy;
  return rampFactor(t, ramp) * angularVelocity;
}

KinematicMap::KinematicMap(const Boundary& b, int n)
    : fixed(n, nullptr), prescribed(n, nullptr), kinematicRotation(n, 0) {
  for (const FixedDofs& f : b.fixed) {
    fixed[f.element] = &f;
    if (f.fixed[3] || f.fixed[4] || f.fixed[5]) kinematicRotation[f.element] = 1;
  }
  for (const Prescribed& p : b.prescribed) {
    prescribed[p.element] = &p;
    kinematicRotation[p.element] = 1;
  }
}

void KinematicMap::applyConstrained(Bodies& s, int i, double t) const {
  if (const Prescribed* p = prescribed[i]) {
    s.velocity[i] = p->velocityAt(t);
    s.setAngularVelocityWorld(i, p->angularVelocityAt(t));
    return;
  }
  const FixedDofs* f = fixed[i];
  if (!f) return;
  for (int d = 0; d < 3; ++d)
    if (f->fixed[d]) s.velocity[i][d] = f->velocity[d] * rampFactor(t - f->start, f->ramp);
  if (f->allRotationsFixed()) {
    s.angularMomentumBody[i].setZero();
  } else if (f->fixed[3] || f->fixed[4] || f->fixed[5]) {
    s.setAngularVelocityWorld(i, constrainedAngularVelocity(s, i, f->fixed));
  }
}

void KinematicMap::apply(Bodies& s, double t) const {
  for (int i = 0; i < s.size(); ++i) applyElement(s, i, t);
}

Vec3 constrainedAngularVelocity(const Bodies& s, int i, const std::array<bool, 6>& fixed) {
  // World inertia tensor I_w = R diag(I) R^T and world angular momentum L = R pi.
  const Mat3 r = toMatrix(s.orientation[i]);
  const Mat3 iw = r * s.inertia[i].asDiagonal() * r.transpose();
  const Vec3 l = r * s.angularMomentumBody[i];
  int freeAxes[3], n = 0;
  for (int d = 0; d < 3; ++d)
    if (!fixed[3 + d]) freeAxes[n++] = d;
  Vec3 w = Vec3::Zero();
  if (n == 1) {
    w[freeAxes[0]] = l[freeAxes[0]] / iw(freeAxes[0], freeAxes[0]);
  } else if (n == 2) {
    const int a = freeAxes[0], b = freeAxes[1];
    Eigen::Matrix2d m;
    m << iw(a, a), iw(a, b), iw(b, a), iw(b, b);
    const Eigen::Vector2d x = m.ldlt().solve(Eigen::Vector2d(l[a], l[b]));
    w[a] = x[0], w[b] = x[1];
  } else if (n == 3) {
    w = iw.ldlt().solve(l);
  }
  return w;
}

void KinematicMap::clearConstrained(int i, Vec3& force, Vec3& torque) const {
  if (prescribed[i]) {
    force.setZero();
    torque.setZero();
    return;
  }
  if (const FixedDofs* f = fixed[i]) {
    for (int d = 0; d < 3; ++d) {
      if (f->fixed[d]) force[d] = 0.0;
      if (f->fixed[3 + d]) torque[d] = 0.0;
    }
  }
}

void KinematicMap::clearConstrainedForces(Bodies& s) const {
  for (int i = 0; i < s.size(); ++i) clearElement(i, s.force[i], s.torque[i]);
}

LoadEffect::LoadEffect(std::vector<Load> loads, const Bodies& initial)
    : loads_(std::move(loads)), start_(initial.size() + 1, 0) {
  for (const Load& l : loads_) {
    forceBody_.push_back(rotateInverse(initial.orientation[l.element], l.force));
    momentBody_.push_back(rotateInverse(initial.orientation[l.element], l.moment));
    ++start_[l.element + 1];
  }
  for (int i = 0; i < initial.size(); ++i) {
    if (start_[i + 1] > 0) loadedElements_.push_back(i);
    start_[i + 1] += start_[i];
  }
  order_.resize(loads_.size());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int k = 0; k < static_cast<int>(loads_.size()); ++k) order_[fill[loads_[k].element]++] = k;
}

void LoadEffect::addToElement(const Bodies& s, int i, double time, Vec3& force,
                              Vec3& torque) const {
  for (int e = start_[i]; e < start_[i + 1]; ++e) {
    const int k = order_[e];
    const Load& l = loads_[k];
    const double r = rampFactor(time, l.ramp);
    if (l.following) {
      force += r * rotate(s.orientation[i], forceBody_[k]);
      torque += r * rotate(s.orientation[i], momentBody_[k]);
    } else {
      force += r * l.force;
      torque += r * l.moment;
    }
  }
}

void LoadEffect::reportEnergy(const State& state, EnergyLedger& ledger) const {
  // Potential of fixed-direction loads once fully applied: -F.u - M.phi, with phi the
  // accumulated rotation (exact for rotation about a fixed axis). Following loads: 0.
  double e = 0.0;
  const Bodies& s = state.bodies;
  for (const Load& l : loads_) {
    if (l.following || rampFactor(state.time, l.ramp) < 1.0) continue;
    const int i = l.element;
    e -= l.force.dot(s.position[i] - s.initialPosition[i]) + l.moment.dot(s.accumulatedRotation[i]);
  }
  ledger.add("load_potential", EnergyKind::Potential, e);
}

}  // namespace mesochain::mdem
