#pragma once
// Pair kernels of the van der Waals contact between two tube elements (cylinders), built on the
// coarse-grained tube potential (tube_potential.hpp, docs/mdem-contacts.md).
//
// Anisotropic form: each element is its axis segment; the energy is
//   E = \int_{-la}^{la} ds [H(h(s), a(s)) - H(h(s), b(s))] = \int_{-la}^{la} ds D(h(s), u0(s))
// where, for the point p(s) = x_a + s t_a, h is its distance from the axis line of b and
// [a, b] = [-lb - u0, lb - u0] the extent of segment b relative to the foot point (u0 the axial
// coordinate of p along b). The integral along b is exact (table H, or the table D of the whole
// segment, segment_line_table.hpp); along a it is a Gauss-Legendre rule. Crossed segments feel an
// aligning moment (the energy is lowest when aligned); a segment sliding along a straight chain of
// segments sees no corrugation, because the inner integrals of consecutive segments add up to the
// integral along the whole chain.
//
// A pair whose axis segments are farther apart than the cut-off d_c plus three table steps returns
// zero without quadrature: there every table cell the quadrature could touch has zero node data,
// so the early out returns exactly what the quadrature would (no jump at its boundary).
//
// Isotropic form: a central pair potential U(r) of the centre distance r, U(r) = the anisotropic
// energy of the two segments parallel and side by side at axis distance r (tabulated). No moment.
//
// Forces and torques are the exact negative gradients of these energies (world frame; a torque
// is -dE/dphi for a rotation q -> exp(phi) q of the element).
#include <memory>
#include <vector>

#include "mdem/contacts/aligned_pair_table.hpp"
#include "mdem/contacts/quadrature.hpp"
#include "mdem/contacts/segment_line_table.hpp"
#include "mdem/contacts/tube_potential.hpp"
#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

struct Segment {
  Vec3 centre;
  Vec3 axis;  // unit
  double halfLength = 0.0;
};

// Early-out distance of the axis segments of the anisotropic kernels: d_c + 3 table steps (d_c the
// axis distance at which the pair potential vanishes, `gridStep` its tables' step). Beyond it
// every kernel returns exactly zero; the neighbour list uses it as its axis range.
inline double segmentCutDistance(double cutoffDistance, double gridStep) { return cutoffDistance + 3.0 * gridStep; }

struct ContactPairResult {
  double energy = 0.0;
  Vec3 forceA = Vec3::Zero(), torqueA = Vec3::Zero();
  Vec3 forceB = Vec3::Zero(), torqueB = Vec3::Zero();
};

// Anisotropic kernel; the quadrature runs along a (`rule` on [-1, 1]); three lookups of H per point.
ContactPairResult anisotropicVdw(const TubePairPotential& potential, const QuadratureRule& rule,
                                 const Segment& a, const Segment& b);

// Everything the anisotropic kernel needs for one ordered pair of element kinds (quadrature side a
// of half-length la, partner b of half-length lb), built once per scene (~0.2 s): the table D of
// b's whole segment (one lookup per quadrature point) and the rule along a.
struct AnisotropicVdwKernel {
  AnisotropicVdwKernel(const TubePairPotential& potential, double halfLengthB, int quadraturePoints);
  // The rule chosen from `quadratureTolerance` for quadrature elements of half-length la
  // (quadraturePointsForTolerance below, on this kernel's table).
  AnisotropicVdwKernel(const TubePairPotential& potential, double halfLengthA, double halfLengthB,
                       double quadratureTolerance);
  const TubePairPotential* potential;
  SegmentLineTable table;
  QuadratureRule rule;
  double sampledError = 0.0;  // with a tolerance: the chosen rule's worst sampled error

