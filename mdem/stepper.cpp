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
                        double t, double h, bool last, double* gatherSeconds = nullptr) {
  Bodies& s = state.bodies;
  Vec3* force = s.force.data();
  Vec3* torque = s.torque.data();
  for (int i = lo; i < hi; ++i) force[i] = Vec3::Zero(), torque[i] = Vec3::Zero();
  if (gatherSeconds) {
    for (std::size_t k = 0; k < fx.all.size(); ++k) {
      const double t0 = omp_get_wtime();
      fx.all[k]->gather(state, t, lo, hi, force, torque);
      gatherSeconds[k] += omp_get_wtime() - t0;
    }
  } else {
    for (const Effect* e : fx.all) e->gather(state, t, lo, hi, force, torque);
  }
  for (int i = lo; i < hi; ++i) {
    km.clearElement(i, force[i], torque[i]);
    closeStep(s, i, t, km, h);
    if (!last) openStep(s, i, t, km, h);
  }
}

// The parallel part of a step at time t, called by every thread of the enclosing parallel
// region (its worksharing loops bind to that region): each effect's items, then per block of
// elements the gathers and the kicks.
// `profile` (may be null): seconds of the first thread, per effect's items, per effect's
// gather, then the rest of the block loop (integrate).
void forcesAndKicks(State& state, const EffectSequence& fx, const KinematicMap& km, double t, double h, bool last,
                    std::vector<double>* profile) {
  const int n = state.bodies.size(), blocks = (n + kBlock - 1) / kBlock;
  const bool timing = profile && omp_get_thread_num() == 0;
  double mark = timing ? omp_get_wtime() : 0.0;
  for (std::size_t k = 0; k < fx.withItems.size(); ++k) {
    Effect* e = fx.withItems[k];
    const int items = e->itemCount();
    const int chunks = (items + kItemChunk - 1) / kItemChunk;
#pragma omp for schedule(static) nowait
    for (int c = 0; c < chunks; ++c) e->computeItems(state, t, c * kItemChunk, std::min(items, (c + 1) * kItemChunk));
    if (timing) {
      const double now = omp_get_wtime();
      (*profile)[k] += now - mark, mark = now;
    }
  }
#pragma omp barrier
  if (timing) {
    const double now = omp_get_wtime();
    if (!fx.withItems.empty()) (*profile)[fx.withItems.size() - 1] += now - mark;  // the wait
    mark = now;
  }
  double* gathers = timing ? profile->data() + fx.withItems.size() : nullptr;
#pragma omp for schedule(static)
  for (int b = 0; b < blocks; ++b) finishBlock(state, fx, km, b * kBlock, std::min(n, (b + 1) * kBlock), t, h, last, gathers);
  if (timing) profile->back() += omp_get_wtime() - mark;  // block loop incl. gathers (collect subtracts them)
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

double& PhaseTimes::operator[](const std::string& phase) {
  for (auto& [name, value] : seconds)
    if (name == phase) return value;
  seconds.emplace_back(phase, 0.0);
  return seconds.back().second;
}

namespace {
// Slots of forcesAndKicks: items of each effect with items, gather of each effect, integrate.
std::vector<double> profileSlots(const EffectSequence& fx) { return std::vector<double>(fx.withItems.size() + fx.all.size() + 1, 0.0); }
void collect(const EffectSequence& fx, const std::vector<double>& slots, PhaseTimes* profile) {
  if (!profile) return;
  double gathered = 0.0;
  for (std::size_t k = 0; k < fx.withItems.size(); ++k) (*profile)["items " + fx.withItems[k]->name()] += slots[k];
  for (std::size_t k = 0; k < fx.all.size(); ++k) {
    (*profile)["gather " + fx.all[k]->name()] += slots[fx.withItems.size() + k];
    gathered += slots[fx.withItems.size() + k];
  }
  (*profile)["integrate"] += slots.back() - gathered;
}
}  // namespace

void advance(State& state, const EffectSequence& fx, const KinematicMap& km, double h, long steps,
             const ThreadPartition* partition, PhaseTimes* profile) {
  if (steps <= 0) return;
  std::vector<double> slots = profile ? profileSlots(fx) : std::vector<double>{};
  Bodies& s = state.bodies;
  const int n = s.size();
  const double t0 = state.time;
  if (partition && partition->independent && partition->threads > 1 && n > kParallelThreshold) {
    const ThreadPartition& p = *partition;
    const double start = omp_get_wtime();
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
    if (profile) (*profile)["independent parts (items, gathers, integrate)"] += omp_get_wtime() - start;
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
      for (Effect* e : fx.withPrepare) {
        const double t1 = omp_get_wtime();
        e->prepare(state, t);
        if (profile) (*profile)["prepare " + e->name()] += omp_get_wtime() - t1;
      }
      const bool last = k + 1 == steps;
#pragma omp parallel if (n > kParallelThreshold)
      forcesAndKicks(state, fx, km, t, h, last, profile ? &slots : nullptr);
      for (Effect* e : fx.withFinish) {
        const double t1 = omp_get_wtime();
        e->finish(state, t);
        if (profile) (*profile)["finish " + e->name()] += omp_get_wtime() - t1;
      }
    }
    for (long k = 0; k < steps; ++k) state.time += h;
    collect(fx, slots, profile);
    return;
  }
#pragma omp parallel if (n > kParallelThreshold)
  {
    double t = t0;  // every thread follows the same time sequence
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) openStep(s, i, t, km, h);
    for (long k = 0; k < steps; ++k) {
      t += h;
      forcesAndKicks(state, fx, km, t, h, k + 1 == steps, profile ? &slots : nullptr);
    }
  }
  for (long k = 0; k < steps; ++k) state.time += h;
  collect(fx, slots, profile);
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
