#include "mdem/simulation.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <omp.h>

#include "common/errors.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/integrator.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
// Which built effects form the outer group of multiple time stepping: those named in
// run.outer_effects, or every conservative effect that couples filaments (the van der Waals
// contacts; dashpots stay on the inner step, Effect::dissipates).
std::vector<char> outerGroup(const Scene& scene, const std::vector<EffectPtr>& effects) {
  std::vector<char> outer(effects.size(), 0);
  if (scene.run.outerStepRatio == 1) return outer;
  const char* key = "key run.outer_effects";
  for (const std::string& name : scene.run.outerEffects) {
    const auto it = std::find_if(effects.begin(), effects.end(), [&](const EffectPtr& e) { return e->name() == name; });
    if (it == effects.end())
      throw InputError(scene.source, key, "\"" + name + "\"", "an effect the scene builds (named in effects)");
    if ((*it)->bondList())
      throw InputError(scene.source, key, "\"" + name + "\"", "effects other than the bonds (they set the inner step)");
    if ((*it)->role() == EffectRole::NumericalDamping)
      throw InputError(scene.source, key, "\"" + name + "\"",
                       "physical effects (numerical damping acts on the net force at every step)");
    outer[it - effects.begin()] = 1;
  }
  if (scene.run.outerEffects.empty())
    for (std::size_t k = 0; k < effects.size(); ++k) outer[k] = effects[k]->couplesFilaments() && !effects[k]->dissipates() ? 1 : 0;
  if (std::find(outer.begin(), outer.end(), 1) == outer.end())
    throw InputError(scene.source, "key run.outer_step_ratio", "a scene without contacts",
                     "outer_effects naming the effects of the outer step (none is a conservative contact)");
  return outer;
}

std::string describe(const StabilityLimit& l) {
  return fmt::format("limited by the {} (omega = {:.6g} rad/ns, damping rate {:.6g} /ns on the {} of element {})",
                     l.limitedBy, l.omega, l.dampingRate, l.rotational ? "rotation" : "translation", l.element);
}
}  // namespace

Simulation::Simulation(const Scene& scene, double startTime, long startStep)
    : state_{scene.bodies, startTime, {}, {}, {}, {}},
      kinematics_(scene.boundary, scene.bodies.size()),
      effects_(buildEffects(scene)),
      h_(scene.run.timeStep),
      steps_(startStep),
      cycleStart_(startStep) {
  // Always: a stage may return to unscaled inertia after a scaled one (the bodies carry theirs).
  scaleInertia(state_.bodies, scene.elementTypes, scene.run.massScale, scene.run.rotationalInertiaScale);
  const GershgorinFrame frame = scene.run.bodyFrameCriticalStep ? GershgorinFrame::Body : GershgorinFrame::World;
  std::vector<char> outer = outerGroup(scene, effects_);
  bool split = std::find(outer.begin(), outer.end(), 1) != outer.end();
  // Stability: the inner step against everything but the outer group, the outer step against
  // the outer group alone (stability.hpp); `allTerms`: every effect on every step.
  std::vector<ContactStabilityTerms> innerTerms(scene.elementTypes.size()), outerTerms(scene.elementTypes.size());
  std::vector<ContactStabilityTerms> allTerms(scene.elementTypes.size());
  for (std::size_t k = 0; k < effects_.size(); ++k) {
    effects_[k]->addStabilityTerms(outer[k] ? outerTerms : innerTerms);
    effects_[k]->addStabilityTerms(allTerms);
    if (outer[k]) outerNames_.push_back(effects_[k]->name());
  }
  limit_ = criticalTimeStep(state_.bodies, bonds(), kinematics_, innerTerms, frame);
  if (split) {
    outerLimit_ = criticalTimeStep(state_.bodies, {}, kinematics_, outerTerms, frame);
    // Impulse multiple time stepping is unstable at outer steps near a third of the fastest
    // inner period (nonlinear 3:1 resonance; Ma, Izaguirre & Skeel, SIAM J. Sci. Comput. 24,
    // 1951 (2003)): H < T / 3 = 2 pi / (3 omega), with omega the inner Gershgorin bound
    // (>= the true frequency, so the guard is conservative). Measured: docs/benchmarks.md.
    // The world-axes bound is 1.2-1.4x the true frequency in the films, and the measured break
    // lies at 0.8-0.9 T/3 of the true period; the body-axes bound is within 1.1x of the true
    // frequency once rotations are slowed (rotational_inertia_scale), so with it the guard takes
    // 3/4 of T/3 (docs/benchmarks.md, "What sets the mDEM time step").
    const double guardFraction = frame == GershgorinFrame::Body ? 0.75 : 1.0;
    const double resonance = guardFraction * 2.0 * units::kPi / (3.0 * limit_.omegaMax);
    if (resonance < outerLimit_.criticalTimeStep) {
      outerLimit_ = limit_;
      outerLimit_.criticalTimeStep = resonance;
      outerLimit_.limitedBy = "resonance with the inner step's fastest vibration (a third of its period)";
    }
  } else {
    outerLimit_.criticalTimeStep = HUGE_VAL;
  }
  const double fraction = scene.run.timeStepFraction;
  if (fraction > 0.0) {
    if (fraction > 1.0)
      throw InputError(scene.source, "key run.time_step_fraction",
                       fmt::format("{}", fraction), "a fraction in (0, 1]");
    h_ = fraction * limit_.criticalTimeStep;
    if (!std::isfinite(h_))
      throw InputError(scene.source, "key run.time_step_fraction", "a scene without bonds or contacts",
                       "run.time_step_ns instead (no critical step to take a fraction of)");
  }
  int ratio = 1;
  if (split && scene.run.outerStepRatio == 0) {
    // "auto": the largest ratio whose outer step fits. When none above 1 fits the inner step,
    // ratio 2 on a shorter inner step if that step is still at least the step of the unsplit
    // scheme; otherwise no splitting at all: ratio 1 puts the outer group back on every step, where
    // the stability limit is that of all effects together, not the two groups' separate ones.
    const double outerStep = scene.run.outerStepFraction * outerLimit_.criticalTimeStep;
    ratio = static_cast<int>(std::clamp(std::floor(outerStep / h_), 1.0, static_cast<double>(kMaxAutoOuterRatio)));
    if (ratio == 1) {
      const StabilityLimit all = criticalTimeStep(state_.bodies, bonds(), kinematics_, allTerms, frame);
      const double unsplit = fraction > 0.0 ? fraction * all.criticalTimeStep : h_;
      if (fraction > 0.0 && 0.5 * outerStep >= unsplit) {
        h_ = 0.5 * outerStep, ratio = 2;
      } else {
        split = false;
        std::fill(outer.begin(), outer.end(), 0);
        outerNames_.clear();
        outerLimit_ = StabilityLimit{};
        outerLimit_.criticalTimeStep = HUGE_VAL;
        limit_ = all, h_ = unsplit;
      }
    }
  } else if (split) {
    ratio = scene.run.outerStepRatio;
  }
  if (!(h_ > 0.0))
    throw InputError(scene.source, "key run.time_step_ns", fmt::format("{}", h_),
                     "a positive time step");
  if (h_ > limit_.criticalTimeStep)
    throw InputError(scene.source, "key run.time_step_ns", fmt::format("{:.6g} ns", h_),
                     fmt::format("at most the critical time step {:.6g} ns{}, {}; docs/scene-file.md, time step",
                                 limit_.criticalTimeStep, split ? " of the inner step" : "", describe(limit_)));
  if (split && ratio * h_ > outerLimit_.criticalTimeStep)
    throw InputError(scene.source, "key run.outer_step_ratio", fmt::format("{} (outer step {:.6g} ns)", ratio, ratio * h_),
                     fmt::format("an outer step of at most the outer group's critical step {:.6g} ns, {}; "
                                 "docs/scene-file.md, multiple time stepping",
                                 outerLimit_.criticalTimeStep, describe(outerLimit_)));
  std::vector<Effect*> pointers;
  for (const EffectPtr& e : effects_) pointers.push_back(e.get());
  sequence_ = EffectSequence(pointers, outer, ratio);
  kinematics_.apply(state_.bodies, startTime);
  evaluateKickForces(state_, sequence_, kinematics_);
  for (const EffectPtr& e : effects_) e->kickForcesReplaced(state_);
}

