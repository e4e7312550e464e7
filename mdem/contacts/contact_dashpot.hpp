#pragma once
// Viscous dashpot in parallel with a contact between two tube elements ("contact_damping").
//
// The dashpot acts at the contact point c (midpoint of the closest points of the two axis
// segments) on the relative velocity of the two elements there,
//   v_rel = (v_b + w_b x (c - x_b)) - (v_a + w_a x (c - x_a)),
//   F_a = gamma lambda s v_rel,  F_b = -F_a,
//   M_a = (c - x_a) x F_a + gamma_r lambda s (w_b - w_a),  M_b = (c - x_b) x F_b - gamma_r lambda s (w_b - w_a),
// with lambda the contact length (overlap of the two segments projected on each other's axis,
// averaged, plus (R_a + R_b)|sin(angle)| for a crossing) and s a smooth weight of the wall gap
// (1 below fullGap, 0 beyond cutoffGap). Forces are equal and opposite and act at one point, so
// linear and angular momentum are conserved; the power is -gamma lambda s |v_rel|^2 - ... <= 0.
// For aligned tubes in contact the friction force per unit length is exactly gamma v.
#include <algorithm>
#include <cmath>

#include "mdem/contacts/contact_spec.hpp"
#include "mdem/contacts/vdw_contact.hpp"

