#include "mdem/simulation.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <omp.h>

#include "common/errors.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/damping.hpp"
#include "mdem/integrator.hpp"
#include "mdem/stepper.hpp"

namespace mesochain::mdem {

namespace {
bool named(const std::vector<std::string>& list, const char* name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}
}  // namespace

Simulation::Simulation(const Scene& scene)
    : state_{scene.bodies, 0.0},
      kinematics_(scene.boundary, scene.bodies.size()),
      h_(scene.run.timeStep) {
  for (const std::string& e : scene.effects)
    if (e != "bonds" && e != "local_damping" && e != "viscous_damping" && e != "vdw_contact" &&
        e != "contact_damping")
      throw InputError(scene.source, "key effects", "\"" + e + "\"",
                       "one of \"bonds\", \"vdw_contact\", \"contact_damping\", "
                       "\"local_damping\", \"viscous_damping\"");
  // Fixed build order: conservative effects, loads, then dissipation.
  if (named(scene.effects, "bonds")) {
    auto b = std::make_unique<BondEffect>(scene.bonds, scene.bodies.size());
    bondEffect_ = b.get();
    effects_.push_back(std::move(b));
  }
  ContactEffects contacts = makeContactEffects(scene);  // only those named
  const std::vector<ContactStabilityTerms> contactTerms = contactStabilityTerms(scene, contacts);
  if (contacts.vdw) effects_.push_back(std::move(contacts.vdw));
  if (!scene.boundary.loads.empty())
    effects_.push_back(std::make_unique<LoadEffect>(scene.boundary.loads, scene.bodies));
  if (contacts.damping) effects_.push_back(std::move(contacts.damping));
  if (named(scene.effects, "local_damping"))
    effects_.push_back(std::make_unique<LocalDamping>(scene.localDampingAlpha));
  if (named(scene.effects, "viscous_damping"))
    effects_.push_back(std::make_unique<ViscousDamping>(scene.viscousRate));

  for (auto& e : effects_) {
    if (auto* b = dynamic_cast<BondEffect*>(e.get())) {
      core_.bonds = b;
    } else if (auto* l = dynamic_cast<LoadEffect*>(e.get())) {
      core_.loads = l;
    } else if (auto* d = dynamic_cast<LocalDamping*>(e.get())) {
      core_.localDamping = d;
    } else if (auto* v = dynamic_cast<ViscousDamping*>(e.get())) {
      core_.viscousDamping = v;
    } else {
      others_.push_back(e.get());
    }
  }

  limit_ = criticalTimeStep(state_.bodies, bondEffect_ ? bondEffect_->bonds() : std::vector<Bond>{},
                            kinematics_, contactTerms);
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
  kinematics_.apply(state_.bodies, 0.0);
  computeForces(true);
}

void Simulation::computeForces(bool withDamping) {
  Bodies& s = state_.bodies;
  std::fill(s.force.begin(), s.force.end(), Vec3::Zero());
  std::fill(s.torque.begin(), s.torque.end(), Vec3::Zero());
  for (auto& e : effects_) {
    if (!withDamping && (e->name() == "local_damping" || e->name() == "viscous_damping")) continue;
    e->addForces(state_);
  }
  kinematics_.clearConstrainedForces(s);
}

void Simulation::run(long steps) {
  if (steps <= 0) return;
  if (others_.empty()) {
    const int threads = omp_get_max_threads();
    if (partition_.threads != threads)
      partition_ = partitionByBonds(state_.bodies.size(), bonds(), threads);
    advanceFused(state_, core_, kinematics_, h_, steps, &partition_);
  } else {
    Bodies& s = state_.bodies;
    for (long k = 0; k < steps; ++k) {
      firstHalf(state_, kinematics_, h_);
      std::fill(s.force.begin(), s.force.end(), Vec3::Zero());
      std::fill(s.torque.begin(), s.torque.end(), Vec3::Zero());
      for (Effect* e : others_) e->addForces(state_);
      secondHalf(state_, core_, kinematics_, h_);
    }
  }
  steps_ += steps;
}

Energies Simulation::energies() const {
  Energies e;
  e.kineticTranslational = kineticTranslational(state_.bodies);
  e.kineticRotational = kineticRotational(state_.bodies);
  for (const auto& f : effects_) e += f->energy(state_);
  return e;
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
  return bondEffect_ ? bondEffect_->bonds() : kNone;
}

std::vector<Vec3> Simulation::unconstrainedForces() const {
  State copy = state_;
  std::fill(copy.bodies.force.begin(), copy.bodies.force.end(), Vec3::Zero());
  std::fill(copy.bodies.torque.begin(), copy.bodies.torque.end(), Vec3::Zero());
  for (const auto& e : effects_)
    if (e->name() != "local_damping" && e->name() != "viscous_damping") e->addForces(copy);
  return copy.bodies.force;
}

std::pair<double, double> Simulation::residual() {
  const std::vector<Vec3> force = state_.bodies.force, torque = state_.bodies.torque;
  computeForces(false);
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
