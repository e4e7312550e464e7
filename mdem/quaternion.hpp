#pragma once
// Unit quaternions for rigid-body orientations: q = (w, x, y, z) with w the scalar part.
// Convention: q rotates body-frame vectors into the world frame (active rotation),
// v_world = q v_body q*. Composition q_a ⊗ q_b applies q_b first.
// The rotation-vector maps (exp/log) and the SO(3) left Jacobian used by the bond follow the
// standard Lie-group formulas (e.g. Sola, Deray & Atchuthan, "A micro Lie theory", 2018).
#include <cmath>

#include <Eigen/Dense>

namespace mesochain::mdem {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Quat {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

  Vec3 vec() const { return {x, y, z}; }
  double norm() const { return std::sqrt(w * w + x * x + y * y + z * z); }
};

inline Quat conj(const Quat& q) { return {q.w, -q.x, -q.y, -q.z}; }

// Always inlined, like rotate(): called several times per element per step, where a call (its
// arguments and result through memory) costs about a third of the arithmetic.
[[gnu::always_inline]] inline Quat operator*(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

inline Quat normalized(const Quat& q) {
  const double n = q.norm();
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// v_world = R(q) v.  Uses v' = v + 2 w (u x v) + 2 u x (u x v), u = vector part.
[[gnu::always_inline]] inline Vec3 rotate(const Quat& q, const Vec3& v) {
  const Vec3 u = q.vec();
  const Vec3 t = 2.0 * u.cross(v);
  return v + q.w * t + u.cross(t);
}

// R(q)^T v.
[[gnu::always_inline]] inline Vec3 rotateInverse(const Quat& q, const Vec3& v) { return rotate(conj(q), v); }

// R(q) of a unit quaternion (the standard quadratic form; equals rotate() column by column).
inline Mat3 toMatrix(const Quat& q) {
  const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  Mat3 r;
  r << 1.0 - 2.0 * (yy + zz), 2.0 * (xy - wz), 2.0 * (xz + wy),  //
      2.0 * (xy + wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz - wx),   //
      2.0 * (xz - wy), 2.0 * (yz + wx), 1.0 - 2.0 * (xx + yy);
  return r;
}

// Quaternion of a proper rotation matrix (Shepperd's method: largest pivot for stability).
Quat fromMatrix(const Mat3& r);

// exp: rotation vector (axis * angle, radians) -> unit quaternion.
inline Quat expMap(const Vec3& theta) {
  const double phi = theta.norm();
  const double half = 0.5 * phi;
  // sin(phi/2)/phi, with its Taylor series near zero.
  const double s = phi < 1e-6 ? 0.5 - phi * phi / 48.0 : std::sin(half) / phi;
  return {std::cos(half), s * theta.x(), s * theta.y(), s * theta.z()};
}

// Rotation about a unit axis by `angle`.
inline Quat axisAngle(const Vec3& unitAxis, double angle) { return expMap(angle * unitAxis); }

// The smallest rotation taking unit vector u to unit vector v (about u x v; identity when they
// are parallel).
inline Quat minimalRotation(const Vec3& u, const Vec3& v) {
  const Vec3 c = u.cross(v);
  const double s = c.norm();
  if (s < 1e-15) return Quat{};
  return axisAngle(c / s, std::atan2(s, u.dot(v)));
}

// Principal log: rotation vector with angle in [0, pi].
Vec3 logMap(const Quat& q);

// Log on a tracked branch: among all rotation vectors (phi + 2 pi k) n of the rotation q, the one
// nearest to `previous`. Lets a relative rotation wind through any number of turns
// continuously (the principal log would wrap at pi). Singular only when |result| = 2 pi k, k != 0.
Vec3 trackedLog(const Quat& q, const Vec3& previous);

// Cross-product matrix [v]x with [v]x u = v x u.
inline Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// J_l^{-T}(theta) m = m + 1/2 theta x m + beta theta x (theta x m) with
// beta = 1/phi^2 - cot(phi/2)/(2 phi): the transpose of the inverse left Jacobian of SO(3).
// If R -> exp([eps]) R, then log(R) -> theta + J_l^{-1}(theta) eps to first order.
inline double inverseLeftJacobianBeta(double phi2) {
  if (phi2 < 1e-8) return 1.0 / 12.0 + phi2 / 720.0;
  const double phi = std::sqrt(phi2);
  return 1.0 / phi2 - 1.0 / (2.0 * phi * std::tan(0.5 * phi));
}
inline Vec3 inverseLeftJacobianTransposeApply(const Vec3& theta, const Vec3& m) {
  const double beta = inverseLeftJacobianBeta(theta.squaredNorm());
  const Vec3 tm = theta.cross(m);
  return m + 0.5 * tm + beta * theta.cross(tm);
}

// A tracked log together with the coefficient beta(|theta|) of J_l^{-T}(theta) (above), for
// the bond kernel: theta = trackedLog(q, previous) and J_l^{-T}(theta) m = m + 1/2 theta x m +
// beta theta x (theta x m).
struct RotationVector {
  Vec3 theta;
  double beta;
};

// General case (any angle, any number of turns): trackedLog and beta in closed form.
RotationVector trackedLogWithJacobianGeneral(const Quat& q, const Vec3& previous);

// The same, with a branch free of transcendental functions for the common case of a small
// relative rotation near the principal branch: with p = +-q (p.w >= 0), t = |p.vec| / p.w =
// tan(phi/2) and u = t^2 <= 1e-2 (phi <= 0.199 rad),
//   atan(t)/t = P(u) = 1 - u Q(u),  Q(u) = sum_{k=0..6} (-u)^k / (2k + 3)   (truncation of P
//   < u^8 / 17 = 6e-18 relative),   theta = (2 / p.w) P(u) p.vec,
// and, since phi = 2 t P and cot(phi/2) = 1/t exactly,
//   beta = 1/phi^2 - cot(phi/2)/(2 phi) = (1 - P) / (4 u P^2) = Q / (4 P^2)
// with no cancellation (-> 1/12 at u = 0). Q is evaluated by Estrin's scheme and beta does not
// wait for theta: the chain is short. The principal branch is the tracked one when
// |previous| + phi < pi, ensured by |previous|^2 < 8 (|previous| < 2.83). Otherwise the
// general case.
// The series branch from sign (of q.w), w = sign q.w and s2 = |q.vec|^2: theta = scale q.vec
// and beta (also the bond kernel's per lane, parallel_bond.cpp).
struct LogSeries {
  double scale, beta;
};
[[gnu::always_inline]] inline LogSeries logSeries(double sign, double w, double s2) {
  const double invW = 1.0 / w;
  const double u = s2 * invW * invW;
  const double u2 = u * u, u4 = u2 * u2;
  const double tail = (1.0 / 3 - u * (1.0 / 5)) + u2 * (1.0 / 7 - u * (1.0 / 9)) +
                      u4 * ((1.0 / 11 - u * (1.0 / 13)) + u2 * (1.0 / 15));  // Q(u)
  const double atanRatio = 1.0 - u * tail;                                    // P(u)
  return {2.0 * sign * invW * atanRatio, 0.25 * tail / (atanRatio * atanRatio)};
}
// Whether the series branch holds (see above).
[[gnu::always_inline]] inline bool logSeriesHolds(double w, double s2, const Vec3& previous) {
  return s2 <= 1e-2 * w * w && previous.squaredNorm() < 8.0;
}
inline RotationVector trackedLogWithJacobian(const Quat& q, const Vec3& previous) {
  const double sign = q.w < 0.0 ? -1.0 : 1.0;
  const double w = sign * q.w;
  const double s2 = q.x * q.x + q.y * q.y + q.z * q.z;
  if (logSeriesHolds(w, s2, previous)) {
    const LogSeries l = logSeries(sign, w, s2);
    RotationVector r;
    r.theta = {l.scale * q.x, l.scale * q.y, l.scale * q.z};
    r.beta = l.beta;
    return r;
  }
  return trackedLogWithJacobianGeneral(q, previous);
}

// J_l^{-T}(theta) m with beta from trackedLogWithJacobian.
inline Vec3 inverseLeftJacobianTransposeApply(const RotationVector& r, const Vec3& m) {
  const Vec3 tm = r.theta.cross(m);
  return m + 0.5 * tm + r.beta * r.theta.cross(tm);
}

}  // namespace mesochain::mdem
