#include "mdem/contacts/contact_dashpot.hpp"

#include <algorithm>
#include <cmath>

namespace mesochain::mdem {

void closestPoints(const Segment& a, const Segment& b, double* sa, double* sb) {
  const Vec3 r = a.centre - b.centre;
  const double c = a.axis.dot(b.axis), e = a.axis.dot(r), f = b.axis.dot(r);
  const double la = a.halfLength, lb = b.halfLength;
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

double contactLength(const Segment& a, const Segment& b, double ra, double rb) {
  auto overlap = [](const Segment& p, const Segment& q) {
    // Projection of q on p's axis, overlapped with [-lp, lp].
    const double m = (q.centre - p.centre).dot(p.axis), h = q.halfLength * std::abs(q.axis.dot(p.axis));
    return std::max(0.0, std::min(m + h, p.halfLength) - std::max(m - h, -p.halfLength));
  };
  const double sine = a.axis.cross(b.axis).norm();
  return 0.5 * (overlap(a, b) + overlap(b, a)) + (ra + rb) * sine;
}

double wallGap(const Segment& a, const Segment& b, double ra, double rb) {
  double sa, sb;
  closestPoints(a, b, &sa, &sb);
  return (a.centre + sa * a.axis - b.centre - sb * b.axis).norm() - ra - rb;
}

DashpotContact dashpotContact(const ContactDampingSpec& spec, const Segment& a, const Segment& b, double ra,
                              double rb) {
  DashpotContact k;
  double sa, sb;
  closestPoints(a, b, &sa, &sb);
  const Vec3 pa = a.centre + sa * a.axis, pb = b.centre + sb * b.axis;
  const double gap = (pa - pb).norm() - ra - rb;
  if (gap >= spec.cutoffGap) return k;
  double weight = 1.0;
  if (gap > spec.fullGap) {
    const double x = (gap - spec.fullGap) / (spec.cutoffGap - spec.fullGap);
    weight = 1.0 - x * x * (3.0 - 2.0 * x);
  }
  k.weightedLength = std::max(0.0, weight * contactLength(a, b, ra, rb));
  k.point = 0.5 * (pa + pb);
  return k;
}

ContactPairResult dashpotForces(const ContactDampingSpec& spec, const DashpotContact& k, const Segment& a,
                                const Segment& b, const Vec3& va, const Vec3& wa, const Vec3& vb, const Vec3& wb) {
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

ContactPairResult contactDashpot(const ContactDampingSpec& spec, const Segment& a, const Segment& b,
                                 double ra, double rb, const Vec3& va, const Vec3& wa, const Vec3& vb,
                                 const Vec3& wb) {
  const DashpotContact k = dashpotContact(spec, a, b, ra, rb);
  if (k.weightedLength <= 0.0) return {};
  return dashpotForces(spec, k, a, b, va, wa, vb, wb);
}

}  // namespace mesochain::mdem
