#pragma once
// Lattice sums of 1/r and 1/r^6 over an objective (helical) group, by Ewald splitting on the
// helix (Nikiforov, Hourahine, Aradi, Frauenheim, Dumitrica, J. Chem. Phys. 139, 094110
// (2013); our own derivation with equation numbers in docs/ewald.md).
//
// Phi_ij = sum over all group elements g = (zeta, c) of K(|x_i - g x_j|), the identity left out
// when i == j. For the Coulomb kernel the sum over a screw diverges logarithmically; Phi is the
// neutralised sum (docs/ewald.md eq. (E14)): each site's infinite screw line carries the
// reference potential -2 lambda ln(rho / 1 Bohr) of a uniform line charge, lambda = N_a / T.
// Any constant shift cancels in E = 1/2 sum_ij q_i q_j Phi_ij when sum_i q_i = 0, which is then
// the Coulomb energy per cell. A closed ring (T = 0) is summed directly.
//
// Atomic units: Bohr, radians, Hartree for unit charges.
#include <optional>

#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace mesochain::ewald {

enum class Kernel { Coulomb /* 1/r */, InverseSixth /* 1/r^6 */ };

struct LatticeSumSettings {
  // Requested relative accuracy: every matrix element to tol K(d_min) / N_o (d_min: the shortest
  // distance between distinct sites), so that energies 1/2 w^T Phi w are good to ~tol. Sets the splitting parameter (unless given) and every
  // truncation. Must lie in [1e-13, 1e-2]; tighter cannot be met in double precision.
  double tolerance = 1e-10;
  std::optional<double> splitting;  // Ewald splitting parameter alpha (1/Bohr); auto if empty
};

// The truncations chosen for one cell (reported by plan(), and by matrix() and derivatives()
// through their optional `used` argument; for benchmarks, tests and reports).
struct LatticeSumPlan {
  double splitting = 0;       // alpha, 1/Bohr
  double realSpaceCutoff = 0; // Bohr
  double elementTolerance = 0;// absolute accuracy aimed at per matrix element
  double shortestDistance = 0;// d_min, Bohr
  int maxAngularOrder = 0;    // largest l kept (a multiple of N_a)
  long reciprocalTerms = 0;   // (l, k) pairs kept at the largest Gaussian width
  int quadratureNodes = 0;    // nodes of the splitting-integral quadrature (eq. (E11))
};

class HelicalLatticeSum {
 public:
  HelicalLatticeSum(Kernel kernel, LatticeSumSettings settings);

  Kernel kernel() const { return kernel_; }
  const LatticeSumSettings& settings() const { return settings_; }

  // N_o x N_o, symmetric. With `used`, also the plan the sum was truncated by (equal to
  // plan(cell), without planning the cell a second time).
  Eigen::MatrixXd matrix(const objective::ObjectiveCell& cell, LatticeSumPlan* used = nullptr) const;

  struct Derivatives {
    Eigen::Matrix3Xd gradient;   // dE/dx_i (Hartree/Bohr for unit weights)
    double dTranslation = 0;     // dE/dT at fixed cell positions
    double dTwist = 0;           // dE/dgamma at fixed cell positions
    double energy = 0;           // E itself
  };
  // Derivatives of E = 1/2 sum_ij w_ij Phi_ij (w symmetric: q q^T for Coulomb, C6_ij for
  // dispersion). Coulomb weights must be neutral (sum_ij w_ij = 0) or an InputError is thrown.
  // With `used`, also the plan the sum was truncated by (equal to plan(cell)).
  Derivatives derivatives(const objective::ObjectiveCell& cell, const Eigen::MatrixXd& weights,
                          LatticeSumPlan* used = nullptr) const;

  // E = 1/2 q^T Phi q; for Coulomb the charges must sum to zero (else InputError).
  double energy(const objective::ObjectiveCell& cell, const Eigen::VectorXd& charges) const;

  // The splitting parameter and truncations this tolerance implies for `cell`.
  LatticeSumPlan plan(const objective::ObjectiveCell& cell) const;

 private:
  Kernel kernel_;
  LatticeSumSettings settings_;
};

}  // namespace mesochain::ewald
