#include "mdem/integrator.hpp"

#include <cmath>

namespace mesochain::mdem {

void kick(Bodies& s, double h) {
#pragma omp parallel for schedule(static) if (s.size() > 512)
  for (int i = 0; i < s.size(); ++i) kickElement(s, i, h);
}

namespace {
// Sub-flow of H_axis = pi_axis^2 / (2 I_axis) over time h.
inline void rotateAbout(int axis, Quat& q, Vec3& pi, const Vec3& inertia, double h) {
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
}  // namespace

void freeRotorStep(Quat& q, Vec3& pi, const Vec3& inertia, double h) {
  rotateAbout(0, q, pi, inertia, 0.5 * h);
  rotateAbout(1, q, pi, inertia, 0.5 * h);
  rotateAbout(2, q, pi, inertia, h);
  rotateAbout(1, q, pi, inertia, 0.5 * h);
  rotateAbout(0, q, pi, inertia, 0.5 * h);
  q = normalized(q);
}

void driftElement(Bodies& s, int i, double h, bool kinematicRotation) {
  s.position[i] += h * s.velocity[i];
  const Vec3 w0 = s.angularVelocityWorld(i);
  if (kinematicRotation) {
    s.orientation[i] = normalized(expMap(h * w0) * s.orientation[i]);
    s.accumulatedRotation[i] += h * w0;
  } else {
    freeRotorStep(s.orientation[i], s.angularMomentumBody[i], s.inertia[i], h);
    s.accumulatedRotation[i] += 0.5 * h * (w0 + s.angularVelocityWorld(i));
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
