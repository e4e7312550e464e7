#pragma once
// Orchestration: builds the list of effects named by the scene, checks the time step against
// the critical one, and advances the state. One step (velocity Verlet + DLM rotation,
// integrator.hpp):
//   kick(h/2); constraints(t + h/2); drift(h); t += h; forces; kick(h/2); constraints(t).
// Forces: every effect in order bonds -> vdw_contact -> loads -> contact_damping ->
// local_damping -> viscous_damping (the damping effects act on the accumulated force), then
// constrained components are cleared. When the scene has only bonds, loads and damping, run(n)
// advances n steps in one OpenMP parallel region (stepper.hpp); other effects (contacts) add
// their forces between the two halves of each step.
#include <string>
#include <vector>

#include "mdem/bond_effect.hpp"
#include "mdem/effect.hpp"
#include "mdem/scene.hpp"
#include "mdem/stability.hpp"
#include "mdem/stepper.hpp"

namespace mesochain::mdem {

class Simulation {
 public:
  // Throws InputError (naming scene.source and key run.time_step_ns) when the time step is not
  // positive or exceeds the critical time step.
  explicit Simulation(const Scene& scene);

  void step() { run(1); }
  void run(long steps);

  // Kinetic energies plus the energies of every effect.
  Energies energies() const;
  const State& state() const { return state_; }
  State& state() { return state_; }
  const Bodies& bodies() const { return state_.bodies; }
  double time() const { return state_.time; }
  double timeStep() const { return h_; }
  long stepCount() const { return steps_; }
  const StabilityLimit& stability() const { return limit_; }
  std::vector<std::string> effectNames() const;
  // The built effect of that name, or nullptr (e.g. dynamic_cast to VdwContactEffect).
  Effect* effect(const std::string& name) const;
  // The bonds with their tracked state (empty when "bonds" is not an effect).
  const std::vector<Bond>& bonds() const;
  const BondEffect* bondEffect() const { return bondEffect_; }

  // Largest unbalanced force (pN) and moment (pN nm) on the unconstrained DOFs, without the
  // damping effects: the residual of a static solution.
  std::pair<double, double> residual();

  // Forces of every effect but local / viscous damping on the current state, constrained
  // components included (the reactions of grips and supports follow from them); the state is
  // left as it was.
  std::vector<Vec3> unconstrainedForces() const;

 private:
  void computeForces(bool withDamping);

  State state_;
  KinematicMap kinematics_;
  std::vector<EffectPtr> effects_;
  BondEffect* bondEffect_ = nullptr;
  CoreEffects core_;             // the effects the fused step runs itself
  std::vector<Effect*> others_;  // effects that add their forces on their own
  ThreadPartition partition_;    // for the current number of OpenMP threads
  StabilityLimit limit_;
  double h_ = 0.0;
  long steps_ = 0;
};

}  // namespace mesochain::mdem
