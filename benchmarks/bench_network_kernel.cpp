// `mesochain-bench network --kernel-curve` (bench_network_kernel.hpp).
#include "benchmarks/bench_network_kernel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/contacts/vdw_contact.hpp"

namespace mesochain::app {

namespace {
// The anisotropic kernel over the contact pairs of a network: each list pair as the contact
// effect orders it (quadrature along the element of the lower filament).
using SegmentPair = std::pair<mdem::Segment, mdem::Segment>;
std::vector<SegmentPair> networkPairs(const mdem::Scene& s) {
  const mdem::ContactNeighbourhood nb(s, mdem::VdwContactEffect::interactionRange(s));
  const mdem::FilamentTopology& topo = nb.topology();
  std::vector<SegmentPair> out;
  for (const auto& [i, j] : nb.list().pairs()) {
    const bool iOuter = topo.filament[i] != topo.filament[j] ? topo.filament[i] < topo.filament[j] : i < j;
    const int o = iOuter ? i : j, in = iOuter ? j : i;
    const mdem::Segment so = nb.segment(s.bodies, o);
    out.emplace_back(so, nb.imageNear(s.bodies, in, so.centre));
  }
  return out;
}

// All pairs, `repeat` times (the function callgrind is told to collect: --toggle-collect=*evaluatePairs*).
template <class Kernel>
__attribute__((noinline)) double evaluatePairs(const Kernel& kernel, const std::vector<SegmentPair>& pairs, int repeat,
                                               std::vector<mdem::ContactPairResult>* out) {
  double sum = 0.0;
  out->resize(pairs.size());
  for (int r = 0; r < repeat; ++r)
    for (std::size_t k = 0; k < pairs.size(); ++k) sum += ((*out)[k] = kernel(pairs[k].first, pairs[k].second)).energy;
  return sum;
}

struct KernelError {
  double energyMax = 0.0, energySum = 0.0, forceMax = 0.0, nsPerPair = 0.0;
};

// Errors against the 64-point rule: largest |dE| in units of the contact energy scale |Phi_eq| 2 la,
// sum |dE| over sum |E|, largest |dF| (force and torque on both elements) over the largest |F|.
template <class Kernel>
KernelError kernelError(const Kernel& kernel, const std::vector<SegmentPair>& pairs,
                        const std::vector<mdem::ContactPairResult>& ref, double scale, double seconds) {
  std::vector<mdem::ContactPairResult> out;
  evaluatePairs(kernel, pairs, 1, &out);
  KernelError e;
  double refSum = 0.0, fRef = 0.0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const mdem::ContactPairResult &a = out[k], &b = ref[k];
    e.energyMax = std::max(e.energyMax, std::abs(a.energy - b.energy) / scale);
    e.energySum += std::abs(a.energy - b.energy), refSum += std::abs(b.energy);
    fRef = std::max({fRef, b.forceA.norm(), b.torqueA.norm(), b.torqueB.norm()});
    e.forceMax = std::max({e.forceMax, (a.forceA - b.forceA).norm(), (a.torqueA - b.torqueA).norm(),
                           (a.torqueB - b.torqueB).norm()});
  }
  e.energySum /= refSum, e.forceMax /= fRef;
  // Wall time per pair: best of a few rounds of `seconds` / 5 each (noisy machine: use callgrind).
  double best = 1e300;
  for (int round = 0; round < 5; ++round) {
    const auto t0 = std::chrono::steady_clock::now();
    long evaluated = 0;
    double elapsed = 0.0;
    while (elapsed < seconds / 5) {
      evaluatePairs(kernel, pairs, 1, &out);
      evaluated += static_cast<long>(pairs.size());
      elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    best = std::min(best, 1e9 * elapsed / evaluated);
  }
  e.nsPerPair = best;
  return e;
}

// The aligned path (vdw_contact.hpp, enableAlignedPath) against its window, 8 Gauss points: the
// errors, the cost and where the interacting pairs fall (weight 1: tables only; ramp: both; rule).
void printAlignedWindowRows(const mdem::TubePairPotential& potential, const std::vector<SegmentPair>& pairs,
                            const std::vector<mdem::ContactPairResult>& ref, double scale, double la, double lb,
                            double seconds) {
  std::cout << "aligned window (degrees; 8 points): errors as above; interacting pairs on the tables alone / in "
               "the blend ramps / on the rule\n";
  for (double window : {0.0, 0.25, 0.5, 0.75, 1.0, 1.15}) {
    mdem::AnisotropicVdwKernel k(potential, lb, 8);
    k.enableAlignedPath(la, window);
    const KernelError e = kernelError([&k](const mdem::Segment& a, const mdem::Segment& b) { return mdem::anisotropicVdw(k, a, b); },
                                      pairs, ref, scale, seconds);
    long tables = 0, ramp = 0, rule = 0;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (ref[p].energy == 0.0) continue;
      const double w = k.aligned ? mdem::alignedWeight(k, pairs[p].first, pairs[p].second) : 0.0;
      (w == 1.0 ? tables : w > 0.0 ? ramp : rule) += 1;
    }
    std::cout << fmt::format("aligned {:4.1f}  {:10.3g}  {:11.3g}  {:10.3g}  {:8.1f}   {} / {} / {}\n", window, e.energyMax,
                             e.energySum, e.forceMax, e.nsPerPair, tables, ramp, rule)
              << std::flush;
  }
}

// Geometry of a pair as the tables below print it: the crossing angle (degrees, 0-90) and the
// distance of a's centre from b's axis line.
struct PairGeometry {
  double degrees = 0.0, lineDistance = 0.0, axialOffset = 0.0;
};
PairGeometry pairGeometry(const SegmentPair& p) {
  const mdem::Vec3 r0 = p.first.centre - p.second.centre;
  const double f = r0.dot(p.second.axis);
  const double c = std::min(1.0, std::abs(p.first.axis.dot(p.second.axis)));
  return {std::acos(c) * 180.0 / 3.14159265358979323846, std::sqrt(std::max(0.0, r0.squaredNorm() - f * f)), f};
}

// The errors of the table path split by the crossing angle of the interacting pairs: whether a
// rule of fewer points would do for a class. Aligned pairs (< 10 degrees) whose axes nearly meet
// (a's centre within 1 nm of b's line: tube ends facing each other) are a class of their own.
void printAngleClassRows(const mdem::TubePairPotential& potential, const std::vector<SegmentPair>& pairs,
                         const std::vector<mdem::ContactPairResult>& ref, double scale, double lb) {
  const std::vector<double> edges{0.0, 2.0, 5.0, 10.0, 20.0, 45.0, 90.01};
  const int endOn = static_cast<int>(edges.size()) - 1;
  std::vector<int> cls(pairs.size(), -1);
  std::vector<long> count(edges.size(), 0);
  double fRef = 0.0;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    fRef = std::max({fRef, ref[p].forceA.norm(), ref[p].torqueA.norm(), ref[p].torqueB.norm()});
    if (ref[p].energy == 0.0) continue;
    const PairGeometry g = pairGeometry(pairs[p]);
    int k = 0;
    while (g.degrees >= edges[k + 1]) ++k;
    cls[p] = g.degrees < 10.0 && g.lineDistance < 1.0 ? endOn : k;
    ++count[cls[p]];
  }
  std::cout << "by crossing angle (degrees; table path): interacting pairs per class, then per rule the class's energy "
               "max (units as above) / force max (over the largest force of all pairs)\n  points";
  for (int k = 0; k < endOn; ++k)
    std::cout << fmt::format("  {:>5.0f}-{:<2.0f} ({:6d})", edges[k], std::min(90.0, edges[k + 1]), count[k]);
  std::cout << fmt::format("  end-on   ({:6d})\n", count[endOn]);
  const auto row = [&](const mdem::AnisotropicVdwKernel& k, const std::string& label) {
    std::vector<double> eMax(count.size(), 0.0), fMax(count.size(), 0.0);
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (cls[p] < 0) continue;
      const mdem::ContactPairResult a = mdem::anisotropicVdw(k, pairs[p].first, pairs[p].second);
      const mdem::ContactPairResult& b = ref[p];
      eMax[cls[p]] = std::max(eMax[cls[p]], std::abs(a.energy - b.energy) / scale);
      fMax[cls[p]] = std::max({fMax[cls[p]], (a.forceA - b.forceA).norm() / fRef, (a.torqueA - b.torqueA).norm() / fRef,
                               (a.torqueB - b.torqueB).norm() / fRef});
    }
    std::cout << fmt::format("  {:>6}", label);
    for (std::size_t c = 0; c < count.size(); ++c) std::cout << fmt::format("  {:8.2g}/{:<8.2g}", eMax[c], fMax[c]);
    std::cout << "\n" << std::flush;
  };
  for (int n : {3, 4, 5, 6, 7, 8, 10, 12}) row(mdem::AnisotropicVdwKernel(potential, lb, n), std::to_string(n));
  // The crossing rule (vdw_contact.hpp, enableCrossingRule): 8 points, and more beyond the ramp.
  for (int n : {10, 12, 16}) {
    mdem::AnisotropicVdwKernel k(potential, lb, 8);
    k.enableCrossingRule(n);
    row(k, fmt::format("8+{}", n));
  }
}