  // Nearly parallel pairs (aligned_pair_table.hpp, docs/mdem-contacts.md "Nearly parallel pairs"):
  // for quadrature elements of half-length la, pairs within `windowDegrees` of parallel use the
  // tilt expansion of the parallel tables, blended smoothly with the rule in the angle (weight 1
  // below half the window, 0 beyond it; forces and torques include the weight's gradient). The
  // window is narrowed to la window <= 0.02 nm (1.15 degrees for 2-nm elements). 0 switches it off.
  void enableAlignedPath(double halfLengthA, double windowDegrees);
  struct AlignedWindow {
    double sine2Full = 0.0, sine2Zero = 0.0;  // sin^2 of the angle: weight 1 below, 0 above
  };
  AlignedWindow window;
  std::shared_ptr<const AlignedPairTable> aligned;  // null: off

  // Crossing pairs (docs/benchmarks.md, "The quadrature points and the stress-strain curve"):
  // beyond kCrossingRampDegrees[1] the pair uses `crossingRule` (`points` Gauss points) instead
  // of `rule`; below kCrossingRampDegrees[0] the rule (or the aligned path) alone; between, the
  // two blended with the same C2 ramp in sin^2 of the angle as the aligned path (forces and
  // torques include the weight's gradient). 0 points switches it off. On the table path (partners
  // of the table's half-length, as the contact effect's kernels always have).
  void enableCrossingRule(int points);
  QuadratureRule crossingRule;  // empty: off
  AlignedWindow crossingWindow;  // sin^2 bounds: the rule alone below sine2Full, crossingRule alone above sine2Zero
};
// The ramp: wide, because the blend's torque is the gradient of the two rules' energy difference
// over it; from 20 degrees, because the corrugation grows with the angle (0.02 zJ at 20 degrees,
// 0.03 at 45, 0.47 at 90 with 8 points) and nearly parallel pairs are accurate with the rule.
inline constexpr double kCrossingRampDegrees[2] = {20.0, 40.0};

// The aligned path's weight of a pair: 1 on the tables alone, 0 on the rule alone (and when off).
double alignedWeight(const AnisotropicVdwKernel& kernel, const Segment& a, const Segment& b);

// The same energy as the kernel above with the same rule (to round-off when lb is a whole number
// of table steps); a b of another half-length than the kernel's table falls back to it.
ContactPairResult anisotropicVdw(const AnisotropicVdwKernel& kernel, const Segment& a, const Segment& b);

// The number of Gauss points along a chosen once per pair of element kinds from a tolerance (so a
// pair never changes its rule between steps and the energy stays continuous): the smallest n in
// [2, 48] whose energy error against a 64-point rule, over a fixed sample of pair geometries
// (crossing angles 0-90 degrees, tilted towards each other or not, wall gaps from the repulsive
// wall to the switch, offsets along both axes up to the ends, end-on), stays below `tolerance`
// times max(|Phi_eq| 2 la, |E|): the contact energy scale (two parallel segments side by side at
// the equilibrium distance), or the pair's own energy where it is larger (deep in the wall).
// `worstError` is the largest sampled error of the chosen n in that unit (above `tolerance` when
// even 48 points miss it; tolerances below 1e-4 are refused by the scene reader). The bound is empirical:
// geometries outside the sample are checked in tests/mdem/test_vdw_table_kernel.cpp.
struct QuadratureChoice {
  int points = 0;
  double worstError = 0.0;
};
QuadratureChoice quadraturePointsForTolerance(const TubePairPotential& potential, double halfLengthA,
                                              double halfLengthB, double tolerance);
// The same on a table already built for the partner half-length.
QuadratureChoice quadraturePointsForTolerance(const TubePairPotential& potential, const SegmentLineTable& table,
                                              double halfLengthA, double tolerance);

// Isotropic kernel U(r), tabulated for one pair of element lengths.
class IsotropicVdw {
 public:
  IsotropicVdw(const TubePairPotential& potential, double halfLengthA, double halfLengthB);
  double energy(double r, double* derivative) const;
  ContactPairResult evaluate(const Vec3& centreA, const Vec3& centreB) const;
  double cutoff() const { return rMax_; }

 private:
  double step_ = 0.0, rMax_ = 0.0;
  std::vector<double> u_, du_;
};

}  // namespace mesochain::mdem