void Simulation::refreshForces() {
  cycleStart_ = steps_;  // the refreshed state starts an outer step
  evaluateKickForces(state_, sequence_, kinematics_);
  for (const EffectPtr& e : effects_) e->kickForcesReplaced(state_);
}

void Simulation::run(long steps) {
  if (steps <= 0) return;
  const int threads = omp_get_max_threads();
  if (partition_.threads != threads) partition_ = partitionElements(state_.bodies.size(), bonds(), sequence_, threads);
  advance(state_, sequence_, kinematics_, h_, steps, &partition_, profile_, steps_ - cycleStart_);
  steps_ += steps;
}

EnergyLedger Simulation::energies() const {
  EnergyLedger e;
  e.add("kinetic_translational", EnergyKind::Kinetic, kineticTranslational(state_.bodies));
  e.add("kinetic_rotational", EnergyKind::Kinetic, kineticRotational(state_.bodies));
  for (const auto& f : effects_) f->reportEnergy(state_, e);
  return e;
}

double Simulation::kineticEnergy() const {
  return kineticTranslational(state_.bodies) + kineticRotational(state_.bodies);
}

std::vector<std::string> Simulation::effectNames() const {
  std::vector<std::string> n;
  for (const auto& e : effects_) n.push_back(e->name());
  return n;
}

Effect* Simulation::effect(const std::string& name) const {
  for (const auto& e : effects_)
    if (e->name() == name) return e.get();
  return nullptr;
}

const std::vector<Bond>& Simulation::bonds() const {
  static const std::vector<Bond> kNone;
  for (const auto& e : effects_)
    if (const std::vector<Bond>* b = e->bondList()) return *b;
  return kNone;
}

const ContactNeighbourhood* Simulation::contactNeighbourhood() const {
  for (const auto& e : effects_)
    if (const ContactNeighbourhood* n = e->contactNeighbourhood()) return n;
  return nullptr;
}

std::vector<Vec3> Simulation::unconstrainedForces() const {
  State copy = state_;
  evaluateForces(copy, sequence_, kinematics_, false, false);
  return copy.bodies.force;
}

std::pair<double, double> Simulation::residual() {
  const std::vector<Vec3> force = state_.bodies.force, torque = state_.bodies.torque;
  evaluateForces(state_, sequence_, kinematics_, false, true);
  double f = 0.0, m = 0.0;
  for (int i = 0; i < state_.bodies.size(); ++i) {
    f = std::max(f, state_.bodies.force[i].norm());
    m = std::max(m, state_.bodies.torque[i].norm());
  }
  state_.bodies.force = force;  // restore the forces the next kick expects
  state_.bodies.torque = torque;
  return {f, m};
}

}  // namespace mesochain::mdem