// Corrugation of a crossing sliding along a straight tube: the quadrature element's chain (7
// elements along x) and one partner element crossing it at `degrees` at the equilibrium axis
// distance, moved along the chain by 4 nm in steps of 0.005 nm. The exact energy is constant
// (the chain is uniform); the rule's ripple (max - min) and the largest force along the chain
// are the friction the quadrature adds to sliding crossings.
void printCrossingCorrugation(const mdem::TubePairPotential& potential, double la, double lb) {
  std::cout << "crossing sliding along a straight tube at the equilibrium axis distance: energy ripple (zJ) / largest "
               "force along the tube (pN) per rule\n  points";
  const std::vector<double> angles{90.0, 45.0, 20.0};
  for (double deg : angles) std::cout << fmt::format("  {:>16}", fmt::format("{:.0f} degrees", deg));
  std::cout << "\n";
  const double d = potential.equilibriumDistance();
  for (int n : {6, 8, 10, 12, 16, -12}) {  // -12: 8 points with the crossing rule of 12
    mdem::AnisotropicVdwKernel k(potential, lb, n > 0 ? n : 8);
    if (n < 0) k.enableCrossingRule(-n);
    std::cout << fmt::format("  {:>6}", n > 0 ? std::to_string(n) : fmt::format("8+{}", -n));
    for (double deg : angles) {
      const double t = deg * 3.14159265358979323846 / 180.0;
      double lo = 1e300, hi = -1e300, force = 0.0;
      for (int step = 0; step <= 800; ++step) {
        const mdem::Segment b{mdem::Vec3(-2.0 + 0.005 * step, d, 0.0), mdem::Vec3(std::cos(t), 0.0, std::sin(t)), lb};
        double e = 0.0, fx = 0.0;
        for (int i = -3; i <= 3; ++i) {
          const mdem::ContactPairResult r = mdem::anisotropicVdw(k, mdem::Segment{mdem::Vec3(2.0 * la * i, 0.0, 0.0), mdem::Vec3::UnitX(), la}, b);
          e += r.energy, fx += r.forceB.x();
        }
        lo = std::min(lo, e), hi = std::max(hi, e), force = std::max(force, std::abs(fx));
      }
      std::cout << fmt::format("  {:7.3g} / {:6.3g}", hi - lo, force);
    }
    std::cout << "\n";
  }
}

