#include "mdem/stepper.hpp"

#include <algorithm>
#include <cstdlib>

#include <omp.h>

#include "mdem/integrator.hpp"

namespace mesochain::mdem {

namespace {

// Elements below this count run on one thread (the parallel region costs more than it saves).
constexpr int kParallelThreshold = 512;
// Elements per gather block (the block's forces stay in cache between the effects' gathers).
constexpr int kBlock = 64;
// Items per chunk of the item phase.
constexpr int kItemChunk = 256;

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

// Forces of elements [lo, hi) at time t: every effect's gather in order, constrained components
// cleared. Then close the step and, unless it is the last, open the next one.
inline void finishBlock(State& state, const EffectSequence& fx, const KinematicMap& km, int lo, int hi,
                        double t, double h, bool last) {
  Bodies& s = state.bodies;
  Vec3* force = s.force.data();
  Vec3* torque = s.torque.data();
  for (int i = lo; i < hi; ++i) force[i] = Vec3::Zero(), torque[i] = Vec3::Zero();
  for (const Effect* e : fx.all) e->gather(state, t, lo, hi, force, torque);
  for (int i = lo; i < hi; ++i) {
    km.clearElement(i, force[i], torque[i]);
    closeStep(s, i, t, km, h);
    if (!last) openStep(s, i, t, km, h);
  }
}

// The parallel part of a step at time t, called by every thread of the enclosing parallel
// region (its worksharing loops bind to that region): each effect's items, then per block of
// elements the gathers and the kicks.
void forcesAndKicks(State& state, const EffectSequence& fx, const KinematicMap& km, double t, double h, bool last) {
  const int n = state.bodies.size(), blocks = (n + kBlock - 1) / kBlock;
  for (Effect* e : fx.withItems) {
    const int items = e->itemCount();
    const int chunks = (items + kItemChunk - 1) / kItemChunk;
#pragma omp for schedule(static) nowait
    for (int c = 0; c < chunks; ++c) e->computeItems(state, t, c * kItemChunk, std::min(items, (c + 1) * kItemChunk));
  }
#pragma omp barrier
#pragma omp for schedule(static)
  for (int b = 0; b < blocks; ++b) finishBlock(state, fx, km, b * kBlock, std::min(n, (b + 1) * kBlock), t, h, last);
}

}  // namespace

EffectSequence::EffectSequence(const std::vector<Effect*>& effects) : all(effects) {
  for (Effect* e : all) {
    if (e->itemCount() > 0 || e->hasPrepare()) withItems.push_back(e);
    if (e->hasPrepare()) withPrepare.push_back(e);
    if (e->hasFinish()) withFinish.push_back(e);
    couplesFilaments = couplesFilaments || e->couplesFilaments();
  }
}

ThreadPartition partitionElements(int n, const std::vector<Bond>& bonds, const EffectSequence& fx, int threads) {
  ThreadPartition p;
  p.threads = std::max(1, threads);
  if (fx.couplesFilaments || !fx.withPrepare.empty() || !fx.withFinish.empty()) return p;
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
  const double share = static_cast<double>(n) / p.threads;
  for (int t = 1; t < p.threads; ++t) {
    const int even = static_cast<int>(t * share);
    int best = -1;
    for (int d = 0; d <= static_cast<int>(0.1 * share) && best < 0; ++d) {
      if (even - d > p.elementStart[t - 1] && reach[even - d] < even - d) best = even - d;
      else if (even + d < n && reach[even + d] < even + d) best = even + d;
    }
    if (best < 0) return p;
    p.elementStart[t] = best;
  }
  std::vector<int> owner(n);
  for (int t = 0; t < p.threads; ++t)
    for (int i = p.elementStart[t]; i < p.elementStart[t + 1]; ++i) owner[i] = t;
  for (const Effect* e : fx.withItems) {
    const int items = e->itemCount();
    std::vector<int> start(p.threads + 1, 0), order(items);
    for (int k = 0; k < items; ++k) {
      const int el = e->itemElement(k);
      if (el < 0 || el >= n) return p;  // an item without an element: no independent parts
      ++start[owner[el] + 1];
    }
    for (int t = 0; t < p.threads; ++t) start[t + 1] += start[t];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int k = 0; k < items; ++k) order[fill[owner[e->itemElement(k)]]++] = k;
    p.itemStart.push_back(std::move(start));
    p.itemOrder.push_back(std::move(order));
  }
  p.independent = true;
  return p;
}

void advance(State& state, const EffectSequence& fx, const KinematicMap& km, double h, long steps,
             const ThreadPartition* partition) {
  if (steps <= 0) return;
  Bodies& s = state.bodies;
  const int n = s.size();
  const double t0 = state.time;
  if (partition && partition->independent && partition->threads > 1 && n > kParallelThreshold) {
    const ThreadPartition& p = *partition;
#pragma omp parallel num_threads(p.threads)
    {
      // Whole parts per thread (a smaller team than planned takes several parts each).
      for (int part = omp_get_thread_num(); part < p.threads; part += omp_get_num_threads()) {
        const int lo = p.elementStart[part], hi = p.elementStart[part + 1];
        double t = t0;
        for (int i = lo; i < hi; ++i) openStep(s, i, t, km, h);
        for (long k = 0; k < steps; ++k) {
          t += h;
          for (std::size_t e = 0; e < fx.withItems.size(); ++e) {
            const std::vector<int>& start = p.itemStart[e];
            fx.withItems[e]->computeItemList(state, t, p.itemOrder[e].data() + start[part],
                                             start[part + 1] - start[part]);
          }
          const bool last = k + 1 == steps;
          for (int b = lo; b < hi; b += kBlock) finishBlock(state, fx, km, b, std::min(hi, b + kBlock), t, h, last);
        }
      }
    }
    for (long k = 0; k < steps; ++k) state.time += h;
    return;
  }
  if (!fx.withPrepare.empty() || !fx.withFinish.empty()) {
    // Effects with serial phases (neighbour lists, dissipated work): those run between parallel
    // regions, one region per step, so that their own parallel loops (the neighbour list's
    // displacement check and rebuild) use every thread instead of one inside a `single`.
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
    for (int i = 0; i < n; ++i) openStep(s, i, t0, km, h);
    double t = t0;
    for (long k = 0; k < steps; ++k) {
      t += h;
      for (Effect* e : fx.withPrepare) e->prepare(state, t);
      const bool last = k + 1 == steps;
#pragma omp parallel if (n > kParallelThreshold)
      forcesAndKicks(state, fx, km, t, h, last);
      for (Effect* e : fx.withFinish) e->finish(state, t);
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
      forcesAndKicks(state, fx, km, t, h, k + 1 == steps);
    }
  }
  for (long k = 0; k < steps; ++k) state.time += h;
}

void evaluateForces(State& state, const EffectSequence& fx, const KinematicMap& km, bool includeNumericalDamping,
                    bool clearConstrained) {
  Bodies& s = state.bodies;
  std::fill(s.force.begin(), s.force.end(), Vec3::Zero());
  std::fill(s.torque.begin(), s.torque.end(), Vec3::Zero());
  for (Effect* e : fx.all) {
    if (!includeNumericalDamping && e->role() == EffectRole::NumericalDamping) continue;
    if (e->hasPrepare()) e->prepare(state, state.time);
    e->computeItems(state, state.time, 0, e->itemCount());
    e->gather(state, state.time, 0, s.size(), s.force.data(), s.torque.data());
    if (e->hasFinish()) e->finish(state, state.time);
  }
  if (clearConstrained) km.clearConstrainedForces(s);
}

}  // namespace mesochain::mdem
