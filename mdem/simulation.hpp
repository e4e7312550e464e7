#pragma once
// Orchestration: builds the effects the scene wants (effect_registry.hpp), checks the time step
// against the critical one, and advances the state on the stepper (stepper.hpp describes the
// scheme). The simulation knows no effect by name: energies come from the ledger the effects
// report into, capabilities (the bonds, the contact neighbourhood) through Effect's queries.
#include <string>
#include <vector>

#include "mdem/effect.hpp"
#include "mdem/scene.hpp"
#include "mdem/stability.hpp"
#include "mdem/stepper.hpp"

namespace mesochain::mdem {

class Simulation {
 public:
  // Throws InputError (naming scene.source and key run.time_step_ns) when the time step is not
  // positive or exceeds the critical time step, and for effects that are not registered; with
  // multiple time stepping (key run.outer_step_ratio) when the outer step exceeds the outer
  // group's critical step or the outer group names an effect the scene does not build.
  // A later stage of a run starts at `startTime` (ns) and step `startStep`.
  explicit Simulation(const Scene& scene, double startTime = 0.0, long startStep = 0);

  void step() { run(1); }
  void run(long steps);

  // Kinetic energies ("kinetic_translational", "kinetic_rotational") and the entries of every
  // effect, in effect order.
  EnergyLedger energies() const;
  // The kinetic part alone (translational + rotational): no effect is evaluated.
  double kineticEnergy() const;
  const State& state() const { return state_; }
  State& state() { return state_; }
  const Bodies& bodies() const { return state_.bodies; }
  double time() const { return state_.time; }
  double timeStep() const { return h_; }
  long stepCount() const { return steps_; }
  // The inner step's limit (every effect not in the outer group, bonds included).
  const StabilityLimit& stability() const { return limit_; }
  // Multiple time stepping (stepper.hpp): outer step / inner step (1: none), the outer group's
  // effects and their own critical step (contacts only; criticalTimeStep infinite when none).
  int outerStepRatio() const { return sequence_.ratio; }
  const std::vector<std::string>& outerEffectNames() const { return outerNames_; }
  const StabilityLimit& outerStability() const { return outerLimit_; }
  std::vector<std::string> effectNames() const;
  // The built effect of that name, or nullptr.
  Effect* effect(const std::string& name) const;
  const std::vector<EffectPtr>& effects() const { return effects_; }
  // The bonds with their tracked state (empty without an effect that has bonds).
  const std::vector<Bond>& bonds() const;
  // The contact neighbourhood of the contact effects (null without contacts).
  const ContactNeighbourhood* contactNeighbourhood() const;

  // Largest unbalanced force (pN) and moment (pN nm) on the unconstrained DOFs, without the
  // numerical damping: the residual of a static solution.
  std::pair<double, double> residual();

  // Forces of every physical effect (no numerical damping) on the current state, constrained
  // components included (the reactions of grips and supports follow from them); the state is
  // left as it was.
  std::vector<Vec3> unconstrainedForces() const;

  // Phase timing of the steps (dem --profile); null profile: none (the default, no cost).
  void setProfile(PhaseTimes* profile) { profile_ = profile; }

  // Restart (checkpoint.hpp): the step count and every effect's evolving state.
  void setStepCount(long steps) { steps_ = steps; }
  long cycleStart() const { return cycleStart_; }
  void setCycleStart(long step) { cycleStart_ = step; }
  // Recomputes the forces of the current state (after the state was replaced, e.g. by a
  // checkpoint), without touching the effects' evolving state beyond what a force evaluation
  // does.
  void refreshForces();

 private:
  State state_;
  KinematicMap kinematics_;
  std::vector<EffectPtr> effects_;
  EffectSequence sequence_;
  ThreadPartition partition_;  // for the current number of OpenMP threads
  StabilityLimit limit_, outerLimit_;
  std::vector<std::string> outerNames_;
  double h_ = 0.0;
  long steps_ = 0;
  long cycleStart_ = 0;  // a boundary state's step (multiple time stepping)
  PhaseTimes* profile_ = nullptr;
};

}  // namespace mesochain::mdem
