#include "mdem/stepper.hpp"

#include <algorithm>
#include <cstdlib>

#include <omp.h>

#include "mdem/integrator.hpp"

namespace mesochain::mdem {

namespace {

// Elements below this count run on one thread (the parallel region costs more than it saves).
constexpr int kParallelThreshold = 512;

// Total force and torque on element i at time t: `force` / `torque` enter with the
// contributions of other effects; bonds, loads and damping are added in the effects' order,
// constrained components cleared, and the result stored for the kick.
inline void finishForces(Bodies& s, int i, double t, const CoreEffects& core,
                         const KinematicMap& km, Vec3 force, Vec3 torque) {
  if (core.bonds) core.bonds->gather(i, force, torque);
  if (core.loads) core.loads->addToElement(s, i, t, force, torque);
  if (core.localDamping) core.localDamping->dampElement(s, i, force, torque);
  if (core.viscousDamping) core.viscousDamping->dampElement(s, i, force, torque);
  km.clearElement(i, force, torque);
  s.force[i] = force;
  s.torque[i] = torque;
}

// Kick h/2, constraints at t + h/2, drift h (t: the time before the step).
inline void openStep(Bodies& s, int i, double t, const KinematicMap& km, double h) {
  kickElement(s, i, 0.5 * h);
  km.applyElement(s, i, t + 0.5 * h);
  driftElement(s, i, h, km.kinematicRotation[i] != 0);
}

// Kick h/2, constraints at t (t: the time after the step).
inline void closeStep(Bodies& s, int i, double t, const KinematicMap& km, double h) {
  kickElement(s, i, 0.5 * h);
  km.applyElement(s, i, t);
}

}  // namespace

ThreadPartition partitionByBonds(int n, const std::vector<Bond>& bonds, int threads) {
  ThreadPartition p;
  p.threads = std::max(1, threads);
  // reach[c]: the largest element index bonded to an element below c; cut c is valid when
  // reach[c] < c (nothing below c is bonded to c or above).
  std::vector<int> reach(n + 1, -1);
  for (const Bond& b : bonds) {
    const int lo = std::min(b.a, b.b), hi = std::max(b.a, b.b);
    reach[lo + 1] = std::max(reach[lo + 1], hi);
  }
  for (int c = 1; c <= n; ++c) reach[c] = std::max(reach[c], reach[c - 1]);
  p.elementStart.assign(p.threads + 1, n);
  p.elementStart[0] = 0;
  p.independent = true;
  const double share = static_cast<double>(n) / p.threads;
  for (int t = 1; t < p.threads; ++t) {
    const int even = static_cast<int>(t * share);
    int best = -1;
    for (int d = 0; d <= static_cast<int>(0.1 * share) && best < 0; ++d) {
      if (even - d > p.elementStart[t - 1] && reach[even - d] < even - d) best = even - d;
      else if (even + d < n && reach[even + d] < even + d) best = even + d;
    }
    if (best < 0) {
      p.independent = false;
      return p;
    }
    p.elementStart[t] = best;
  }
  std::vector<int> owner(n);
  for (int t = 0; t < p.threads; ++t)
    for (int i = p.elementStart[t]; i < p.elementStart[t + 1]; ++i) owner[i] = t;
  p.bondStart.assign(p.threads + 1, 0);
  for (const Bond& b : bonds) ++p.bondStart[owner[b.a] + 1];
  for (int t = 0; t < p.threads; ++t) p.bondStart[t + 1] += p.bondStart[t];
  p.bondOrder.resize(bonds.size());
  std::vector<int> fill(p.bondStart.begin(), p.bondStart.end() - 1);
  for (int k = 0; k < static_cast<int>(bonds.size()); ++k) p.bondOrder[fill[owner[bonds[k].a]]++] = k;
  return p;
}

void advanceFused(State& state, const CoreEffects& core, const KinematicMap& km, double h,
                  long steps, const ThreadPartition* partition) {
  if (steps <= 0) return;
  Bodies& s = state.bodies;
  const int n = s.size();
  const int nb = core.bonds ? core.bonds->size() : 0;
  const double t0 = state.time;
  if (partition && partition->independent && partition->threads > 1 && n > kParallelThreshold) {
    const ThreadPartition& p = *partition;
#pragma omp parallel num_threads(p.threads)
    {
      // Whole parts per thread (a smaller team than planned takes several parts each).
      for (int part = omp_get_thread_num(); part < p.threads; part += omp_get_num_threads()) {
        const int lo = p.elementStart[part], hi = p.elementStart[part + 1];
        const int blo = p.bondStart[part], bhi = p.bondStart[part + 1];
        double t = t0;
        for (int i = lo; i < hi; ++i) openStep(s, i, t, km, h);
        for (long k = 0; k < steps; ++k) {
          t += h;
          for (int e = blo; e < bhi; ++e) core.bonds->computeBond(s, p.bondOrder[e]);
          const bool last = k + 1 == steps;
          for (int i = lo; i < hi; ++i) {
            finishForces(s, i, t, core, km, Vec3::Zero(), Vec3::Zero());
            closeStep(s, i, t, km, h);
            if (!last) openStep(s, i, t, km, h);
          }
        }
      }
    }
    for (long k = 0; k < steps; ++k) state.time += h;
    return;
  }
#pragma omp parallel if (n > kParallelThreshold)
  {
    double t = t0;  // every thread follows the same time sequence
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) openStep(s, i, t, km, h);
    for (long k = 0; k < steps; ++k) {
      t += h;
      if (nb > 0) {
#pragma omp for schedule(static)
        for (int b = 0; b < nb; ++b) core.bonds->computeBond(s, b);
      }
      const bool last = k + 1 == steps;
#pragma omp for schedule(static)
      for (int i = 0; i < n; ++i) {
        finishForces(s, i, t, core, km, Vec3::Zero(), Vec3::Zero());
        closeStep(s, i, t, km, h);
        if (!last) openStep(s, i, t, km, h);
      }
    }
  }
  for (long k = 0; k < steps; ++k) state.time += h;
}

void firstHalf(State& state, const KinematicMap& km, double h) {
  Bodies& s = state.bodies;
  const int n = s.size();
  const double t = state.time;
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (int i = 0; i < n; ++i) openStep(s, i, t, km, h);
  state.time += h;
}

void secondHalf(State& state, const CoreEffects& core, const KinematicMap& km, double h) {
  Bodies& s = state.bodies;
  const int n = s.size();
  const int nb = core.bonds ? core.bonds->size() : 0;
  const double t = state.time;
#pragma omp parallel if (n > kParallelThreshold)
  {
    if (nb > 0) {
#pragma omp for schedule(static)
      for (int b = 0; b < nb; ++b) core.bonds->computeBond(s, b);
    }
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      finishForces(s, i, t, core, km, s.force[i], s.torque[i]);
      closeStep(s, i, t, km, h);
    }
  }
}

}  // namespace mesochain::mdem
