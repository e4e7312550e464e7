#include "dftb/calculator.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

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

namespace {
// The band term holds at least three complex N_o x N_o matrices (Hamiltonian, overlap,
// eigenvectors) of a k-point at a time: 48 N_o^2 bytes. A cell whose estimate exceeds the
// machine's memory is refused before the first allocation (a bare std::bad_alloc otherwise).
void requireBandMemory(const objective::ObjectiveCell& cell, const ParameterSet& params,
                       int kpoints) {
  double orbitals = 0;
  for (int a = 0; a < cell.atomCount(); ++a)
    orbitals += params.species(cell.species[a]).orbitalCount;
  const double bytes = 48.0 * orbitals * orbitals;
  const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  if (memory > 0 && bytes > memory)
    throw InputError("<calculator>", "the cell's atoms",
                     fmt::format("{} atoms with {:.0f} orbitals: at least {:.3g} GB for the "
                                 "Hamiltonian, overlap and eigenvectors of one of the {} k-points",
                                 cell.atomCount(), orbitals, bytes * 1e-9, kpoints),
                     fmt::format("a cell that fits the {:.3g} GB of this machine", memory * 1e-9));
}
}  // namespace

Result Calculator::evaluate(const objective::ObjectiveCell& cell,
                            const EvaluationRequest& request) const {
  for (size_t s = 0; s < cell.speciesNames.size(); ++s)
    if (static_cast<int>(s) >= params_->speciesCount() ||
        params_->species(static_cast<int>(s)).name != cell.speciesNames[s])
      throw InputError("<calculator>", "species " + cell.speciesNames[s],
                       "a species order that differs from the parameter set",
                       "the parameter set loaded for this cell's species");
  requireBandMemory(cell, *params_, settings_.band.helicalKPoints);
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
  // A non-finite energy or force is never a result (it would be written as null, exit 0).
  const std::pair<const char*, double> parts[] = {
      {"band energy", r.bandEnergy}, {"entropy term", r.entropyTerm}, {"SCC energy", r.scc},
      {"repulsive energy", r.repulsive}, {"dispersion energy", r.dispersion},
      {"dF/dT", r.dFdTranslation}, {"dF/dtwist", r.dFdTwist}};
  for (const auto& [name, value] : parts)
    if (!std::isfinite(value))
      throw NumericalError(fmt::format("the calculator gave a non-finite {} ({}) for a cell of {} "
                                       "atoms", name, value, cell.atomCount()));
  if (r.gradient.size() && !r.gradient.allFinite())
    throw NumericalError(fmt::format("the calculator gave non-finite forces for a cell of {} atoms",
                                     cell.atomCount()));
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
