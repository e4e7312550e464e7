#pragma once
// DFTB+ has no 1-D periodic Ewald sum: tests/data/dftbplus/ch_chain_1d holds the same chain in
// 3-D cells of lateral vacuum L (one run per L). With tin-foil boundary conditions a quantity of
// the neutral wire lattice goes as y(L) = c0 + c1/L^2 + c2/L^4 (README.md there); c0 is the
// isolated chain that mesochain's 1-D sums compute. Shared by tests/dftb and tests/input.
#include <vector>

#include <Eigen/Dense>

namespace mesochain::testing {

// Least-squares c0 + c1 x + c2 x^2 with x = 1/L^2; returns (c0, c1, c2).
inline Eigen::Vector3d fitInverseSquare(const std::vector<double>& lengths, const std::vector<double>& y) {
  const int n = static_cast<int>(lengths.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    const double x = 1.0 / (lengths[i] * lengths[i]);
    a.row(i) << 1.0, x, x * x;
    b[i] = y[i];
  }
  return a.colPivHouseholderQr().solve(b);
}

}  // namespace mesochain::testing
