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

// Kick forces of elements [lo, hi) at time t under `plan`: every gather in order, the outer
// group into the hold (boundary plans only) and `ratio` times into the force; numerical damping
// sees the held outer force (stepper.hpp); constrained components cleared.
// `gatherSeconds` (may be null): per entry of EffectSequence::all.
inline void gatherBlock(State& state, const EffectSequence& fx, const StepPlan& plan, const KinematicMap& km,
                        int lo, int hi, double t, double* gatherSeconds) {
  Bodies& s = state.bodies;
  Vec3* force = s.force.data();
  Vec3* torque = s.torque.data();
  for (int i = lo; i < hi; ++i) force[i] = Vec3::Zero(), torque[i] = Vec3::Zero();
  const bool split = fx.ratio > 1;
  Vec3* heldF = split ? state.heldForce.data() : nullptr;
  Vec3* heldT = split ? state.heldTorque.data() : nullptr;
  if (plan.anyHeld)
    for (int i = lo; i < hi; ++i) heldF[i] = Vec3::Zero(), heldT[i] = Vec3::Zero();
  bool heldAdded = false;
  for (std::size_t k = 0; k < plan.gathers.size(); ++k) {
    const Effect* e = plan.gathers[k];
    const double t0 = gatherSeconds ? omp_get_wtime() : 0.0;
    if (plan.held[k]) {
      e->gather(state, t, lo, hi, heldF, heldT);
    } else {
      if (split && !heldAdded && e->role() == EffectRole::NumericalDamping) {
        for (int i = lo; i < hi; ++i) force[i] += heldF[i], torque[i] += heldT[i];
        heldAdded = true;
      }
      e->gather(state, t, lo, hi, force, torque);
    }
    if (gatherSeconds) gatherSeconds[plan.gatherSlot[k]] += omp_get_wtime() - t0;
  }
  if (split) {
    // The outer impulse: ratio F_o at a boundary, nothing in between (less what damping saw).
    const double w = (plan.anyHeld ? fx.ratio : 0) - (heldAdded ? 1 : 0);
    if (w != 0.0)
      for (int i = lo; i < hi; ++i) force[i] += w * heldF[i], torque[i] += w * heldT[i];
  }
  for (int i = lo; i < hi; ++i) km.clearElement(i, force[i], torque[i]);
}

// The kicks (and drifts) of finishBlock; `record`: State::stepVelocity gets the velocities of
// time t, between the two half kicks.
template <bool record>
inline void kickBlock(State& state, const KinematicMap& km, int lo, int hi, double t, double h, bool last) {
  Bodies& s = state.bodies;
  const auto recordAt = [&](int i) {
    if constexpr (record) state.stepVelocity[i] = s.velocity[i], state.stepAngularVelocity[i] = s.angularVelocityWorld(i);
  };
  // closeStep then openStep of a free element: the two half kicks share their force and
  // orientation, so the increment is formed once and added twice (the same sums, bit for bit, as
  // two kickElement calls: a run resumed between them gives the same state).
  const auto kickTwice = [&](int i) { kickElementTwice(s, i, 0.5 * h, [&] { recordAt(i); }); };
  for (int i = lo; i < hi; ++i) {
    if (!last && !km.constrained(i)) {
      // Two free neighbours drift together (driftFreePair: the same results, overlapped).
      kickTwice(i);
      if (i + 1 < hi && !km.constrained(i + 1)) {
        kickTwice(i + 1);
        driftFreePair(s, i, h);
        ++i;
      } else {
        driftElement(s, i, h, false);
      }
      continue;
    }
    closeStep(s, i, t, km, h);
    recordAt(i);
    if (!last) openStep(s, i, t, km, h);
  }
}

// Forces of elements [lo, hi) at time t; then close the step and, unless it is the last, open
// the next one.
inline void finishBlock(State& state, const EffectSequence& fx, const StepPlan& plan, const KinematicMap& km, int lo,
                        int hi, double t, double h, bool last, double* gatherSeconds = nullptr) {
  gatherBlock(state, fx, plan, km, lo, hi, t, gatherSeconds);
  if (fx.recordsStepVelocities)
    kickBlock<true>(state, km, lo, hi, t, h, last);
  else
    kickBlock<false>(state, km, lo, hi, t, h, last);
}