// The pairs of largest energy error with `points` Gauss points (the scene's rule): their geometry.
void printWorstPairs(const mdem::TubePairPotential& potential, const std::vector<SegmentPair>& pairs,
                     const std::vector<mdem::ContactPairResult>& ref, double scale, double lb, int points) {
  const mdem::AnisotropicVdwKernel k(potential, lb, points);
  std::vector<std::pair<double, std::size_t>> error;
  for (std::size_t p = 0; p < pairs.size(); ++p)
    if (ref[p].energy != 0.0)
      error.emplace_back(std::abs(mdem::anisotropicVdw(k, pairs[p].first, pairs[p].second).energy - ref[p].energy) / scale, p);
  const std::size_t shown = std::min<std::size_t>(8, error.size());
  std::partial_sort(error.begin(), error.begin() + static_cast<std::ptrdiff_t>(shown), error.end(), std::greater<>());
  std::cout << fmt::format("the {} pairs of largest energy error at {} points: error, energy (zJ), angle (degrees), distance "
                           "of a's centre from b's axis line and along it (nm)\n",
                           shown, points);
  for (std::size_t q = 0; q < shown; ++q) {
    const PairGeometry g = pairGeometry(pairs[error[q].second]);
    std::cout << fmt::format("  {:9.3g}  {:9.4g}  {:6.2f}  {:7.4f}  {:7.4f}\n", error[q].first, ref[error[q].second].energy,
                             g.degrees, g.lineDistance, g.axialOffset);
  }
}

}  // namespace

