#pragma once
// The time step on one OpenMP parallel region (simulation.hpp describes the scheme).
//
// Every per-element operation of a step is fused into one loop over the elements and every
// per-bond operation into one loop over the bonds, all with static schedules over the same
// ranges (each thread keeps its elements from loop to loop and step to step). A run of n steps
// is one parallel region with two barriers per step:
//   [elements]  kick h/2, constraints, drift            (once, at the start of the run)
//   per step:   [bonds]     bond kernels into the per-bond buffer            -- barrier
//               [elements]  gather bonds, loads, damping, clear constrained,
//                           kick h/2, constraints; then the next step's
//                           kick h/2, constraints, drift                     -- barrier
// Nothing is allocated per step. Forces are summed per element in a fixed order, so the result
// does not depend on the number of threads.
//
// Independent parts: when the elements can be cut into one contiguous range per thread with no
// bond between ranges (separate filaments, and no other effect coupling them), each thread
// advances its range through all n steps with no barrier at all (ThreadPartition). This
// matters on a loaded machine, where every barrier may wait for a descheduled thread.
#include <vector>

#include "mdem/bond_effect.hpp"
#include "mdem/boundary.hpp"
#include "mdem/damping.hpp"

namespace mesochain::mdem {

// The effects the fused step knows; any may be null.
struct CoreEffects {
  BondEffect* bonds = nullptr;
  const LoadEffect* loads = nullptr;
  const LocalDamping* localDamping = nullptr;
  const ViscousDamping* viscousDamping = nullptr;
};

// Contiguous element ranges, one per thread, that no bond crosses; each thread's bonds.
struct ThreadPartition {
  int threads = 0;
  bool independent = false;       // false: no balanced cut exists (use the barrier scheme)
  std::vector<int> elementStart;  // threads + 1 entries
  std::vector<int> bondStart;     // threads + 1 entries into bondOrder
  std::vector<int> bondOrder;     // bond indices by thread
};

// Cuts the elements into `threads` ranges no bond crosses, each within 10% of the even share
// (elements are cut at the valid point nearest to the even split); independent = false if none.
ThreadPartition partitionByBonds(int elementCount, const std::vector<Bond>& bonds, int threads);

// Advances `steps` steps. On entry state.bodies.force / torque hold the forces of the current
// state; on exit those of the final state. `partition` (may be null) selects the barrier-free
// scheme when it is independent and made for the current number of threads.
void advanceFused(State& state, const CoreEffects& core, const KinematicMap& kinematics,
                  double h, long steps, const ThreadPartition* partition = nullptr);

// The two halves of one step, for scenes with other effects (which add their forces between
// the halves, with their own parallel loops):
//   firstHalf:   kick h/2, constraints, drift; time += h.
//   secondHalf:  with state.bodies.force / torque holding the other effects' forces: add the
//                core effects, clear constrained components, kick h/2, constraints.
void firstHalf(State& state, const KinematicMap& kinematics, double h);
void secondHalf(State& state, const CoreEffects& core, const KinematicMap& kinematics, double h);

}  // namespace mesochain::mdem
