#include "dftb/gamma_interaction.hpp"

#include <utility>

#include "common/errors.hpp"
#include "dftb/calculator.hpp"
#include "dftb/term_registry.hpp"

namespace mesochain::dftb {

namespace {
std::vector<double> hubbardPerSpecies(const ParameterSet& params) {
  std::vector<double> u;
  for (int s = 0; s < params.speciesCount(); ++s) {
    const SpeciesData& sp = params.species(s);
    if (!(sp.hubbardU > 0.0))
      throw InputError("the parameter tables", "Hubbard U of " + sp.name, std::to_string(sp.hubbardU),
                       "a positive Hubbard U in " + sp.name + "-" + sp.name + ".skf for SCC");
    u.push_back(sp.hubbardU);
  }
  return u;
}
}  // namespace

GammaInteraction::GammaInteraction(std::shared_ptr<const ParameterSet> params,
                                   double ewaldTolerance)
    : params_(std::move(params)),
      coulomb_(makeCoulombLatticeSum(ewaldTolerance)),
      shortRange_(std::make_unique<ShortRangeGammaSum>(hubbardPerSpecies(*params_),
                                                       ewaldTolerance * 1e-2)) {}

Eigen::MatrixXd GammaInteraction::kernel(const objective::ObjectiveCell& cell) const {
  Eigen::MatrixXd g = coulomb_->matrix(cell) - shortRange_->matrix(cell);
  for (int a = 0; a < cell.atomCount(); ++a) g(a, a) += params_->species(cell.species[a]).hubbardU;
  return g;
}

ImagePairSum GammaInteraction::derivatives(const objective::ObjectiveCell& cell,
                                           const Eigen::MatrixXd& weights) const {
  ImagePairSum d = coulomb_->derivatives(cell, weights);
  const ImagePairSum sr = shortRange_->derivatives(cell, weights);
  d.energy -= sr.energy;
  d.gradient -= sr.gradient;
  d.dTranslation -= sr.dTranslation;
  d.dTwist -= sr.dTwist;
  return d;
}

MESOCHAIN_DFTB_TERM(TermRegistration{
    "scc", 150, "DFTB2 charge interaction gamma~ (Ewald 1/r minus the short-range part, + U)",
    true, [](const CalculatorSettings& s) { return s.scc.enabled; }, nullptr,
    [](const TermBuild& b) -> std::shared_ptr<const ChargeInteraction> {
      validate(b.settings.scc);
      return std::make_shared<GammaInteraction>(b.params, b.settings.scc.ewaldTolerance);
    }})

}  // namespace mesochain::dftb
