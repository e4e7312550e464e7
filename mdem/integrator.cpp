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
// parallel with the division; a becomes it (0 if none). (It differs from nextCoefficient times
// the stored pi_Next by rounding only: time reversal still holds to round-off.)
// N elements at once, lane k = element k, each statement a loop over the lanes: every lane does
// the same operations in the same order whatever N is (so an element's result does not depend
// on its partners), and for N = 2 the compiler packs each loop into one vector operation (one
// division for both elements), so that two chains of dependent divisions overlap.
template <int N>
struct RotorLanes {
  double q[4][N];   // q[0] = w, q[1 + axis] = vector part
  double pi[3][N];
  double a[N];
};

template <int I, int Next, int N>
[[gnu::always_inline]] inline void rotateAboutCayley(RotorLanes<N>& r, const double (&nextCoefficient)[N]) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  double inv[N], nj[N], nk[N];
  for (int k = 0; k < N; ++k) {
    const double a2 = r.a[k] * r.a[k];
    inv[k] = 1.0 / (1.0 + a2);
    const double oneMinus = 1.0 - a2, twoA = 2.0 * r.a[k];
    nj[k] = oneMinus * r.pi[J][k] + twoA * r.pi[K][k];
    nk[k] = oneMinus * r.pi[K][k] - twoA * r.pi[J][k];
  }
  for (int k = 0; k < N; ++k) {
    r.pi[J][k] = nj[k] * inv[k];
    r.pi[K][k] = nk[k] * inv[k];
    const double a = r.a[k], w = r.q[0][k], qi = r.q[1 + I][k], qj = r.q[1 + J][k], qk = r.q[1 + K][k];
    r.q[0][k] = w - a * qi;
    r.q[1 + I][k] = qi + a * w;
    r.q[1 + J][k] = qj + a * qk;
    r.q[1 + K][k] = qk - a * qj;
  }
  for (int k = 0; k < N; ++k) {
    if constexpr (Next == J) r.a[k] = (nextCoefficient[k] * nj[k]) * inv[k];
    if constexpr (Next == K) r.a[k] = (nextCoefficient[k] * nk[k]) * inv[k];
    if constexpr (Next != J && Next != K) r.a[k] = 0.0;
  }
}

// The Cayley free-rotor step of the N elements loaded into r (q then normalised), with
// k_x, k_y, k_z = (h/4, h/4, h/2) times each element's inverse principal moments: the parameter
// of a sub-rotation is (tau / 2) pi_i / I_i with tau = h/2 (x and y) or h (z).
template <int N>
[[gnu::always_inline]] inline void freeRotorStepCayley(RotorLanes<N>& r, const double (&kx)[N], const double (&ky)[N],
                                                       const double (&kz)[N]) {
  const double none[N] = {};
  for (int k = 0; k < N; ++k) r.a[k] = kx[k] * r.pi[0][k];
  rotateAboutCayley<0, 1>(r, ky);
  rotateAboutCayley<1, 2>(r, kz);
  rotateAboutCayley<2, 1>(r, ky);
  rotateAboutCayley<1, 0>(r, kx);
  rotateAboutCayley<0, -1>(r, none);
  double inv[N];
  for (int k = 0; k < N; ++k)
    inv[k] = 1.0 / std::sqrt(r.q[0][k] * r.q[0][k] + r.q[1][k] * r.q[1][k] + r.q[2][k] * r.q[2][k] + r.q[3][k] * r.q[3][k]);
  for (int k = 0; k < N; ++k)
    for (int c = 0; c < 4; ++c) r.q[c][k] *= inv[k];
}

// Loads one element into lane k, and stores it back.
template <int N>
inline void loadLane(RotorLanes<N>& r, int k, const Quat& q, const Vec3& pi) {
  r.q[0][k] = q.w, r.q[1][k] = q.x, r.q[2][k] = q.y, r.q[3][k] = q.z;
  r.pi[0][k] = pi[0], r.pi[1][k] = pi[1], r.pi[2][k] = pi[2];
}
template <int N>
inline void storeLane(const RotorLanes<N>& r, int k, Quat& q, Vec3& pi) {
  q = {r.q[0][k], r.q[1][k], r.q[2][k], r.q[3][k]};
  pi = Vec3(r.pi[0][k], r.pi[1][k], r.pi[2][k]);
}

// The drift of the free elements i .. i + N - 1: x += h v, the free rotor, and the rotation probe
// by the trapezoid rule of the world angular velocity before and after.
template <int N>
[[gnu::always_inline]] inline void driftFree(Bodies& s, int i, double h) {
  RotorLanes<N> r;
  Vec3 inverseInertia[N], w0[N];
  double kx[N], ky[N], kz[N];
  for (int k = 0; k < N; ++k) {
    s.position[i + k] += h * s.velocity[i + k];
    inverseInertia[k] = s.inertia[i + k].cwiseInverse();
    w0[k] = rotate(s.orientation[i + k], s.angularMomentumBody[i + k].cwiseProduct(inverseInertia[k]));
    loadLane(r, k, s.orientation[i + k], s.angularMomentumBody[i + k]);
    kx[k] = 0.25 * h * inverseInertia[k][0], ky[k] = 0.25 * h * inverseInertia[k][1];
    kz[k] = 0.5 * h * inverseInertia[k][2];
  }
  freeRotorStepCayley(r, kx, ky, kz);
  for (int k = 0; k < N; ++k) {
    storeLane(r, k, s.orientation[i + k], s.angularMomentumBody[i + k]);
    const Vec3 w1 = rotate(s.orientation[i + k], s.angularMomentumBody[i + k].cwiseProduct(inverseInertia[k]));
    s.accumulatedRotation[i + k] += 0.5 * h * (w0[k] + w1);
  }
}
}  // namespace

void freeRotorStep(Quat& q, Vec3& pi, const Vec3& inertia, double h) {
  const Vec3 inverseInertia = inertia.cwiseInverse();
  const double kx[1] = {0.25 * h * inverseInertia[0]}, ky[1] = {0.25 * h * inverseInertia[1]};
  const double kz[1] = {0.5 * h * inverseInertia[2]};
  RotorLanes<1> r;
  loadLane(r, 0, q, pi);
  freeRotorStepCayley(r, kx, ky, kz);
  storeLane(r, 0, q, pi);
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
  if (!kinematicRotation) return driftFree<1>(s, i, h);
  s.position[i] += h * s.velocity[i];
  Quat& q = s.orientation[i];
  const Vec3 w0 = rotate(q, s.angularMomentumBody[i].cwiseProduct(s.inertia[i].cwiseInverse()));  // omega_world
  q = normalized(expMap(h * w0) * q);
  s.accumulatedRotation[i] += h * w0;
}

void driftFreePair(Bodies& s, int i, double h) { driftFree<2>(s, i, h); }

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
