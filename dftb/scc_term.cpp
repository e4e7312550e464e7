#include "dftb/scc_term.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "common/electronic_temperature.hpp"
#include "common/errors.hpp"
#include "dftb/fermi.hpp"
#include "dftb/band_solver.hpp"
#include "dftb/bloch.hpp"
#include "dftb/charge_mixer.hpp"
#include "dftb/mulliken.hpp"

namespace mesochain::dftb {

using objective::ObjectiveCell;
using Clock = std::chrono::steady_clock;

namespace {
template <class... Args>
std::string fmt(const char* format, Args... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

std::string historyTable(const std::vector<double>& energy, const std::vector<double>& residual) {
  std::string s = "  iteration  free energy (Ha)        max |q_out - q_in| (e)\n";
  char line[128];
  for (size_t m = 0; m < energy.size(); ++m) {
    std::snprintf(line, sizeof line, "  %9zu  %22.14f  %.3e\n", m + 1, energy[m], residual[m]);
    s += line;
  }
  return s;
}
}  // namespace

void validate(const SccSettings& scc) {
  const std::string src = "the calculator settings";
  // Mulliken populations carry rounding errors of a few 1e-15 per electron; a tolerance below
  // 1e-13 electrons cannot be certified in double precision.
  if (!(scc.chargeTolerance >= 1e-13))
    throw InputError(src, "scc.charge_tolerance", std::to_string(scc.chargeTolerance),
                     "at least 1e-13 electrons (tighter cannot be resolved in double precision)");
  if (!(scc.energyTolerance >= 1e-13))
    throw InputError(src, "scc.energy_tolerance_Ha", std::to_string(scc.energyTolerance),
                     "at least 1e-13 Hartree (tighter cannot be resolved in double precision)");
  if (scc.maxIterations < 1)
    throw InputError(src, "scc.max_iterations", std::to_string(scc.maxIterations),
                     "a positive count");
  if (!(scc.ewaldTolerance >= 1e-13 && scc.ewaldTolerance <= 1e-2))
    throw InputError(src, "scc.ewald_tolerance", fmt("%.3g", scc.ewaldTolerance),
                     "a tolerance in [1e-13, 1e-2]");
  makeChargeMixer(scc.mixer, scc.mixing);  // validates the mixer name and mixing
}

SccBandStructureTerm::SccBandStructureTerm(
    std::shared_ptr<const ParameterSet> params, BandSettings band, SccSettings scc,
    std::vector<std::shared_ptr<const ChargeInteraction>> interactions,
    std::shared_ptr<ChargeCache> cache, parallel::Communicator comm)
    : params_(std::move(params)),
      band_(band),
      scc_(std::move(scc)),
      interactions_(std::move(interactions)),
      cache_(std::move(cache)),
      comm_(std::move(comm)) {
  validate(band_);
  validate(scc_);
  if (interactions_.empty())
    throw std::logic_error("SccBandStructureTerm built without a charge interaction");
}

Eigen::MatrixXd SccBandStructureTerm::gammaMatrix(const ObjectiveCell& cell) const {
  Eigen::MatrixXd g = interactions_.front()->kernel(cell);
  for (std::size_t k = 1; k < interactions_.size(); ++k) g += interactions_[k]->kernel(cell);
  return g;
}

void SccBandStructureTerm::evaluate(const ObjectiveCell& cell, const EvaluationRequest& request,
                                    TermOutput& out) const {
  const ParameterSet& params = *params_;
  const double kT = band_.electronicTemperature;
  const auto t0 = Clock::now();
  const BandGeometry geo(cell, params, band_.helicalKPoints, band_.angular);
  const Eigen::MatrixXd gamma = gammaMatrix(cell);
  const int n = cell.atomCount();
  Eigen::VectorXd q0(n);
  for (int a = 0; a < n; ++a) q0[a] = params.species(cell.species[a]).valenceElectrons;
  const auto pairs = geo.images.pairs();
  const auto t1 = Clock::now();

  auto mixer = makeChargeMixer(scc_.mixer, scc_.mixing);
  Eigen::VectorXd dqIn = Eigen::VectorXd::Zero(n), dqOut, v;
  bool warm = false;
  if (scc_.warmStart && cache_)
    if (auto cached = cache_->lookup(cell.species)) {
      dqIn = *cached;
      warm = true;
    }
  std::vector<OrbitalBlock> h(pairs.size());
  // S(k) is the same in every iteration: its Cholesky factors are computed once.
  OverlapFactors overlapFactors(geo, 1024.0 * 1024.0 * 1024.0, comm_);
  std::vector<double> energies, residuals;
  BandSolution sol;
  double energy = 0, h0Energy = 0, sccEnergy = 0, timeIterations = 0;
  bool converged = false;
  std::string reason;
  double bestResidual = std::numeric_limits<double>::infinity();
  int sinceBest = 0;
  for (int it = 0; it < scc_.maxIterations; ++it) {
    const auto a = Clock::now();
    v = gamma * dqIn;
    for (size_t p = 0; p < pairs.size(); ++p)
      h[p] = geo.h0[p] + (0.5 * (v[pairs[p].i] + v[pairs[p].j])) * geo.s[p];
    sol = solveBands(cell, params, geo, h, v, kT, true, band_.eigenvectors, &overlapFactors,
                     comm_);
    const Eigen::VectorXd q = mullikenPopulations(geo.layout, geo.images, sol.onsiteDensity,
                                                  sol.p, geo.s);
    dqOut = q - q0;
    h0Energy = sol.filling.bandEnergy - v.dot(q);
    sccEnergy = 0.5 * dqOut.dot(gamma * dqOut);
    energy = h0Energy - sol.filling.entropyTerm + sccEnergy;
    const double residual = (dqOut - dqIn).cwiseAbs().maxCoeff();
    const double change =
        energies.empty() ? std::numeric_limits<double>::infinity() : std::abs(energy - energies.back());
    energies.push_back(energy);
    residuals.push_back(residual);
    timeIterations += std::chrono::duration<double>(Clock::now() - a).count();
    if (!std::isfinite(energy) || !std::isfinite(residual)) {
      reason = "the energy or the charges became non-finite";
      break;
    }
    if (residual < scc_.chargeTolerance && change < scc_.energyTolerance) {
      converged = true;
      break;
    }
    // Stagnation: no new smallest residual for 10 iterations means the mixer cannot get below
    // the noise floor of the charges (or is cycling); stop instead of spending max_iterations.
    if (residual < bestResidual) {
      bestResidual = residual;
      sinceBest = 0;
    } else if (++sinceBest >= 10) {
      reason = fmt("stagnated: no decrease of the residual below %.3e e in 10 iterations (a "
                   "tolerance below the precision of the charges, or charge sloshing: try "
                   "mixer = \"broyden\" or a smaller mixing)",
                   bestResidual);
      break;
    }
    if (it + 1 < scc_.maxIterations) dqIn = mixer->next(dqIn, dqOut);
  }
  const int iterations = static_cast<int>(energies.size());
  if (!converged && reason.empty())
    reason = "not converged in max_iterations = " + std::to_string(scc_.maxIterations);
  if (!converged && scc_.stopIfUnconverged)
    throw NumericalError(fmt("SCC %s (charge tolerance %.1e e, energy tolerance %.1e Ha, "
                             "mixer %s, mixing %g); history:\n",
                             reason.c_str(), scc_.chargeTolerance, scc_.energyTolerance,
                             scc_.mixer.c_str(), scc_.mixing) +
                         historyTable(energies, residuals));

  if (cache_) {
    cache_->recordLoop(iterations);
    if (converged && scc_.warmStart) cache_->store(cell.species, dqOut);
  }
  reportBandSolution(geo, sol, kT, out);
  out.energies.add("scc", EnergyKind::Energy,
                   energy - (sol.filling.bandEnergy - sol.filling.entropyTerm),
                   "SCC (double counting + Coulomb)");
  out.energies.add("h0", EnergyKind::Reported, h0Energy, "H0 energy Tr(rho H0)");
  out.energies.add("scc_coulomb", EnergyKind::Reported, sccEnergy, "SCC Coulomb 1/2 dq gamma dq");
  out.extras["scc_iterations"] = iterations;
  out.extras["scc_converged"] = converged ? 1.0 : 0.0;
  out.extras["scc_warm_start"] = warm ? 1.0 : 0.0;
  out.extras["scc_residual"] = residuals.back();
  out.extras["time_setup"] = std::chrono::duration<double>(t1 - t0).count();
  out.extras["time_scc_iterations"] = timeIterations;
  out.extras["time_per_scc_iteration"] = timeIterations / iterations;
  std::vector<double> populations(n), charges(n);
  for (int a = 0; a < n; ++a) {
    populations[a] = q0[a] + dqOut[a];
    charges[a] = -dqOut[a];
  }
  out.series["mulliken_populations"] = populations;
  out.series["mulliken_charges"] = charges;
  out.series["scc_history_energy"] = energies;
  out.series["scc_history_residual"] = residuals;
  if (!request.gradient && !request.strain) return;

  // W' = W - 1/2 (V_i + V_j) P with the output potential (see the header).
  const Eigen::VectorXd vOut = gamma * dqOut;
  std::vector<OrbitalBlock> wShifted(pairs.size());
  for (size_t p = 0; p < pairs.size(); ++p)
    wShifted[p] = sol.w[p] - (0.5 * (vOut[pairs[p].i] + vOut[pairs[p].j])) * sol.p[p];
  const BandDerivatives d =
      contractDerivatives(cell, params, geo.images, sol.p, wShifted, request.strain);
  const Eigen::MatrixXd weights = dqOut * dqOut.transpose();
  if (request.gradient) out.gradient = d.gradient;
  out.dEdTranslation = d.dEdTranslation;
  out.dEdTwist = d.dEdTwist;
  for (const auto& interaction : interactions_) {
    const ImagePairSum c = interaction->derivatives(cell, weights);
    if (request.gradient) out.gradient += c.gradient;
    out.dEdTranslation += c.dTranslation;
    out.dEdTwist += c.dTwist;
  }
}

}  // namespace mesochain::dftb
