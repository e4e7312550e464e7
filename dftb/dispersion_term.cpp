#include "dftb/dispersion_term.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "dftb/calculator.hpp"
#include "dftb/dispersion_ewald.hpp"
#include "dftb/parameters.hpp"
#include "dftb/term_registry.hpp"

namespace mesochain::dftb {

void validate(const DispersionSettings& d) {
  const std::string src = "the calculator settings";
  requireFinite(d.epsilon, src, "dispersion.epsilon_hartree");
  requireFinite(d.r0, src, "dispersion.r0_bohr");
  requireFinite(d.cutoff, src, "dispersion.cutoff_bohr");
  if (!(d.epsilon >= 0.0))
    throw InputError(src, "dispersion.epsilon_hartree", "a negative well depth", ">= 0");
  // With per-element parameters epsilon and r0 are not used (the readers leave them 0).
  if (d.elements.empty() && !(d.r0 > 0.0))
    throw InputError(src, "dispersion.r0_bohr", "r0 <= 0", "a positive distance");
  if (!(d.cutoff > 0.0))
    throw InputError(src, "dispersion.cutoff_bohr", "cutoff <= 0", "a positive distance");
  if (d.elementEpsilon.size() != d.elements.size() || d.elementR0.size() != d.elements.size())
    throw InputError(src, "dispersion.elements",
                     fmt::format("{} elements, {} well depths, {} distances", d.elements.size(),
                                 d.elementEpsilon.size(), d.elementR0.size()),
                     "one well depth and one distance per element");
  for (std::size_t k = 0; k < d.elements.size(); ++k) {
    const std::string key = "dispersion.elements." + d.elements[k];
    requireFinite(d.elementEpsilon[k], src, key + ".epsilon_hartree");
    requireFinite(d.elementR0[k], src, key + ".r0_bohr");
    if (!(d.elementEpsilon[k] >= 0.0))
      throw InputError(src, key + ".epsilon_hartree", "a negative well depth", ">= 0");
    if (!(d.elementR0[k] > 0.0)) throw InputError(src, key + ".r0_bohr", "r0 <= 0", "a positive distance");
    for (std::size_t m = 0; m < k; ++m)
      if (d.elements[m] == d.elements[k])
        throw InputError(src, key, "the element twice", "one entry per element");
  }
  if (d.ewald && !(d.ewaldTolerance >= 1e-13 && d.ewaldTolerance <= 1e-2))
    throw InputError(src, "dispersion.ewald_tolerance", std::to_string(d.ewaldTolerance),
                     "a tolerance in [1e-13, 1e-2]");
}

SpeciesPairTable<UffLennardJones> lennardJonesPairs(const DispersionSettings& d,
                                                    const std::vector<std::string>& species) {
  if (d.elements.empty()) return {{UffLennardJones(d.epsilon, d.r0, d.cutoff)}, 0};
  const int n = static_cast<int>(species.size());
  std::vector<double> eps(n), r0(n);
  for (int s = 0; s < n; ++s) {
    const auto it = std::find(d.elements.begin(), d.elements.end(), species[s]);
    if (it == d.elements.end())
      throw InputError("the calculator settings", "dispersion.elements",
                       "no Lennard-Jones parameters for " + species[s],
                       "an entry for every element of the cell");
    eps[s] = d.elementEpsilon[it - d.elements.begin()];
    r0[s] = d.elementR0[it - d.elements.begin()];
  }
  SpeciesPairTable<UffLennardJones> t;
  t.speciesCount = n;
  // Geometric means (DFTB+ dispuff.F90); sqrt(x * x) == x, so one element gives its own values.
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      t.pairs.emplace_back(std::sqrt(eps[a] * eps[b]), std::sqrt(r0[a] * r0[b]), d.cutoff);
  return t;
}

CutoffDispersionTerm::CutoffDispersionTerm(const UffLennardJones& lj)
    : CutoffDispersionTerm(SpeciesPairTable<UffLennardJones>{{lj}, 0}) {}

CutoffDispersionTerm::CutoffDispersionTerm(SpeciesPairTable<UffLennardJones> pairs)
    : pairs_("dispersion", std::move(pairs)) {}

void CutoffDispersionTerm::evaluate(const objective::ObjectiveCell& cell,
                                    const EvaluationRequest& request, TermOutput& out) const {
  pairs_.evaluate(cell, request, out);
  if (cell.symmetry.isRing()) return;
  const SpeciesPairTable<UffLennardJones>& lj = pairs_.evaluator();
  double c6 = 0.0;  // sum over the cell pairs of C6_ij = 2 eps_ij r0_ij^6
  for (int i = 0; i < cell.atomCount(); ++i)
    for (int j = 0; j < cell.atomCount(); ++j) {
      const UffLennardJones& p = lj.pair(cell.species[i], cell.species[j]);
      c6 += 2.0 * p.epsilon() * std::pow(p.r0(), 6);
    }
  out.energies.add("dispersion_tail_estimate", EnergyKind::Reported,
                   -0.2 * cell.symmetry.rotationOrder() / cell.symmetry.translation() * c6 /
                       std::pow(lj.cutoff(), 5));
}

MESOCHAIN_DFTB_TERM(TermRegistration{
    "dispersion", 300, "Lennard-Jones (UFF form) dispersion, cutoff or helical Ewald sum", false,
    [](const CalculatorSettings& s) { return s.dispersion.enabled; },
    [](const TermBuild& b) -> std::unique_ptr<EnergyTerm> {
      const DispersionSettings& d = b.settings.dispersion;
      validate(d);
      std::vector<std::string> species;
      for (int s = 0; s < b.params->speciesCount(); ++s) species.push_back(b.params->species(s).name);
      SpeciesPairTable<UffLennardJones> lj = lennardJonesPairs(d, species);
      if (d.ewald) return std::make_unique<EwaldDispersionTerm>(std::move(lj), d.ewaldTolerance);
      return std::make_unique<CutoffDispersionTerm>(std::move(lj));
    },
    nullptr})

}  // namespace mesochain::dftb
