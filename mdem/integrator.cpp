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
// rotateAboutCayley for two elements at once, lane k = element k: each lane does exactly the
// operations of the scalar version in the same order (so each element's result is bit for bit
// the same), written as loops over the lanes so that the compiler packs them into one vector
// operation each (one division for both elements). Two independent chains of dependent
// divisions then overlap instead of waiting on each other.
template <int I, int Next>
inline void rotateAboutCayleyPair(double (&q)[4][2], double (&pi)[3][2], double (&a)[2], const double (&nextCoefficient)[2]) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  double inv[2], nj[2], nk[2];
  for (int k = 0; k < 2; ++k) {
    const double a2 = a[k] * a[k];
    inv[k] = 1.0 / (1.0 + a2);
    const double oneMinus = 1.0 - a2, twoA = 2.0 * a[k];
    nj[k] = oneMinus * pi[J][k] + twoA * pi[K][k];
    nk[k] = oneMinus * pi[K][k] - twoA * pi[J][k];
  }
  for (int k = 0; k < 2; ++k) {
    pi[J][k] = nj[k] * inv[k];
    pi[K][k] = nk[k] * inv[k];
    const double w = q[0][k], qi = q[1 + I][k], qj = q[1 + J][k], qk = q[1 + K][k];
    q[0][k] = w - a[k] * qi;
    q[1 + I][k] = qi + a[k] * w;
    q[1 + J][k] = qj + a[k] * qk;
    q[1 + K][k] = qk - a[k] * qj;
  }
  for (int k = 0; k < 2; ++k) {
    if constexpr (Next == J) a[k] = (nextCoefficient[k] * nj[k]) * inv[k];
    if constexpr (Next == K) a[k] = (nextCoefficient[k] * nk[k]) * inv[k];
  }
}

// freeRotorStepCayley of two elements (quat0, pi0, inverseInertia0 and quat1, ...), bit for bit.
inline void freeRotorStepCayleyPair(Quat& quat0, Vec3& pi0, const Vec3& inverseInertia0, Quat& quat1, Vec3& pi1,
                                    const Vec3& inverseInertia1, double h) {
  double q[4][2] = {{quat0.w, quat1.w}, {quat0.x, quat1.x}, {quat0.y, quat1.y}, {quat0.z, quat1.z}};
  double pi[3][2] = {{pi0[0], pi1[0]}, {pi0[1], pi1[1]}, {pi0[2], pi1[2]}};
  const double kx[2] = {0.25 * h * inverseInertia0[0], 0.25 * h * inverseInertia1[0]};
  const double ky[2] = {0.25 * h * inverseInertia0[1], 0.25 * h * inverseInertia1[1]};
  const double kz[2] = {0.5 * h * inverseInertia0[2], 0.5 * h * inverseInertia1[2]};
  const double none[2] = {0.0, 0.0};
  double a[2] = {kx[0] * pi[0][0], kx[1] * pi[0][1]};
  rotateAboutCayleyPair<0, 1>(q, pi, a, ky);
  rotateAboutCayleyPair<1, 2>(q, pi, a, kz);
  rotateAboutCayleyPair<2, 1>(q, pi, a, ky);
  rotateAboutCayleyPair<1, 0>(q, pi, a, kx);
  rotateAboutCayleyPair<0, -1>(q, pi, a, none);
  double inv[2];
  for (int k = 0; k < 2; ++k)
    inv[k] = 1.0 / std::sqrt(q[0][k] * q[0][k] + q[1][k] * q[1][k] + q[2][k] * q[2][k] + q[3][k] * q[3][k]);
  quat0 = {q[0][0] * inv[0], q[1][0] * inv[0], q[2][0] * inv[0], q[3][0] * inv[0]};
  quat1 = {q[0][1] * inv[1], q[1][1] * inv[1], q[2][1] * inv[1], q[3][1] * inv[1]};
  pi0 = Vec3(pi[0][0], pi[1][0], pi[2][0]);
  pi1 = Vec3(pi[0][1], pi[1][1], pi[2][1]);
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

void driftFreePair(Bodies& s, int i, double h) {
  const int j = i + 1;
  s.position[i] += h * s.velocity[i];
  s.position[j] += h * s.velocity[j];
  const Vec3 inverseInertiaI = s.inertia[i].cwiseInverse(), inverseInertiaJ = s.inertia[j].cwiseInverse();
  Quat &qi = s.orientation[i], &qj = s.orientation[j];
  Vec3 &pi = s.angularMomentumBody[i], &pj = s.angularMomentumBody[j];
  const Vec3 w0i = rotate(qi, pi.cwiseProduct(inverseInertiaI));
  const Vec3 w0j = rotate(qj, pj.cwiseProduct(inverseInertiaJ));
  freeRotorStepCayleyPair(qi, pi, inverseInertiaI, qj, pj, inverseInertiaJ, h);
  s.accumulatedRotation[i] += 0.5 * h * (w0i + rotate(qi, pi.cwiseProduct(inverseInertiaI)));
  s.accumulatedRotation[j] += 0.5 * h * (w0j + rotate(qj, pj.cwiseProduct(inverseInertiaJ)));
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
