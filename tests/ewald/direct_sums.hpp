#pragma once
// Brute-force references for the helical lattice sums: plain sums over group elements, with a
// smooth window over the screw index and polynomial extrapolation in 1/N for the Coulomb energy
// of a neutral cell (whose plain partial sums converge only like 1/N^2).
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace ewaldtest {

using mesochain::objective::GroupElement;
using mesochain::objective::ObjectiveCell;

// C-infinity step: 1 for |s| <= 1/2, 0 for |s| >= 1.
inline double window(double s) {
  const double x = 2 * (std::abs(s) - 0.5);
  if (x <= 0) return 1;
  if (x >= 1) return 0;
  const double a = std::exp(-1 / x), b = std::exp(-1 / (1 - x));
  return b / (a + b);
}

// sum_{zeta, c} window(zeta / N) K(|x_i - g x_j|) per pair (identity excluded for i == j);
// power = 1 (Coulomb) or 6. N = 0 with no window for a ring.
inline Eigen::MatrixXd windowedSum(const ObjectiveCell& cell, int power, long n, bool useWindow) {
  const int no = cell.atomCount();
  const auto& s = cell.symmetry;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(no, no);
  const long zmax = s.isRing() ? 0 : n;
  for (int i = 0; i < no; ++i)
    for (int j = 0; j < no; ++j) {
      long double acc = 0;
      for (long z = -zmax; z <= zmax; ++z) {
        const double f = useWindow ? window(static_cast<double>(z) / n) : 1.0;
        if (f == 0) continue;
        for (int c = 0; c < s.rotationOrder(); ++c) {
          const GroupElement g{z, c};
          if (i == j && g.isIdentity()) continue;
          const double r = (s.apply(g, cell.positions.col(j)) - cell.positions.col(i)).norm();
          acc += f * std::pow(r, -power);
        }
      }
      m(i, j) = static_cast<double>(acc);
    }
  return m;
}

// Coulomb energy per cell of a neutral cell: windowed sums at N = n0 * {1, 1.5, 2, 3, 4, 6}
// extrapolated to 1/N -> 0 with the error powers 1/N^2 .. 1/N^6 (tails of neutral-cell
// interactions decay like zeta^-3 and faster; the window removes oscillating tails).
inline double extrapolatedCoulombEnergy(const ObjectiveCell& cell, const Eigen::VectorXd& q,
                                        long n0) {
  const std::vector<double> factors{1, 1.5, 2, 3, 4, 6};
  const int m = static_cast<int>(factors.size());
  Eigen::MatrixXd a(m, m);
  Eigen::VectorXd e(m);
  for (int r = 0; r < m; ++r) {
    const long n = static_cast<long>(n0 * factors[r]);
    e(r) = 0.5 * q.dot(windowedSum(cell, 1, n, true) * q);
    const double h = 1.0 / static_cast<double>(n);
    a(r, 0) = 1;
    for (int p = 1; p < m; ++p) a(r, p) = std::pow(h * n0, p + 1);
  }
  return a.fullPivLu().solve(e)(0);
}

}  // namespace ewaldtest
