#include "dftb/dispersion_term.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "dftb/calculator.hpp"
#include "dftb/dispersion_ewald.hpp"
#include "dftb/term_registry.hpp"

namespace mesochain::dftb {

void validate(const DispersionSettings& d) {
  const std::string src = "the calculator settings";
  requireFinite(d.epsilon, src, "dispersion.epsilon_hartree");
  requireFinite(d.r0, src, "dispersion.r0_bohr");
  requireFinite(d.cutoff, src, "dispersion.cutoff_bohr");
  if (!(d.epsilon >= 0.0))
    throw InputError(src, "dispersion.epsilon_hartree", "a negative well depth", ">= 0");
  if (!(d.r0 > 0.0)) throw InputError(src, "dispersion.r0_bohr", "r0 <= 0", "a positive distance");
  if (!(d.cutoff > 0.0))
    throw InputError(src, "dispersion.cutoff_bohr", "cutoff <= 0", "a positive distance");
  if (d.ewald && !(d.ewaldTolerance >= 1e-13 && d.ewaldTolerance <= 1e-2))
    throw InputError(src, "dispersion.ewald_tolerance", std::to_string(d.ewaldTolerance),
                     "a tolerance in [1e-13, 1e-2]");
}

CutoffDispersionTerm::CutoffDispersionTerm(const UffLennardJones& lj)
    : pairs_("dispersion", SamePotentialEvaluator<UffLennardJones>{lj}) {}

void CutoffDispersionTerm::evaluate(const objective::ObjectiveCell& cell,
                                    const EvaluationRequest& request, TermOutput& out) const {
  pairs_.evaluate(cell, request, out);
  if (cell.symmetry.isRing()) return;
  const UffLennardJones& lj = pairs_.evaluator().potential;
  const double lambda =
      cell.atomCount() * cell.symmetry.rotationOrder() / cell.symmetry.translation();
  out.energies.add("dispersion_tail_estimate", EnergyKind::Reported,
                   -0.4 * cell.atomCount() * lambda * lj.epsilon() * std::pow(lj.r0(), 6) /
                       std::pow(lj.cutoff(), 5));
}

MESOCHAIN_DFTB_TERM(TermRegistration{
    "dispersion", 300, "Lennard-Jones (UFF form) dispersion, cutoff or helical Ewald sum", false,
    [](const CalculatorSettings& s) { return s.dispersion.enabled; },
    [](const TermBuild& b) -> std::unique_ptr<EnergyTerm> {
      const DispersionSettings& d = b.settings.dispersion;
      validate(d);
      const UffLennardJones lj(d.epsilon, d.r0, d.cutoff);
      if (d.ewald) return std::make_unique<EwaldDispersionTerm>(lj, d.ewaldTolerance);
      return std::make_unique<CutoffDispersionTerm>(lj);
    },
    nullptr})

}  // namespace mesochain::dftb
