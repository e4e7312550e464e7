#pragma once
// Long-range (smooth) part of the helical Ewald sum for one pair of cell sites: the Gaussian
// superposition of the split kernel, Poisson-summed over the screw index (docs/ewald.md,
// eqs. (E6)-(E13); the part t < t_c in closed form, eqs. (E18)-(E20)). Internal to ewald/.
#include <vector>

#include "ewald/helical_lattice_sum.hpp"

namespace mesochain::ewald::detail {

struct ReciprocalSetup {
  Kernel kernel = Kernel::Coulomb;
  double alpha = 1;        // splitting parameter, 1/Bohr
  double translation = 1;  // T, Bohr
  double twist = 0;        // gamma, rad
  int rotationOrder = 1;   // N_a
  double elementTolerance = 1e-12;  // absolute accuracy aimed at for the pair value
  double panelWidth = 1.0;          // quadrature panel width in u = ln(t / alpha^2)
};

// Value and derivatives of the long-range pair sum L_ij (eq. (E12)) with respect to the
// cylindrical coordinates of site i (rho_i, phi_i, z_i) and site j, and to T and gamma.
// Angular derivatives are given as (1/rho) d/dphi, finite on the axis.
struct PairLongRange {
  double value = 0;
  double dRhoI = 0, dRhoJ = 0;
  double gradPhiI = 0, gradPhiJ = 0;  // (1/rho_i) dL/dphi_i, (1/rho_j) dL/dphi_j
  double dDz = 0;                     // dL/d(z_i - z_j)
  double dTranslation = 0, dTwist = 0;
  long terms = 0;                     // (l, k) terms accumulated (for plans and benchmarks)
  int maxOrder = 0;                   // largest l kept
  int nodes = 0;                      // quadrature nodes used
};

// dphi = phi_i - phi_j, dz = z_i - z_j. Includes the identity image (the caller removes the
// self term for i == j, eq. (E15)). Throws NumericalError when a truncation limit is exceeded.
PairLongRange longRangePair(const ReciprocalSetup& setup, double rhoI, double rhoJ, double dphi,
                            double dz, bool withDerivatives);

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre recurrence).
void gaussLegendre(int order, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace mesochain::ewald::detail
