#pragma once
// The charge interaction of DFTB2 ("scc", registered in gamma_interaction.cpp; Elstner et al.,
// Phys. Rev. B 58, 7260 (1998)):
//   K_ij = gamma~_ij = Phi_ij - S~_ij + delta_ij U_i,
// the 1/r lattice sum Phi from a CoulombLatticeSum (the helical Ewald sum), the short-range part
// S~ summed over images (dftb/gamma_functional.hpp), U the Hubbard parameter of the tables.
// Built when CalculatorSettings::scc.enabled; it makes the band term self-consistent.
#include <memory>
#include <string>
#include <vector>

#include "dftb/charge_interaction.hpp"
#include "dftb/coulomb_lattice_sum.hpp"
#include "dftb/gamma_functional.hpp"
#include "dftb/parameters.hpp"

namespace mesochain::dftb {

class GammaInteraction final : public ChargeInteraction {
 public:
  // ewaldTolerance: SccSettings::ewaldTolerance (the 1/r sum; the short-range image cutoff at
  // 1e-2 of it). InputError for a species without a positive Hubbard U.
  GammaInteraction(std::shared_ptr<const ParameterSet> params, double ewaldTolerance);
  std::string name() const override { return "scc"; }
  Eigen::MatrixXd kernel(const objective::ObjectiveCell& cell) const override;
  ImagePairSum derivatives(const objective::ObjectiveCell& cell,
                           const Eigen::MatrixXd& weights) const override;

 private:
  std::shared_ptr<const ParameterSet> params_;
  std::unique_ptr<CoulombLatticeSum> coulomb_;
  std::unique_ptr<ShortRangeGammaSum> shortRange_;
};

}  // namespace mesochain::dftb
