#include "dftb/dispersion_ewald.hpp"

#include <cmath>
#include <utility>

namespace mesochain::dftb {

LjShortRange::LjShortRange(const UffLennardJones& lj)
    : lj_(lj), c6_(2.0 * lj.epsilon() * std::pow(lj.r0(), 6)) {}

void LjShortRange::evaluate(double r, double& value, double& derivative) const {
  lj_.evaluate(r, value, derivative);
  if (r >= lj_.cutoff()) return;
  const double r6 = std::pow(r, 6);
  value += c6_ / r6;
  derivative -= 6.0 * c6_ / (r6 * r);
}

namespace {
ewald::LatticeSumSettings settingsFor(double tolerance) {
  ewald::LatticeSumSettings s;
  s.tolerance = tolerance;
  return s;
}

SpeciesPairTable<LjShortRange> shortRangePairs(const SpeciesPairTable<UffLennardJones>& lj) {
  SpeciesPairTable<LjShortRange> t;
  t.speciesCount = lj.speciesCount;
  for (const UffLennardJones& p : lj.pairs) t.pairs.emplace_back(p);
  return t;
}
}  // namespace

EwaldDispersionTerm::EwaldDispersionTerm(const UffLennardJones& lj, double tolerance)
    : EwaldDispersionTerm(SpeciesPairTable<UffLennardJones>{{lj}, 0}, tolerance) {}

EwaldDispersionTerm::EwaldDispersionTerm(const SpeciesPairTable<UffLennardJones>& lj,
                                         double tolerance)
    : shortTerm_("dispersion_short", shortRangePairs(lj)),
      sum_(ewald::Kernel::InverseSixth, settingsFor(tolerance)) {}

void EwaldDispersionTerm::evaluate(const objective::ObjectiveCell& cell,
                                   const EvaluationRequest& request, TermOutput& out) const {
  TermOutput shortPart;
  shortTerm_.evaluate(cell, request, shortPart);
  double energy = shortPart.energies["dispersion_short"];
  out.gradient = std::move(shortPart.gradient);
  out.dEdTranslation = shortPart.dEdTranslation;
  out.dEdTwist = shortPart.dEdTwist;
  const int n = cell.atomCount();
  Eigen::MatrixXd w(n, n);
  const SpeciesPairTable<LjShortRange>& pairs = shortTerm_.evaluator();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) w(i, j) = -pairs.pair(cell.species[i], cell.species[j]).c6();
  ewald::LatticeSumPlan used;  // the plan the sum ran with, reported without planning again
  if (request.gradient || request.strain) {
    const auto d = sum_.derivatives(cell, w, &used);
    energy += d.energy;
    if (request.gradient) out.gradient += d.gradient;
    if (request.strain && !cell.symmetry.isRing()) {
      out.dEdTranslation += d.dTranslation;
      out.dEdTwist += d.dTwist;
    }
  } else {
    energy += 0.5 * w.cwiseProduct(sum_.matrix(cell, &used)).sum();
  }
  out.energies.add("dispersion", EnergyKind::Energy, energy);
  out.extras["dispersion_ewald_splitting"] = used.splitting;
}

}  // namespace mesochain::dftb