// The parallel part of a step at time t, called by every thread of the enclosing parallel
// region (its worksharing loops bind to that region): each effect's items, then per block of
// elements the gathers and the kicks.
// `profile` (may be null): seconds of the first thread, per effect's items, per effect's
// gather, then the rest of the block loop (integrate).
void forcesAndKicks(State& state, const EffectSequence& fx, const StepPlan& plan, const KinematicMap& km, double t,
                    double h, bool last, std::vector<double>* profile) {
  const int n = state.bodies.size(), blocks = (n + kBlock - 1) / kBlock;
  const bool timing = profile && omp_get_thread_num() == 0;
  double mark = timing ? omp_get_wtime() : 0.0;
  for (std::size_t k = 0; k < plan.withItems.size(); ++k) {
    Effect* e = plan.withItems[k];
    const int items = e->itemCount();
    const int chunks = (items + kItemChunk - 1) / kItemChunk;
#pragma omp for schedule(static) nowait
    for (int c = 0; c < chunks; ++c) e->computeItems(state, t, c * kItemChunk, std::min(items, (c + 1) * kItemChunk));
    if (timing) {
      const double now = omp_get_wtime();
      (*profile)[plan.itemSlot[k]] += now - mark, mark = now;
    }
  }
#pragma omp barrier
  if (timing) {
    const double now = omp_get_wtime();
    if (!plan.withItems.empty()) (*profile)[plan.itemSlot.back()] += now - mark;  // the wait
    mark = now;
  }
  double* gathers = timing ? profile->data() + fx.withItems.size() : nullptr;
#pragma omp for schedule(static)
  for (int b = 0; b < blocks; ++b)
    finishBlock(state, fx, plan, km, b * kBlock, std::min(n, (b + 1) * kBlock), t, h, last, gathers);
  if (timing) profile->back() += omp_get_wtime() - mark;  // block loop incl. gathers (collect subtracts them)
}

StepPlan makePlan(const EffectSequence& fx, bool boundary) {
  StepPlan p;
  const bool split = fx.ratio > 1;
  for (std::size_t k = 0; k < fx.all.size(); ++k) {
    Effect* e = fx.all[k];
    const bool outer = split && fx.outer[k];
    if (outer && !boundary) continue;
    p.gathers.push_back(e);
    p.held.push_back(outer ? 1 : 0);
    p.gatherSlot.push_back(static_cast<int>(k));
    p.anyHeld = p.anyHeld || outer;
    if (e->hasPrepare()) p.withPrepare.push_back(e);
    if (e->hasFinish()) p.withFinish.push_back(e);
  }
  for (std::size_t k = 0; k < fx.withItems.size(); ++k) {
    Effect* e = fx.withItems[k];
    const auto at = std::find(fx.all.begin(), fx.all.end(), e) - fx.all.begin();
    if (split && fx.outer[at] && !boundary) continue;
    p.withItems.push_back(e);
    p.itemSlot.push_back(static_cast<int>(k));
  }
  return p;
}

}  // namespace

EffectSequence::EffectSequence(const std::vector<Effect*>& effects, std::vector<char> outerGroup, int outerRatio)
    : all(effects), outer(std::move(outerGroup)), ratio(std::max(1, outerRatio)) {
  outer.resize(all.size(), 0);
  for (Effect* e : all) {
    if (e->itemCount() > 0 || e->hasPrepare()) withItems.push_back(e);
    if (e->hasPrepare()) withPrepare.push_back(e);
    if (e->hasFinish()) withFinish.push_back(e);
    couplesFilaments = couplesFilaments || e->couplesFilaments();
    recordsStepVelocities = recordsStepVelocities || e->wantsStepVelocities();
  }
  if (std::find(outer.begin(), outer.end(), 1) == outer.end()) ratio = 1;
  boundary = makePlan(*this, true);
  inner = makePlan(*this, false);
}

