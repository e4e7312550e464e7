#pragma once
// Interpolation of Slater-Koster integral tables on an equidistant grid, with analytic d/dr.
//
// The scheme is the one of DFTB+'s default ("new") method, src/dftbp/dftb/slakoeqgrid.F90
// (SlakoEqGrid_interNew_) with the constants of src/dftbp/common/accuracy.F90 (distFudge);
// this is an independent implementation of the same mathematics:
//   grid:   row i (1-based, i = 1..N) at r_i = i h
//   inside (r < r_N):  the degree-7 polynomial through the 8 rows i0 .. i0+7 with
//           i0 = clamp(floor(r / h) - 3, 1, N - 7), i.e. 4 grid points at or below r and 4
//           above it, shifted to stay inside the table. (DFTB+ evaluates it with Neville's
//           scheme; here in Lagrange form, whose derivative is analytic.)
//   tail (r_N <= r < r_N + L), L = 1 Bohr:  the quintic
//           f(r) = s^3 (D + E s + F s^2),   s = (r_N + L - r) / L,
//           whose value, first and second derivative are zero at r_N + L and equal those of
//           the last 8-point polynomial at r_N:  with a = y, b = -L y', c = L^2 y'',
//           D = 10a - 4b + c/2,  E = -15a + 7b - c,  F = 6a - 3b + c/2.
//           (DFTB+ takes y' and y'' of that polynomial by central differences with step
//           1e-5 Bohr; here they are exact. The difference is far below the table precision.)
//   r >= r_N + L:  zero. cutoff() = N h + L.
// A table needs at least 9 rows (as in DFTB+).
#include <string>

#include <Eigen/Dense>

namespace mesochain::dftb {

class SkGrid {
 public:
  static constexpr int kPoints = 8;        // points of the local polynomial
  static constexpr int kPointsRight = 4;   // of which above floor(r/h)
  static constexpr double kTailLength = 1.0;  // Bohr (DFTB+ distFudge)

  // table: rows x columns, row i (0-based) at r = (i + 1) * spacing. `source` names the
  // table(s) in errors.
  SkGrid(double spacing, Eigen::MatrixXd table, const std::string& source);

  double cutoff() const { return cutoff_; }
  double spacing() const { return h_; }
  int rows() const { return static_cast<int>(table_.rows()); }
  int columns() const { return static_cast<int>(table_.cols()); }

  // Values and d/dr of every column at r (arrays of columns() entries).
  void evaluate(double r, double* value, double* derivative) const;

 private:
  double h_;
  Eigen::MatrixXd table_;
  double lastR_;   // r_N
  double cutoff_;  // r_N + L
  // Tail coefficients D, E, F per column.
  Eigen::MatrixXd tail_;
};

}  // namespace mesochain::dftb
