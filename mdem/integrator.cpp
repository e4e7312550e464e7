#include "mdem/integrator.hpp"

#include <cmath>

namespace mesochain::mdem {

void kick(Bodies& s, double h) {
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) kickElement(s, i, h);
}

namespace {
// Exact sub-flow of H_axis = pi_axis^2 / (2 I_axis) over time h.
inline void rotateAboutExact(int axis, Quat& q, Vec3& pi, const Vec3& inertia, double h) {
  const double alpha = h * pi[axis] / inertia[axis];
  // One sincos of the half angle gives both rotations (pi turns by alpha, q by alpha / 2).
  const double sh = std::sin(0.5 * alpha), ch = std::cos(0.5 * alpha);
  const double c = 1.0 - 2.0 * sh * sh, s = 2.0 * sh * ch;
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  // pi <- R_axis(alpha)^T pi (components j, k turn by -alpha).
  const double pj = pi[j], pk = pi[k];
  pi[j] = c * pj + s * pk;
  pi[k] = -s * pj + c * pk;
  // q <- q (x) (cos(alpha/2), sin(alpha/2) e_axis).
  Quat r{ch, 0.0, 0.0, 0.0};
  if (axis == 0) r.x = sh;
  if (axis == 1) r.y = sh;
  if (axis == 2) r.z = sh;
  q = q * r;
}

// Rational sub-rotation about body axis I (see integrator.hpp): a = tau pi_I / (2 I_I) is
// tan(phi/2) of the rotation angle phi = 2 atan(a). halfTauInvI = tau / (2 I_I).
// q is left unnormalised: q (x) (1, a e_I) = |(1, a)| q (x) (cos(phi/2), sin(phi/2) e_I).
template <int I>
inline void rotateAboutCayley(double (&q)[4], Vec3& pi, double halfTauInvI) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  const double a = halfTauInvI * pi[I];
  const double a2 = a * a;
  const double inv = 1.0 / (1.0 + a2);
  const double c = (1.0 - a2) * inv, s = 2.0 * a * inv;
  const double pj = pi[J], pk = pi[K];
  pi[J] = c * pj + s * pk;
  pi[K] = -s * pj + c * pk;
  // Quaternion components: q[0] = w, q[1 + axis] = vector part.
  const double w = q[0], qi = q[1 + I], qj = q[1 + J], qk = q[1 + K];
  q[0] = w - a * qi;
  q[1 + I] = qi + a * w;
  q[1 + J] = qj + a * qk;
  q[1 + K] = qk - a * qj;
}

// The Cayley free-rotor step with the inverse principal moments given.
inline void freeRotorStepCayley(Quat& quat, Vec3& pi, const Vec3& inverseInertia, double h) {
  double q[4] = {quat.w, quat.x, quat.y, quat.z};
  const double quarter = 0.25 * h, half = 0.5 * h;  // tau / 2 for tau = h/2 and tau = h
  rotateAboutCayley<0>(q, pi, quarter * inverseInertia[0]);
  rotateAboutCayley<1>(q, pi, quarter * inverseInertia[1]);
  rotateAboutCayley<2>(q, pi, half * inverseInertia[2]);
  rotateAboutCayley<1>(q, pi, quarter * inverseInertia[1]);
  rotateAboutCayley<0>(q, pi, quarter * inverseInertia[0]);
  const double inv = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  quat = {q[0] * inv, q[1] * inv, q[2] * inv, q[3] * inv};
}
}  // namespace

void freeRotorStep(Quat& q, Vec3& pi, const Vec3& inertia, double h) {
  freeRotorStepCayley(q, pi, inertia.cwiseInverse(), h);
}

void freeRotorStepExact(Quat& q, Vec3& pi, const Vec3& inertia, double h) {
  rotateAboutExact(0, q, pi, inertia, 0.5 * h);
  rotateAboutExact(1, q, pi, inertia, 0.5 * h);
  rotateAboutExact(2, q, pi, inertia, h);
  rotateAboutExact(1, q, pi, inertia, 0.5 * h);
  rotateAboutExact(0, q, pi, inertia, 0.5 * h);
  q = normalized(q);
}

void driftElement(Bodies& s, int i, double h, bool kinematicRotation) {
  s.position[i] += h * s.velocity[i];
  const Vec3 inverseInertia = s.inertia[i].cwiseInverse();
  Quat& q = s.orientation[i];
  Vec3& pi = s.angularMomentumBody[i];
  const Vec3 w0 = rotate(q, pi.cwiseProduct(inverseInertia));  // omega_world before
  if (kinematicRotation) {
    q = normalized(expMap(h * w0) * q);
    s.accumulatedRotation[i] += h * w0;
  } else {
    freeRotorStepCayley(q, pi, inverseInertia, h);
    s.accumulatedRotation[i] += 0.5 * h * (w0 + rotate(q, pi.cwiseProduct(inverseInertia)));
  }
}

void drift(Bodies& s, double h, const std::vector<char>& kinematicRotation) {
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) driftElement(s, i, h, kinematicRotation[i] != 0);
}

double kineticTranslational(const Bodies& s) {
  double e = 0.0;
  for (int i = 0; i < s.size(); ++i) e += 0.5 * s.mass[i] * s.velocity[i].squaredNorm();
  return e;
}

double kineticRotational(const Bodies& s) {
  double e = 0.0;
  for (int i = 0; i < s.size(); ++i)
    e += 0.5 * s.angularMomentumBody[i].cwiseAbs2().cwiseQuotient(s.inertia[i]).sum();
  return e;
}

}  // namespace mesochain::mdem
