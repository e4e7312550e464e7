#pragma once
// A charge-dependent interaction of self-consistent-charge DFTB: an energy quadratic in the
// Mulliken charge fluctuations dq (electrons relative to the neutral atoms),
//   E = 1/2 sum_ij dq_i K_ij dq_j,   V_i = dE/ddq_i = sum_j K_ij dq_j   (per cell),
// with K a symmetric N_o x N_o kernel of the geometry (summed over the objective images). The
// interactions a calculator builds (registered with needsCharges, dftb/term_registry.hpp) are
// what the self-consistency loop of the band term (dftb/scc_term.hpp) adds to H0: their summed
// kernel gives the potential shift, their energies the second-order energy, their derivatives
// (at the converged charges) the forces. The DFTB2 gamma interaction is
// dftb/gamma_interaction.hpp.
#include <string>

#include <Eigen/Dense>

#include "dftb/image_pair_sum.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::dftb {

class ChargeInteraction {
 public:
  virtual ~ChargeInteraction() = default;
  virtual std::string name() const = 0;
  // K (Hartree per electron^2), N_o x N_o, symmetric.
  virtual Eigen::MatrixXd kernel(const objective::ObjectiveCell& cell) const = 0;
  // Derivatives of 1/2 sum_ij w_ij K_ij at fixed weights (w = dq dq^T at self-consistency)
  // with respect to the cell atoms, T and gamma.
  virtual ImagePairSum derivatives(const objective::ObjectiveCell& cell,
                                   const Eigen::MatrixXd& weights) const = 0;
};

}  // namespace mesochain::dftb
