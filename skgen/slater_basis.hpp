#pragma once
// Slater-type-function basis back-end of the atomic solver (the classical choice of published
// DFTB parameter sets, e.g. the Eschrig / Porezag codes behind pbc-0-3): the radial function of
// every state with angular momentum l is expanded as
//   R(r) = Σ_{i,j} c_ij r^{l+i} e^{−α_j r},   i = 0..powers−1, α_j from a fixed exponent set,
// and the radial Kohn-Sham equation becomes the generalized eigenproblem H c = ε S c.
// S and the kinetic matrix are analytic (∫_0^∞ r^m e^{−βr} dr = m!/β^{m+1}); the potential
// (nuclear, Hartree, exchange-correlation, confinement, all given on the atom's log grid) is
// integrated on that grid, where the trapezoid rule in ln r converges faster than any power of
// the step for these smooth, decaying integrands.
#include <vector>

#include <Eigen/Dense>

#include "skgen/radial_grid.hpp"

namespace mesochain::skgen {

struct SlaterBasis {
  std::vector<double> exponents;  // α_j (1/Bohr); empty: the numerical-grid back-end is used
  int powers = 3;                 // polynomial powers r^l .. r^{l+powers−1} per exponent
  bool empty() const { return exponents.empty(); }
};

// One term c r^k e^{−α r} of a radial function.
struct SlaterTerm {
  double c = 0.0;
  int k = 0;
  double alpha = 1.0;
};

// R(r), dR/dr and the radial part of the kinetic operator applied to R Y_lm,
//   t(r) = −½ [ R'' + 2R'/r − l(l+1) R / r² ],
// for a sum of Slater terms (all with k >= l, so t is regular at r = 0).
struct SlaterValue {
  double R = 0.0, dR = 0.0, t = 0.0;
};
SlaterValue evaluateSlater(const std::vector<SlaterTerm>& terms, int l, double r);

struct SlaterState {
  double energy = 0.0;
  std::vector<SlaterTerm> terms;  // normalised, outermost lobe positive
  std::vector<double> u;          // u = r R on the grid
};

// Basis of one angular momentum on one grid; S and T are built once, the potential per solve.
class SlaterRadialSolver {
 public:
  // Throws std::invalid_argument for an empty basis, non-positive exponents or
  // powers < 1 (the callers validate user input and name the key).
  SlaterRadialSolver(const SlaterBasis& basis, const LogGrid& grid, int l);

  int size() const { return static_cast<int>(alpha_.size()); }
  // The lowest `count` states of T + l(l+1)/(2r²) + v, v the full potential on the grid.
  std::vector<SlaterState> solve(const std::vector<double>& v, int count) const;

  const Eigen::MatrixXd& overlap() const { return s_; }

 private:
  const LogGrid* grid_;
  int l_;
  std::vector<int> power_;      // k = l + i of every basis function
  std::vector<double> alpha_;   // α of every basis function
  Eigen::MatrixXd s_, t_;
  Eigen::MatrixXd chi_;         // basis functions on the grid (functions x points)
};

}  // namespace mesochain::skgen
