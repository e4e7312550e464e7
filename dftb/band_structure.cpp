#include "dftb/band_structure.hpp"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "common/electronic_temperature.hpp"
#include "common/errors.hpp"
#include "dftb/band_solver.hpp"
#include "dftb/bloch.hpp"
#include "dftb/calculator.hpp"
#include "dftb/fermi.hpp"
#include "dftb/term_registry.hpp"

namespace mesochain::dftb {

using objective::ObjectiveCell;
using Clock = std::chrono::steady_clock;

BandStructureTerm::BandStructureTerm(std::shared_ptr<const ParameterSet> params,
                                     BandSettings settings, parallel::Communicator comm)
    : params_(std::move(params)), settings_(settings), comm_(std::move(comm)) {
  validate(settings_);
}

void validate(const BandSettings& settings) {
  requireElectronicTemperature(settings.electronicTemperature, "the calculator settings",
                               "band.electronic_temperature_hartree");
}

void reportBandSolution(const BandGeometry& geo, const BandSolution& sol, double kT,
                        TermOutput& out) {
  const auto& kpts = geo.grid.points();
  const int nk = static_cast<int>(kpts.size());
  if (geo.grid.angularSampled() && geo.grid.angularCount() >= 2) {
    // Error estimate of the sampled angular sum: the free energies of the two interleaved half
    // grids (even and odd sample index), each filled on its own, differ by more than the error
    // of the full set for a smooth integrand; half their difference is reported.
    double half[2];
    for (int parity = 0; parity < 2; ++parity) {
      std::vector<Eigen::VectorXd> lv;
      std::vector<double> wt;
      double sum = 0;
      for (int k = 0; k < nk; ++k)
        if (kpts[k].angularIndex % 2 == parity) {
          lv.push_back(sol.levels[k]);
          wt.push_back(sol.weights[k]);
          sum += sol.weights[k];
        }
      for (double& x : wt) x /= sum;
      const Filling f = fillFermiDirac(lv, wt, geo.electrons, kT);
      half[parity] = f.bandEnergy - f.entropyTerm;
    }
    out.energies.add("angular_sampling_error_estimate", EnergyKind::Reported,
                     0.5 * std::abs(half[0] - half[1]));
  }
  const Filling& filling = sol.filling;
  out.energies.add("band", EnergyKind::Energy, filling.bandEnergy);
  out.energies.add("entropy_term_ts", EnergyKind::Entropy, filling.entropyTerm, "-TS");
  out.extras["fermi_level"] = filling.fermiLevel;
  out.extras["homo"] = filling.highestOccupied;
  out.extras["lumo"] = filling.lowestUnoccupied;
  out.extras["electrons"] = geo.electrons;
  out.extras["kpoints"] = nk;
  out.extras["orbitals"] = geo.layout.total;
  out.extras["image_pairs"] = static_cast<double>(geo.images.pairs().size());
  // The levels per k-point (Hartree, ascending; k-point major, `orbitals` per point) and the
  // points (kappa, mu, filling weight), for band output (the Python module's Result.eigenvalues).
  std::vector<double> levels, kappa, mu, weight;
  levels.reserve(static_cast<std::size_t>(nk) * static_cast<std::size_t>(geo.layout.total));
  for (int k = 0; k < nk; ++k) {
    levels.insert(levels.end(), sol.levels[k].data(), sol.levels[k].data() + sol.levels[k].size());
    kappa.push_back(kpts[k].kappa);
    mu.push_back(kpts[k].mu);
    weight.push_back(sol.weights[k]);
  }
  out.series["eigenvalues"] = std::move(levels);
  out.series["kpoint_kappa"] = std::move(kappa);
  out.series["kpoint_mu"] = std::move(mu);
  out.series["kpoint_weight"] = std::move(weight);
}

void BandStructureTerm::evaluate(const ObjectiveCell& cell, const EvaluationRequest& request,
                                 TermOutput& out) const {
  const ParameterSet& params = *params_;
  const auto t0 = Clock::now();
  const BandGeometry geo(cell, params, settings_.helicalKPoints, settings_.angular);
  const auto t1 = Clock::now();
  const bool wantDensity = request.gradient || request.strain;
  const BandSolution sol = solveBands(cell, params, geo, geo.h0, Eigen::VectorXd(),
                                      settings_.electronicTemperature, wantDensity,
                                      settings_.eigenvectors, nullptr, comm_);
  reportBandSolution(geo, sol, settings_.electronicTemperature, out);
  out.extras["time_setup"] = std::chrono::duration<double>(t1 - t0).count();
  out.extras["time_filling"] = sol.timeFilling;
  out.extras["time_assembly"] = sol.timeAssembly;
  out.extras["time_eigensolver"] = sol.timeEigensolver;
  if (!wantDensity) return;
  const auto t4 = Clock::now();
  const BandDerivatives d =
      contractDerivatives(cell, params, geo.images, sol.p, sol.w, request.strain);
  if (request.gradient) out.gradient = d.gradient;
  out.dEdTranslation = d.dEdTranslation;
  out.dEdTwist = d.dEdTwist;
  out.extras["time_density"] = sol.timeDensity;
  out.extras["time_density_products"] = sol.timeDensityProducts;
  out.extras["time_forces"] = std::chrono::duration<double>(Clock::now() - t4).count();
}

// The band term is always built; with charge interactions (SCC) it is the self-consistent one.
MESOCHAIN_DFTB_TERM(TermRegistration{
    "band", 100,
    "band structure: Mermin free energy of the helical k-point filling (self-consistent with "
    "the charge interactions when there are any)",
    false, [](const CalculatorSettings&) { return true; },
    [](const TermBuild& b) -> std::unique_ptr<EnergyTerm> {
      if (b.chargeInteractions.empty())
        return std::make_unique<BandStructureTerm>(b.params, b.settings.band, b.comm);
      return std::make_unique<SccBandStructureTerm>(b.params, b.settings.band, b.settings.scc,
                                                    b.chargeInteractions, b.chargeCache, b.comm);
    },
    nullptr})

}  // namespace mesochain::dftb
