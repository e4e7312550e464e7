#include "mdem/quaternion.hpp"

#include <cmath>

namespace mesochain::mdem {

Quat fromMatrix(const Mat3& r) {
  const double tr = r.trace();
  Quat q;
  if (tr >= r(0, 0) && tr >= r(1, 1) && tr >= r(2, 2)) {
    const double s = 2.0 * std::sqrt(1.0 + tr);
    q = {0.25 * s, (r(2, 1) - r(1, 2)) / s, (r(0, 2) - r(2, 0)) / s, (r(1, 0) - r(0, 1)) / s};
  } else if (r(0, 0) >= r(1, 1) && r(0, 0) >= r(2, 2)) {
    const double s = 2.0 * std::sqrt(1.0 + r(0, 0) - r(1, 1) - r(2, 2));
    q = {(r(2, 1) - r(1, 2)) / s, 0.25 * s, (r(0, 1) + r(1, 0)) / s, (r(0, 2) + r(2, 0)) / s};
  } else if (r(1, 1) >= r(2, 2)) {
    const double s = 2.0 * std::sqrt(1.0 + r(1, 1) - r(0, 0) - r(2, 2));
    q = {(r(0, 2) - r(2, 0)) / s, (r(0, 1) + r(1, 0)) / s, 0.25 * s, (r(1, 2) + r(2, 1)) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + r(2, 2) - r(0, 0) - r(1, 1));
    q = {(r(1, 0) - r(0, 1)) / s, (r(0, 2) + r(2, 0)) / s, (r(1, 2) + r(2, 1)) / s, 0.25 * s};
  }
  return normalized(q);
}

Vec3 logMap(const Quat& q) {
  Quat p = q.w < 0.0 ? Quat{-q.w, -q.x, -q.y, -q.z} : q;
  const Vec3 v = p.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v / (p.w > 0.0 ? p.w : 1.0);  // small angle: theta ~ 2 v
  const double phi = 2.0 * std::atan2(s, p.w);
  return (phi / s) * v;
}

Vec3 trackedLog(const Quat& q, const Vec3& previous) {
  constexpr double kTwoPi = 6.283185307179586476925;
  const Vec3 principal = logMap(q);
  const double phi0 = principal.norm();
  Vec3 n;
  if (phi0 > 1e-9) {
    n = principal / phi0;
  } else {
    const double pn = previous.norm();
    if (pn < 1.0) return principal;  // near the identity on the principal branch
    n = previous / pn;               // identity reached after whole turns: keep the axis
  }
  // All rotation vectors of this rotation are (phi0 + 2 pi k) n; pick k nearest the previous.
  const double k = std::round((n.dot(previous) - phi0) / kTwoPi);
  return (phi0 + kTwoPi * k) * n;
}

RotationVector trackedLogWithJacobianGeneral(const Quat& q, const Vec3& previous) {
  RotationVector r;
  r.theta = trackedLog(q, previous);
  r.beta = inverseLeftJacobianBeta(r.theta.squaredNorm());
  return r;
}

}  // namespace mesochain::mdem
