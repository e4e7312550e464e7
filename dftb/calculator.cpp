#include "dftb/calculator.hpp"

#include <chrono>
#include <cmath>

#include "common/errors.hpp"
#include "dftb/dispersion_ewald.hpp"
#include "dftb/dispersion_lj.hpp"
#include "dftb/pair_potential_term.hpp"

namespace mesochain::dftb {

Calculator::Calculator(std::shared_ptr<const ParameterSet> params, CalculatorSettings settings)
    : params_(std::move(params)), settings_(settings) {
  if (settings_.scc.enabled)
    terms_.push_back(std::make_unique<SccBandStructureTerm>(params_, settings_.band, settings_.scc,
                                                            chargeCache_));
  else
    terms_.push_back(std::make_unique<BandStructureTerm>(params_, settings_.band));
  const ParameterSet* p = params_.get();
  terms_.push_back(std::make_unique<PairPotentialTerm>(
      "repulsive", [p](int a, int b) -> const RadialPotential& { return p->repulsive(a, b); },
      p->repulsiveCutoff()));
  if (settings_.dispersion.enabled) {
    const auto& d = settings_.dispersion;
    lj_ = std::make_shared<UffLennardJones>(d.epsilon, d.r0, d.cutoff);
    const RadialPotential* lj = lj_.get();
    if (d.ewald)
      terms_.push_back(std::make_unique<EwaldDispersionTerm>(
          UffLennardJones(d.epsilon, d.r0, d.cutoff), d.ewaldTolerance));
    else
      terms_.push_back(std::make_unique<PairPotentialTerm>(
          "dispersion", [lj](int, int) -> const RadialPotential& { return *lj; }, d.cutoff));
  }
}

std::vector<std::string> Calculator::termNames() const {
  std::vector<std::string> names;
  for (const auto& t : terms_) names.push_back(t->name());
  return names;
}

Result Calculator::evaluate(const objective::ObjectiveCell& cell,
                            const EvaluationRequest& request) const {
  for (size_t s = 0; s < cell.speciesNames.size(); ++s)
    if (static_cast<int>(s) >= params_->speciesCount() ||
        params_->species(static_cast<int>(s)).name != cell.speciesNames[s])
      throw InputError("<calculator>", "species " + cell.speciesNames[s],
                       "a species order that differs from the parameter set",
                       "the parameter set loaded for this cell's species");
  Result r;
  r.atoms = cell.atomCount();
  if (request.gradient) r.gradient = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  for (const auto& term : terms_) {
    TermOutput out;
    const auto t0 = std::chrono::steady_clock::now();
    term->evaluate(cell, request, out);
    r.extras["time_" + term->name() + "_total"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (request.gradient) r.gradient += out.gradient;
    r.dFdTranslation += out.dEdTranslation;
    r.dFdTwist += out.dEdTwist;
    for (const auto& [k, v] : out.extras) r.extras[k] = v;
    for (auto& [k, v] : out.series) r.series[k] = std::move(v);
    if (term->name() == "band") {
      r.bandEnergy = out.extras.at("band_energy");
      r.entropyTerm = out.extras.at("entropy_term");
      // The band term's energy is band - TS (+ the SCC double-counting terms).
      r.scc = out.energy - (r.bandEnergy - r.entropyTerm);
    } else if (term->name() == "repulsive") {
      r.repulsive = out.energy;
    } else if (term->name() == "dispersion") {
      r.dispersion = out.energy;
    }
  }
  r.totalEnergy = r.bandEnergy + r.scc + r.repulsive + r.dispersion;
  r.freeEnergy = r.totalEnergy - r.entropyTerm;
  r.extrapolatedEnergy = r.totalEnergy - 0.5 * r.entropyTerm;
  if (settings_.dispersion.enabled && !settings_.dispersion.ewald && !cell.symmetry.isRing()) {
    // Truncation estimate of the r^-6 tail beyond the cutoff for a line of atoms with density
    // lambda = N_o N_a / T: E_tail = -(2/5) N_o lambda eps r0^6 / r_c^5 per cell.
    const auto& d = settings_.dispersion;
    const double lambda = cell.atomCount() * cell.symmetry.rotationOrder() /
                          cell.symmetry.translation();
    r.extras["dispersion_tail_estimate"] =
        -0.4 * cell.atomCount() * lambda * d.epsilon * std::pow(d.r0, 6) / std::pow(d.cutoff, 5);
  }
  return r;
}

}  // namespace mesochain::dftb