int printKernelCurve(const mdem::Scene& s, const KernelCurveOptions& o) {
  const std::vector<SegmentPair> pairs = networkPairs(s);
  mdem::TubePairSpec ps;
  ps.lj = s.contacts.vdw.lj, ps.radiusA = ps.radiusB = s.elementTypes[0].radius;
  ps.switchGap = s.contacts.vdw.switchGap, ps.cutoffGap = s.contacts.vdw.cutoffGap;
  const mdem::TubePairPotential potential(ps);
  const double la = 0.5 * s.elementTypes[0].length, lb = la;
  const auto line = [&](const mdem::QuadratureRule& rule) {
    return [&potential, rule](const mdem::Segment& a, const mdem::Segment& b) { return mdem::anisotropicVdw(potential, rule, a, b); };
  };
  if (o.points > 0) {  // one variant only, for callgrind
    std::vector<mdem::ContactPairResult> out;
    double sum = 0.0;
    if (o.path == "line") {
      sum = evaluatePairs(line(mdem::gaussLegendre(o.points)), pairs, o.repeat, &out);
    } else {
      mdem::AnisotropicVdwKernel k(potential, lb, o.points);
      if (o.alignedWindow > 0.0) k.enableAlignedPath(la, o.alignedWindow);
      if (o.crossingPoints > 0) k.enableCrossingRule(o.crossingPoints);
      sum = evaluatePairs([&k](const mdem::Segment& a, const mdem::Segment& b) { return mdem::anisotropicVdw(k, a, b); },
                          pairs, o.repeat, &out);
    }
    std::cout << fmt::format("{} pairs x {} evaluations, {} path, {} points, aligned window {} degrees, crossing rule {} "
                             "points: energy sum {:.10g} zJ\n",
                             pairs.size(), o.repeat, o.path, o.points, std::max(0.0, o.alignedWindow), o.crossingPoints,
                             sum / o.repeat);
    return 0;
  }
  const double scale = std::abs(potential.wellDepthPerLength()) * 2.0 * la;
  std::vector<mdem::ContactPairResult> ref;
  const mdem::AnisotropicVdwKernel reference(potential, lb, 64);
  auto tableKernel = [](const mdem::AnisotropicVdwKernel& k) {
    return [&k](const mdem::Segment& a, const mdem::Segment& b) { return mdem::anisotropicVdw(k, a, b); };
  };
  evaluatePairs(tableKernel(reference), pairs, 1, &ref);
  long interacting = 0, farPairs = 0;
  for (const auto& r : ref) interacting += r.energy != 0.0;
  const double farCut = potential.cutoffDistance() + 3.0 * potential.gridStep();  // the kernel's early out
  for (const auto& [a, b] : pairs) {
    double sa, sb;
    mdem::closestPoints(a, b, &sa, &sb);
    farPairs += (a.centre + sa * a.axis - b.centre - sb * b.axis).norm() >= farCut;
  }
  std::cout << fmt::format(
      "Anisotropic contact kernel over the {} list pairs of the {}-element network ({} with nonzero energy, {} "
      "skipped by the far-pair early out);\n"
      "errors against the 64-point rule: energy max in units of |Phi_eq| 2 la = {:.4g} zJ, energy sum |dE|/sum |E|,\n"
      "force/torque max |dF| over max |F|; ns per pair: best of 5 (wall time, noisy: callgrind figures in "
      "docs/benchmarks.md)\n",
      pairs.size(), s.bodies.size(), interacting, farPairs, scale);
  printAngleClassRows(potential, pairs, ref, scale, lb);
  printWorstPairs(potential, pairs, ref, scale, lb, s.contacts.vdw.quadraturePoints);
  printCrossingCorrugation(potential, la, lb);
  std::cout << "path   points  tolerance  sample_worst  energy_max   energy_sum   force_max    ns/pair\n";
  const double per = std::max(0.2, o.seconds / 10);
  for (int n : {2, 3, 4, 5, 6, 8, 10, 12, 16}) {
    const mdem::AnisotropicVdwKernel k(potential, lb, n);
    const KernelError e = kernelError(tableKernel(k), pairs, ref, scale, per);
    std::cout << fmt::format("table  {:6d}  {:>9}  {:>12}  {:10.3g}  {:11.3g}  {:10.3g}  {:8.1f}\n", n, "-", "-",
                             e.energyMax, e.energySum, e.forceMax, e.nsPerPair)
              << std::flush;
  }
  for (int n : {8}) {
    const KernelError e = kernelError(line(mdem::gaussLegendre(n)), pairs, ref, scale, per);
    std::cout << fmt::format("line   {:6d}  {:>9}  {:>12}  {:10.3g}  {:11.3g}  {:10.3g}  {:8.1f}\n", n, "-", "-",
                             e.energyMax, e.energySum, e.forceMax, e.nsPerPair)
              << std::flush;
  }
  for (int n : {10, 12, 16}) {
    mdem::AnisotropicVdwKernel k(potential, lb, 8);
    k.enableCrossingRule(n);
    const KernelError e = kernelError(tableKernel(k), pairs, ref, scale, per);
    std::cout << fmt::format("cross  {:>6}  {:>9}  {:>12}  {:10.3g}  {:11.3g}  {:10.3g}  {:8.1f}\n", fmt::format("8+{}", n), "-",
                             "-", e.energyMax, e.energySum, e.forceMax, e.nsPerPair)
              << std::flush;
  }
  printAlignedWindowRows(potential, pairs, ref, scale, la, lb, per);
  for (double tol : {3e-2, 1e-2, 3e-3, 1e-3, 1e-4}) {
    const mdem::QuadratureChoice c = mdem::quadraturePointsForTolerance(potential, la, lb, tol);
    const mdem::AnisotropicVdwKernel k(potential, lb, c.points);
    const KernelError e = kernelError(tableKernel(k), pairs, ref, scale, per);
    std::cout << fmt::format("table  {:6d}  {:9.0e}  {:12.3g}  {:10.3g}  {:11.3g}  {:10.3g}  {:8.1f}\n", c.points,
                             tol, c.worstError, e.energyMax, e.energySum, e.forceMax, e.nsPerPair)
              << std::flush;
  }
  return 0;
}

}  // namespace mesochain::app
