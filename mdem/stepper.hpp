#pragma once
// The time step on one OpenMP parallel region, driving every effect through its phases
// (effect.hpp). One step (velocity Verlet + DLM rotation, integrator.hpp):
//   kick(h/2); constraints(t + h/2); drift(h); t += h; forces(t); kick(h/2); constraints(t).
// A run of n steps is one parallel region; per step:
//   [items]     each effect's items, split into chunks between the threads      -- barrier
//   [elements]  per block of elements: zero, gather every effect in order, clear the constrained
//               components, kick h/2, constraints; then the next step's kick h/2, constraints,
//               drift                                                            -- barrier
// When an effect has serial phases (prepare: e.g. a neighbour list; finish: e.g. dissipated
// work), they run between parallel regions, one region per step: their own parallel loops then
// use every thread.
// Nothing is allocated per step by the stepper. Forces are summed per element in a fixed order,
// so the result does not depend on the number of threads.
//
// Multiple time stepping (r-RESPA in its impulse form: Tuckerman, Berne & Martyna, J. Chem. Phys.
// 97, 1990 (1992); Grubmueller et al., Mol. Simul. 6, 121 (1991)): the effects of the outer group
// (contacts) are evaluated only at every `ratio`-th state (a "boundary" state), and their force
// F_o acts there as an impulse ratio h / 2 on either side, inside the inner kicks:
//   kick(H/2, F_o) [ kick(h/2, F_i) drift(h) F_i kick(h/2, F_i) ] x ratio  F_o kick(H/2, F_o),
// H = ratio h. Written into the steps above, the kick force of a boundary state is
// F_i + ratio F_o and that of any other state F_i: the scheme stays one kick-drift-kick step
// per h, symplectic and time reversible (the composition is symmetric), and the outer group
// costs 1/ratio of its evaluations. F_o is held in State::heldForce / heldTorque between
// boundaries (checkpointed). Numerical damping acts on the net force (local damping), so it
// sees F_i + F_o(held) at every step and vanishes at equilibrium as without the splitting;
// it must come after the outer effects in the force order (it does: order 500).
//
// Independent parts: when no effect couples filaments and the elements can be cut into one
// contiguous range per thread with no bond between ranges (separate filaments), each thread
// advances its range through all n steps with no barrier at all (ThreadPartition). This matters
// on a loaded machine, where every barrier may wait for a descheduled thread.
#include <string>
#include <utility>
#include <vector>

#include "mdem/boundary.hpp"
#include "mdem/effect.hpp"

namespace mesochain::mdem {

// What one force evaluation runs: the effects of a boundary state (all) or of an inner state
// (those not in the outer group), in force order.
struct StepPlan {
  std::vector<Effect*> withItems, withPrepare, withFinish;
  std::vector<Effect*> gathers;
  std::vector<char> held;          // per gather: an outer effect, gathered into the hold
  std::vector<int> itemSlot, gatherSlot;  // indices into EffectSequence::withItems / all (profile)
  bool anyHeld = false;
};

// The built effects in force order, with what the stepper needs to know of each.
struct EffectSequence {
  std::vector<Effect*> all;
  std::vector<Effect*> withItems, withPrepare, withFinish;  // of all
  std::vector<char> outer;  // per entry of `all`: in the outer group
  int ratio = 1;            // outer step / inner step; 1: no splitting
  StepPlan boundary, inner;
  bool couplesFilaments = false;
  bool recordsStepVelocities = false;  // an effect wants State::stepVelocity (Effect::wantsStepVelocities)
  // `outer` (empty or one flag per effect) takes effect when ratio > 1.
  explicit EffectSequence(const std::vector<Effect*>& effects = {}, std::vector<char> outer = {}, int ratio = 1);
  // Whether the state `cycleStep` steps after a boundary state is one.
  bool isBoundary(long cycleStep) const { return ratio == 1 || cycleStep % ratio == 0; }
};

// Contiguous element ranges, one per thread, that no bond crosses, and each thread's items.
struct ThreadPartition {
  int threads = 0;
  bool independent = false;       // false: no balanced cut exists (use the barrier scheme)
  std::vector<int> elementStart;  // threads + 1 entries
  // Per effect of EffectSequence::withItems: threads + 1 offsets into its item order.
  // Each part's items in the order of their lowest element (Effect::itemElement), and that element.
  std::vector<std::vector<int>> itemStart, itemOrder, itemLowest;
};

// Cuts the elements into `threads` ranges no bond crosses, each within 10% of the even share
// (elements are cut at the valid point nearest to the even split); independent = false if none,
// when an effect couples filaments, or with multiple time stepping.
ThreadPartition partitionElements(int elementCount, const std::vector<Bond>& bonds,
                                  const EffectSequence& effects, int threads);

// Wall seconds by phase of the step, measured on the first thread of the team (with static
// schedules every thread has an equal share; waits at barriers are counted in the phase before
// them): "prepare <effect>", "items <effect>", "gather <effect>", "integrate", "finish <effect>".
struct PhaseTimes {
  std::vector<std::pair<std::string, double>> seconds;
  double& operator[](const std::string& phase);
};

// Advances `steps` steps. On entry state.bodies.force / torque hold the kick forces of the
// current state (evaluateKickForces); on exit those of the final state. `partition` (may be
// null) selects the barrier-free scheme when it is independent and made for the current number
// of threads. `cycleStep`: steps of the current state since the last boundary state (or any
// multiple of the ratio plus that).
void advance(State& state, const EffectSequence& effects, const KinematicMap& kinematics, double h,
             long steps, const ThreadPartition* partition = nullptr, PhaseTimes* profile = nullptr,
             long cycleStep = 0);

// The kick forces of the current state taken as a boundary state, serially: every effect;
// with multiple time stepping the outer group into state.heldForce / heldTorque (sized here) and
// ratio times into the force; constrained components cleared. What a run starts from.
void evaluateKickForces(State& state, const EffectSequence& effects, const KinematicMap& kinematics);

// One force evaluation at state.time, serially (start-up, residuals): every effect of the
// sequence, numerical damping only when asked; constrained components cleared when asked.
void evaluateForces(State& state, const EffectSequence& effects, const KinematicMap& kinematics,
                    bool includeNumericalDamping, bool clearConstrained);

}  // namespace mesochain::mdem
