#include "mdem/contacts/contact_dashpot.hpp"

#include <algorithm>
#include <cmath>

namespace mesochain::mdem {

double wallGap(const Segment& a, const Segment& b, double ra, double rb) {
  double sa, sb;
  closestPoints(a, b, &sa, &sb);
  return (a.centre + sa * a.axis - b.centre - sb * b.axis).norm() - ra - rb;
}

ContactPairResult contactDashpot(const ContactDampingSpec& spec, const Segment& a, const Segment& b,
                                 double ra, double rb, const Vec3& va, const Vec3& wa, const Vec3& vb,
                                 const Vec3& wb) {
  const DashpotContact k = dashpotContact(spec, a, b, ra, rb);
  if (k.weightedLength <= 0.0) return {};
  return dashpotForces(spec, k, a, b, va, wa, vb, wb);
}

}  // namespace mesochain::mdem
