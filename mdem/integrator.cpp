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
// tan(phi/2) of the rotation angle phi = 2 atan(a); cos phi, sin phi = (1 - a^2, 2a) / (1 + a^2).
// q is left unnormalised: q (x) (1, a e_I) = |(1, a)| q (x) (cos(phi/2), sin(phi/2) e_I).
// Written for latency (the five sub-rotations are one dependent chain): the rotated pi_J, pi_K
// are numerators times 1/(1 + a^2), so that one multiplication follows the division, and the
// next sub-rotation's parameter, nextCoefficient * pi_Next, is formed from its numerator in
// parallel with the division. Returns it (0 if none). (It differs from nextCoefficient times
// the stored pi_Next by rounding only: time reversal still holds to round-off.)
template <int I, int Next>
inline double rotateAboutCayley(double (&q)[4], Vec3& pi, double a, double nextCoefficient) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  const double a2 = a * a;
  const double inv = 1.0 / (1.0 + a2);
  const double oneMinus = 1.0 - a2, twoA = 2.0 * a;
  const double nj = oneMinus * pi[J] + twoA * pi[K];
  const double nk = oneMinus * pi[K] - twoA * pi[J];
  pi[J] = nj * inv;
  pi[K] = nk * inv;
  // Quaternion components: q[0] = w, q[1 + axis] = vector part.
  const double w = q[0], qi = q[1 + I], qj = q[1 + J], qk = q[1 + K];
  q[0] = w - a * qi;
  q[1 + I] = qi + a * w;
  q[1 + J] = qj + a * qk;
  q[1 + K] = qk - a * qj;
  if constexpr (Next == J) return (nextCoefficient * nj) * inv;
  if constexpr (Next == K) return (nextCoefficient * nk) * inv;
  return 0.0;
}

// The Cayley free-rotor step with the inverse principal moments given.
inline void freeRotorStepCayley(Quat& quat, Vec3& pi, const Vec3& inverseInertia, double h) {
  double q[4] = {quat.w, quat.x, quat.y, quat.z};
  // a = (tau / 2) pi_i / I_i with tau = h/2 (x and y) or h (z).
  const double kx = 0.25 * h * inverseInertia[0], ky = 0.25 * h * inverseInertia[1];
  const double kz = 0.5 * h * inverseInertia[2];
  double a = kx * pi[0];
  a = rotateAboutCayley<0, 1>(q, pi, a, ky);
  a = rotateAboutCayley<1, 2>(q, pi, a, kz);
  a = rotateAboutCayley<2, 1>(q, pi, a, ky);
  a = rotateAboutCayley<1, 0>(q, pi, a, kx);
  rotateAboutCayley<0, -1>(q, pi, a, 0.0);
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