namespace mesochain::mdem {

// Closest points of two segments from c = t_a.t_b, e = t_a.r, f = t_b.r (r = x_a - x_b) and
// the half lengths: parameters sa in [-la, la], sb in [-lb, lb].
inline void closestPointParameters(double c, double e, double f, double la, double lb, double* sa, double* sb) {
  double s;
  if (1.0 - c * c > 1e-10) {
    s = std::clamp((c * f - e) / (1.0 - c * c), -la, la);
  } else {
    // Parallel: the middle of the overlap of b's projection on a's axis with [-la, la].
    const double p0 = -e - lb, p1 = -e + lb;
    s = std::clamp(0.5 * (std::max(p0, -la) + std::min(p1, la)), -la, la);
  }
  double u = std::clamp(f + s * c, -lb, lb);
  s = std::clamp(u * c - e, -la, la);
  u = std::clamp(f + s * c, -lb, lb);
  *sa = s, *sb = u;
}
// Closest points of two segments: parameters sa in [-la, la], sb in [-lb, lb].
inline void closestPoints(const Segment& a, const Segment& b, double* sa, double* sb) {
  const Vec3 r = a.centre - b.centre;
  closestPointParameters(a.axis.dot(b.axis), a.axis.dot(r), b.axis.dot(r), a.halfLength, b.halfLength, sa, sb);
}
// Wall-to-wall gap of two tubes of radii ra, rb along the segments: the distance of the closest
// points of the axes minus both radii (negative: the walls interpenetrate).
double wallGap(const Segment& a, const Segment& b, double ra, double rb);

// Length of [m - h, m + h] (a segment projected on an axis: centre m, half length h) inside
// [-l, l].
inline double projectedOverlap(double m, double h, double l) {
  return std::max(0.0, std::min(m + h, l) - std::max(m - h, -l));
}

// Contact length lambda (see above).
inline double contactLength(const Segment& a, const Segment& b, double ra, double rb) {
  auto overlap = [](const Segment& p, const Segment& q) {  // q projected on p's axis
    return projectedOverlap((q.centre - p.centre).dot(p.axis), q.halfLength * std::abs(q.axis.dot(p.axis)), p.halfLength);
  };
  const double sine = a.axis.cross(b.axis).norm();
  return 0.5 * (overlap(a, b) + overlap(b, a)) + (ra + rb) * sine;
}

// The weight s of a wall gap below the cut-off: 1 up to fullGap, a smoothstep down to 0 at cutoffGap.
inline double gapWeight(const ContactDampingSpec& spec, double gap) {
  if (gap <= spec.fullGap) return 1.0;
  const double x = (gap - spec.fullGap) / (spec.cutoffGap - spec.fullGap);
  return 1.0 - x * x * (3.0 - 2.0 * x);
}

// Where and how strongly the dashpot acts: the contact point c and lambda s (zero beyond the
// cut-off gap: then the pair has no dashpot and its velocities need not be formed).
struct DashpotContact {
  Vec3 point = Vec3::Zero();
  double weightedLength = 0.0;  // lambda s, nm
};
inline DashpotContact dashpotContact(const ContactDampingSpec& spec, const Segment& a, const Segment& b, double ra,
                                     double rb) {
  DashpotContact k;
  double sa, sb;
  closestPoints(a, b, &sa, &sb);
  const Vec3 pa = a.centre + sa * a.axis, pb = b.centre + sb * b.axis;
  const double gap = (pa - pb).norm() - ra - rb;
  if (gap >= spec.cutoffGap) return k;
  k.weightedLength = std::max(0.0, gapWeight(spec, gap) * contactLength(a, b, ra, rb));
  k.point = 0.5 * (pa + pb);
  return k;
}
// The forces and torques of a contact with weightedLength > 0.
inline ContactPairResult dashpotForces(const ContactDampingSpec& spec, const DashpotContact& k, const Segment& a,
                                       const Segment& b, const Vec3& va, const Vec3& wa, const Vec3& vb,
                                       const Vec3& wb) {
  ContactPairResult r;
  const double lw = k.weightedLength;
  const Vec3& c = k.point;
  const Vec3 vrel = (vb + wb.cross(c - b.centre)) - (va + wa.cross(c - a.centre));
  r.forceA = spec.translational * lw * vrel;
  r.forceB = -r.forceA;
  const Vec3 mr = spec.rotational * lw * (wb - wa);
  r.torqueA = (c - a.centre).cross(r.forceA) + mr;
  r.torqueB = (c - b.centre).cross(r.forceB) - mr;
  return r;
}

// One listed pair in one pass, the kernel of the contact_damping effect: dashpotContact then
// dashpotForces, with the closest points' dot products reused by the contact length (a's view
// of b's centre is -e, b's of a's is f, |cos| is |c|: the same products in the same order). The
// operations are those of the two functions, so the results are the same bits (test
// MdemContactDashpot.OnePassKernelEqualsTheTwoStepsBitForBit). Returns false, leaving `out`,
// when the pair has no dashpot (wall gap at or beyond the cut-off).
inline bool dashpotPair(const ContactDampingSpec& spec, const Segment& a, const Segment& b, double ra, double rb,
                        const Vec3& va, const Vec3& wa, const Vec3& vb, const Vec3& wb, ContactPairResult* out) {
  const Vec3 r = a.centre - b.centre;
  const double c = a.axis.dot(b.axis), e = a.axis.dot(r), f = b.axis.dot(r);
  const double la = a.halfLength, lb = b.halfLength;
  double s, u;
  closestPointParameters(c, e, f, la, lb, &s, &u);
  const Vec3 pa = a.centre + s * a.axis, pb = b.centre + u * b.axis;
  const double gap = (pa - pb).norm() - ra - rb;
  if (gap >= spec.cutoffGap) return false;
  const double cosine = std::abs(c);  // contactLength
  const double length = 0.5 * (projectedOverlap(-e, lb * cosine, la) + projectedOverlap(f, la * cosine, lb)) +
                        (ra + rb) * a.axis.cross(b.axis).norm();
  const double lw = std::max(0.0, gapWeight(spec, gap) * length);
  if (lw <= 0.0) return false;
  *out = dashpotForces(spec, {0.5 * (pa + pb), lw}, a, b, va, wa, vb, wb);
  return true;
}

// Both in one call.
ContactPairResult contactDashpot(const ContactDampingSpec& spec, const Segment& a, const Segment& b,
                                 double radiusA, double radiusB, const Vec3& va, const Vec3& wa,
                                 const Vec3& vb, const Vec3& wb);

}  // namespace mesochain::mdem
