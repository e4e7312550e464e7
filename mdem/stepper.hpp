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

// The built effects in force order, with what the stepper needs to know of each.
struct EffectSequence {
  std::vector<Effect*> all;
  std::vector<Effect*> withItems, withPrepare, withFinish;
  bool couplesFilaments = false;
  explicit EffectSequence(const std::vector<Effect*>& effects = {});
};

// Contiguous element ranges, one per thread, that no bond crosses, and each thread's items.
struct ThreadPartition {
  int threads = 0;
  bool independent = false;       // false: no balanced cut exists (use the barrier scheme)
  std::vector<int> elementStart;  // threads + 1 entries
  // Per effect of EffectSequence::withItems: threads + 1 offsets into its item order.
  std::vector<std::vector<int>> itemStart, itemOrder;
};

// Cuts the elements into `threads` ranges no bond crosses, each within 10% of the even share
// (elements are cut at the valid point nearest to the even split); independent = false if none,
// or when an effect couples filaments.
ThreadPartition partitionElements(int elementCount, const std::vector<Bond>& bonds,
                                  const EffectSequence& effects, int threads);

// Wall seconds by phase of the step, measured on the first thread of the team (with static
// schedules every thread has an equal share; waits at barriers are counted in the phase before
// them): "prepare <effect>", "items <effect>", "gather <effect>", "integrate", "finish <effect>".
struct PhaseTimes {
  std::vector<std::pair<std::string, double>> seconds;
  double& operator[](const std::string& phase);
};

// Advances `steps` steps. On entry state.bodies.force / torque hold the forces of the current
// state; on exit those of the final state. `partition` (may be null) selects the barrier-free
// scheme when it is independent and made for the current number of threads.
void advance(State& state, const EffectSequence& effects, const KinematicMap& kinematics, double h,
             long steps, const ThreadPartition* partition = nullptr, PhaseTimes* profile = nullptr);

// One force evaluation at state.time, serially (start-up, residuals): every effect of the
// sequence, numerical damping only when asked; constrained components cleared when asked.
void evaluateForces(State& state, const EffectSequence& effects, const KinematicMap& kinematics,
                    bool includeNumericalDamping, bool clearConstrained);

}  // namespace mesochain::mdem
