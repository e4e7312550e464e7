#pragma once
#include <cmath>

namespace mesochain::objective {

template <class F>
void forEachImageNear(const Symmetry& s, const Eigen::Vector3d& xi, const Eigen::Vector3d& xj,
                      double cutoff, F&& f) {
  const int na = s.rotationOrder();
  const double c2 = cutoff * cutoff;
  long zmin = 0, zmax = 0;
  if (!s.isRing()) {
    // |g(x_j) - x_i| >= |zeta*T + z_j - z_i|: only these screw powers can be within the cutoff.
    const double t = s.translation();
    zmin = static_cast<long>(std::ceil((xi.z() - xj.z() - cutoff) / t));
    zmax = static_cast<long>(std::floor((xi.z() - xj.z() + cutoff) / t));
  }
  // In-plane: the image rotates xj by phi; a cheap bound on the in-plane distance uses radii.
  const double ri = std::hypot(xi.x(), xi.y());
  const double rj = std::hypot(xj.x(), xj.y());
  for (long zeta = zmin; zeta <= zmax; ++zeta) {
    const double dz = static_cast<double>(zeta) * s.translation() + xj.z() - xi.z();
    const double dz2 = dz * dz;
    if (dz2 + (ri - rj) * (ri - rj) >= c2) continue;
    for (int c = 0; c < na; ++c) {
      const GroupElement g{zeta, c};
      const Eigen::Vector3d y = s.apply(g, xj);
      if ((y - xi).squaredNorm() < c2) f(g, y);
    }
  }
}

}  // namespace mesochain::objective
