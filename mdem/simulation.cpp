#include "mdem/simulation.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <omp.h>

#include "common/errors.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/integrator.hpp"

namespace mesochain::mdem {

namespace {
std::vector<Effect*> pointers(const std::vector<EffectPtr>& effects) {
  std::vector<Effect*> p;
  for (const EffectPtr& e : effects) p.push_back(e.get());
  return p;
}
}  // namespace

Simulation::Simulation(const Scene& scene, double startTime, long startStep)
    : state_{scene.bodies, startTime},
      kinematics_(scene.boundary, scene.bodies.size()),
      effects_(buildEffects(scene)),
      sequence_(pointers(effects_)),
      h_(scene.run.timeStep),
      steps_(startStep) {
  std::vector<ContactStabilityTerms> contactTerms(scene.elementTypes.size());
  for (const EffectPtr& e : effects_) e->addStabilityTerms(contactTerms);
  limit_ = criticalTimeStep(state_.bodies, bonds(), kinematics_, contactTerms);
  if (scene.run.timeStepFraction > 0.0) {
    if (scene.run.timeStepFraction > 1.0)
      throw InputError(scene.source, "key run.time_step_fraction",
                       fmt::format("{}", scene.run.timeStepFraction), "a fraction in (0, 1]");
    h_ = scene.run.timeStepFraction * limit_.criticalTimeStep;
    if (!std::isfinite(h_))
      throw InputError(scene.source, "key run.time_step_fraction", "a scene without bonds or contacts",
                       "run.time_step_ns instead (no critical step to take a fraction of)");
  }
  if (!(h_ > 0.0))
    throw InputError(scene.source, "key run.time_step_ns", fmt::format("{}", h_),
                     "a positive time step");
  if (h_ > limit_.criticalTimeStep)
    throw InputError(scene.source, "key run.time_step_ns", fmt::format("{:.6g} ns", h_),
                     fmt::format("at most the critical time step {:.6g} ns, limited by the {} "
                                 "(omega = {:.6g} rad/ns, damping rate {:.6g} /ns on the {} "
                                 "of element {}; docs/scene-file.md, time step)",
                                 limit_.criticalTimeStep, limit_.limitedBy, limit_.omega,
                                 limit_.dampingRate, limit_.rotational ? "rotation" : "translation",
                                 limit_.element));
  kinematics_.apply(state_.bodies, startTime);
  evaluateForces(state_, sequence_, kinematics_, true, true);
}

void Simulation::refreshForces() { evaluateForces(state_, sequence_, kinematics_, true, true); }

void Simulation::run(long steps) {
  if (steps <= 0) return;
  const int threads = omp_get_max_threads();
  if (partition_.threads != threads) partition_ = partitionElements(state_.bodies.size(), bonds(), sequence_, threads);
  advance(state_, sequence_, kinematics_, h_, steps, &partition_, profile_);
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
