#pragma once
// The gamma functional of second-order (SCC) DFTB: Elstner et al., Phys. Rev. B 58, 7260
// (1998), eqs. (13)-(16) and appendix. Two exponential charge densities with decay constants
// tau = 16/5 U (U: Hubbard parameter, Hartree) interact as
//   gamma_ab(r) = 1/r - S(r; tau_a, tau_b),
// where the short-range part S decays exponentially and gamma_aa(0) = U_a. On an objective
// cell the short-range part is summed over the images of the cell atoms,
//   S~_ij = sum_g S(|g(x_j) - x_i|)   (identity excluded for i == j),
// and the long-range 1/r part goes through a CoulombLatticeSum (dftb/coulomb_lattice_sum.hpp).
#include <vector>

#include <Eigen/Dense>

#include "dftb/coulomb_lattice_sum.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::dftb {

// S(r; U_a, U_b) and dS/dr for r > 0 (Bohr, Hartree). Equal tau:
//   S = exp(-tau r) [1/r + 11 tau/16 + 3 tau^2 r/16 + tau^3 r^2/48];
// unequal tau: S = e^{-tau_a r} [tau_b^4 tau_a / (2 (tau_a^2 - tau_b^2)^2)
//   - (tau_b^6 - 3 tau_b^4 tau_a^2) / ((tau_a^2 - tau_b^2)^3 r)] + (a <-> b).
// The unequal form loses digits as tau_a -> tau_b (denominators (tau_a^2 - tau_b^2)^3); below a
// relative difference of 1e-3 the equal form at the mean tau is used (S is symmetric in a, b,
// so that error is second order in the difference, < 1e-6 relative).
void gammaShortRange(double r, double ua, double ub, double& value, double& derivative);

// gamma_ab(r) = 1/r - S for r > 0; the r -> 0 limit for equal U is U.
double gammaValue(double r, double ua, double ub);

// Distance beyond which |S| (and |r^2 S|, so that the image sum converges to the tolerance)
// stays below `tolerance` for decay constants of at least 16/5 uMin.
double shortRangeCutoff(double uMin, double tolerance);

// The short-range part summed over images. hubbard: U per species index of the cell.
class ShortRangeGammaSum {
 public:
  ShortRangeGammaSum(std::vector<double> hubbard, double tolerance);
  double cutoff() const { return cutoff_; }
  Eigen::MatrixXd matrix(const objective::ObjectiveCell& cell) const;  // S~, N_o x N_o
  // Derivatives of 1/2 sum_ij w_ij S~_ij.
  LatticeSumDerivatives derivatives(const objective::ObjectiveCell& cell,
                                    const Eigen::MatrixXd& weights) const;

 private:
  std::vector<double> hubbard_;
  double cutoff_ = 0.0;
};

}  // namespace mesochain::dftb