ThreadPartition partitionElements(int n, const std::vector<Bond>& bonds, const EffectSequence& fx, int threads) {
  ThreadPartition p;
  p.threads = std::max(1, threads);
  if (fx.couplesFilaments || fx.ratio > 1 || !fx.withPrepare.empty() || !fx.withFinish.empty()) return p;
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
    // Each part's items by their lowest element, the order in which its block sweep computes them.
    std::vector<int> element(items), lowest(items);
    for (int k = 0; k < items; ++k) element[k] = e->itemElement(k);
    for (int t = 0; t < p.threads; ++t)
      std::stable_sort(order.begin() + start[t], order.begin() + start[t + 1],
                       [&element](int x, int y) { return element[x] < element[y]; });
    for (int m = 0; m < items; ++m) lowest[m] = element[order[m]];
    p.itemLowest.push_back(std::move(lowest));
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
             const ThreadPartition* partition, PhaseTimes* profile, long cycleStep) {
  if (steps <= 0) return;
  std::vector<double> slots = profile ? profileSlots(fx) : std::vector<double>{};
  Bodies& s = state.bodies;
  const int n = s.size();
  if (fx.recordsStepVelocities) state.stepVelocity.resize(n), state.stepAngularVelocity.resize(n);
  const double t0 = state.time;
  // The barrier-free sweep, also on one thread (items computed block by block stay in cache),
  // except for a one-thread profile, which the phase-by-phase scheme below splits by phase.
  if (partition && partition->independent && n > kParallelThreshold && fx.ratio == 1 &&
      (partition->threads > 1 || !profile)) {
    const ThreadPartition& p = *partition;
    const double start = omp_get_wtime();
#pragma omp parallel num_threads(p.threads)
    {
      // Whole parts per thread (a smaller team than planned takes several parts each).
      for (int part = omp_get_thread_num(); part < p.threads; part += omp_get_num_threads()) {
        const int lo = p.elementStart[part], hi = p.elementStart[part + 1];
        double t = t0;
        for (int i = lo; i < hi; ++i) openStep(s, i, t, km, h);
        std::vector<int> next(fx.withItems.size());
        for (long k = 0; k < steps; ++k) {
          t += h;
          const bool last = k + 1 == steps;
          for (std::size_t e = 0; e < fx.withItems.size(); ++e) next[e] = p.itemStart[e][part];
          // One sweep over the part's blocks: before a block's gathers and kicks, the items whose
          // lowest element lies below the block's end (all its elements' items; every element
          // an item touches is at or above its lowest, so none has drifted yet). The items'
          // data and results are still in cache when the block gathers them.
          for (int b = lo; b < hi; b += kBlock) {
            const int end = std::min(hi, b + kBlock);
            for (std::size_t e = 0; e < fx.withItems.size(); ++e) {
              const int* order = p.itemOrder[e].data();
              const int* lowest = p.itemLowest[e].data();
              const int stop = p.itemStart[e][part + 1];
              int m = next[e];
              while (m < stop && lowest[m] < end) ++m;
              fx.withItems[e]->computeItemList(state, t, order + next[e], m - next[e]);
              next[e] = m;
            }
            finishBlock(state, fx, fx.boundary, km, b, end, t, h, last);
          }
        }
      }
    }
    for (long k = 0; k < steps; ++k) state.time += h;
    if (profile) (*profile)["independent parts (items, gathers, integrate)"] += omp_get_wtime() - start;
    return;
  }
  // The plan of step k (0-based here): that of the state it ends in.
  auto planOf = [&](long k) -> const StepPlan& { return fx.isBoundary(cycleStep + k + 1) ? fx.boundary : fx.inner; };
  // Steps run in parallel regions; an effect's serial phases (prepare: e.g. a neighbour list;
  // finish: dissipated work) run between regions, so that their own parallel loops use every
  // thread. A region spans as many steps as need no serial phase in between (all of them
  // without such effects; with multiple time stepping the inner steps between boundaries).
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (int i = 0; i < n; ++i) openStep(s, i, t0, km, h);
  double t = t0;
  for (long k = 0; k < steps;) {
    for (Effect* e : planOf(k).withPrepare) {
      const double t1 = omp_get_wtime();
      e->prepare(state, t + h);
      if (profile) (*profile)["prepare " + e->name()] += omp_get_wtime() - t1;
    }
    long end = k + 1;
    while (end < steps && planOf(end - 1).withFinish.empty() && planOf(end).withPrepare.empty()) ++end;
#pragma omp parallel if (n > kParallelThreshold)
    {
      double tk = t;  // every thread follows the same time sequence
      for (long j = k; j < end; ++j) {
        tk += h;
        forcesAndKicks(state, fx, planOf(j), km, tk, h, j + 1 == steps, profile ? &slots : nullptr);
      }
    }
    for (long j = k; j < end; ++j) t += h;
    for (Effect* e : planOf(end - 1).withFinish) {
      const double t1 = omp_get_wtime();
      e->finish(state, t);
      if (profile) (*profile)["finish " + e->name()] += omp_get_wtime() - t1;
    }
    k = end;
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

void evaluateKickForces(State& state, const EffectSequence& fx, const KinematicMap& km) {
  Bodies& s = state.bodies;
  if (fx.ratio > 1) {
    state.heldForce.assign(s.size(), Vec3::Zero());
    state.heldTorque.assign(s.size(), Vec3::Zero());
  }
  const StepPlan& plan = fx.boundary;
  for (Effect* e : plan.withPrepare) e->prepare(state, state.time);
  for (Effect* e : plan.withItems) e->computeItems(state, state.time, 0, e->itemCount());
  gatherBlock(state, fx, plan, km, 0, s.size(), state.time, nullptr);
  for (Effect* e : plan.withFinish) e->finish(state, state.time);
}

}  // namespace mesochain::mdem
