#include "dftb/band_structure.hpp"

#include <chrono>
#include <string>
#include <vector>

#include <omp.h>

#include "common/errors.hpp"
#include "dftb/bloch.hpp"
#include "dftb/fermi.hpp"

// OpenBLAS's own threads would compete with the k-point threads; switch them off while the
// k loop runs (weak: absent when another BLAS is in use).
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
extern "C" int openblas_get_num_threads() __attribute__((weak));

namespace mesochain::dftb {

using objective::HelicalKGrid;
using objective::HelicalKPoint;
using objective::ImageList;
using objective::ObjectiveCell;
using Clock = std::chrono::steady_clock;

namespace {
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

struct BlasThreadsOff {
  int saved = 0;
  BlasThreadsOff() {
    if (openblas_get_num_threads && openblas_set_num_threads) {
      saved = openblas_get_num_threads();
      openblas_set_num_threads(1);
    }
  }
  ~BlasThreadsOff() {
    if (saved > 0) openblas_set_num_threads(saved);
  }
};

// Buffers of one thread, sized once before the k loop.
struct ThreadWork {
  ComplexMatrix hk, sk, x, y;  // hk: H(k) when the eigenvectors are not kept
  Eigen::MatrixXd hr, sr;
  GeneralizedEigensolver solver;
  std::vector<OrbitalBlock> p, w;
  double tAssembly = 0, tSolve = 0, tDensity = 0;
};
}  // namespace

BandStructureTerm::BandStructureTerm(std::shared_ptr<const ParameterSet> params,
                                     BandSettings settings)
    : params_(std::move(params)), settings_(settings) {
  if (!(settings_.electronicTemperature > 0.0))
    throw InputError("<electrons>", "electrons.temperature",
                     std::to_string(settings_.electronicTemperature), "a positive temperature");
}

void BandStructureTerm::evaluate(const ObjectiveCell& cell, const EvaluationRequest& request,
                                 TermOutput& out) const {
  const ParameterSet& params = *params_;
  const auto t0 = Clock::now();
  const OrbitalLayout layout(cell, params);
  const ImageList images(cell, params.integralCutoff());
  std::vector<OrbitalBlock> hBlocks, sBlocks;
  computeRealSpaceBlocks(cell, params, images, hBlocks, sBlocks);
  const HelicalKGrid grid(cell.symmetry, settings_.helicalKPoints, settings_.angular);
  const auto& kpts = grid.points();
  const int nk = static_cast<int>(kpts.size());
  const int n = layout.total;
  double electrons = 0.0;
  for (int a = 0; a < cell.atomCount(); ++a)
    electrons += params.species(cell.species[a]).valenceElectrons;

  std::vector<Eigen::VectorXd> levels(nk, Eigen::VectorXd(n));
  // Eigenvectors are needed only for the density matrices (gradient or strain derivatives);
  // an energy-only evaluation asks LAPACK for eigenvalues alone.
  const bool wantDensity = request.gradient || request.strain;
  std::vector<ComplexMatrix> vectors(wantDensity ? nk : 0, ComplexMatrix(n, n));
  std::vector<double> weights(nk);
  bool anyReal = false;
  for (int k = 0; k < nk; ++k) {
    weights[k] = kpts[k].weight;
    anyReal = anyReal || kpts[k].realPhases;
  }
  const int nThreads = std::max(1, std::min(omp_get_max_threads(), nk));
  std::vector<ThreadWork> work(nThreads);
  for (auto& w : work) {
    w.sk.resize(n, n);
    if (!wantDensity) w.hk.resize(n, n);
    w.solver.resize(n);
    if (anyReal) {
      w.hr.resize(n, n);
      w.sr.resize(n, n);
    }
    if (wantDensity) {
      w.x.resize(n, n);
      w.y.resize(n, n);
      w.p.assign(images.pairs().size(), OrbitalBlock::Zero());
      w.w.assign(images.pairs().size(), OrbitalBlock::Zero());
    }
  }
  const auto t1 = Clock::now();

  std::string failure;
  {
    BlasThreadsOff blasOff;
#pragma omp parallel for num_threads(nThreads) schedule(dynamic)
    for (int k = 0; k < nk; ++k) {
      ThreadWork& w = work[omp_get_thread_num()];
      const HelicalKPoint& kp = kpts[k];
      try {
        const auto a = Clock::now();
        if (kp.realPhases) {
          assembleBlochReal(cell, params, layout, images, hBlocks, sBlocks, grid, kp, w.hr, w.sr);
          const auto b = Clock::now();
          w.solver.solveReal(w.hr, w.sr, levels[k], wantDensity, "band structure (real k-point)");
          if (wantDensity) vectors[k] = w.hr.cast<std::complex<double>>();
          w.tAssembly += seconds(a, b);
          w.tSolve += seconds(b, Clock::now());
        } else {
          ComplexMatrix& hk = wantDensity ? vectors[k] : w.hk;
          assembleBloch(cell, params, layout, images, hBlocks, sBlocks, grid, kp, hk, w.sk);
          const auto b = Clock::now();
          w.solver.solveComplex(hk, w.sk, levels[k], wantDensity, "band structure");
          w.tAssembly += seconds(a, b);
          w.tSolve += seconds(b, Clock::now());
        }
      } catch (const std::exception& e) {
#pragma omp critical
        failure = std::string(e.what()) + " (kappa = " + std::to_string(kp.kappa) +
                  ", mu = " + std::to_string(kp.mu) + ")";
      }
    }
  }
  if (!failure.empty()) throw NumericalError(failure);
  const auto t2 = Clock::now();

  const Filling filling =
      fillFermiDirac(levels, weights, electrons, settings_.electronicTemperature);
  const auto t3 = Clock::now();

  out.energy = filling.bandEnergy - filling.entropyTerm;
  if (grid.angularSampled() && grid.angularCount() >= 2) {
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
          lv.push_back(levels[k]);
          wt.push_back(weights[k]);
          sum += weights[k];
        }
      for (double& x : wt) x /= sum;
      const Filling f = fillFermiDirac(lv, wt, electrons, settings_.electronicTemperature);
      half[parity] = f.bandEnergy - f.entropyTerm;
    }
    out.extras["angular_sampling_error_estimate"] = 0.5 * std::abs(half[0] - half[1]);
  }
  out.extras["band_energy"] = filling.bandEnergy;
  out.extras["entropy_term"] = filling.entropyTerm;
  out.extras["fermi_level"] = filling.fermiLevel;
  out.extras["homo"] = filling.highestOccupied;
  out.extras["lumo"] = filling.lowestUnoccupied;
  out.extras["electrons"] = electrons;
  out.extras["kpoints"] = nk;
  out.extras["orbitals"] = n;
  out.extras["image_pairs"] = static_cast<double>(images.pairs().size());
  out.extras["time_setup"] = seconds(t0, t1);
  out.extras["time_filling"] = seconds(t2, t3);
  double tA = 0, tS = 0;
  for (const auto& w : work) {
    tA += w.tAssembly;
    tS += w.tSolve;
  }
  // Thread-time shares scaled to the wall time of the k loop.
  const double loop = seconds(t1, t2);
  out.extras["time_assembly"] = (tA + tS) > 0 ? loop * tA / (tA + tS) : 0.0;
  out.extras["time_eigensolver"] = (tA + tS) > 0 ? loop * tS / (tA + tS) : 0.0;
  if (!wantDensity) return;

  // Density and energy-weighted density folded onto the image pairs.
  {
    BlasThreadsOff blasOff;
#pragma omp parallel for num_threads(nThreads) schedule(dynamic)
    for (int k = 0; k < nk; ++k) {
      ThreadWork& w = work[omp_get_thread_num()];
      const Eigen::VectorXd& f = filling.occupations[k];
      const Eigen::VectorXd& e = levels[k];
      int nocc = 0;
      while (nocc < n && f[nocc] > 1e-15) ++nocc;  // ascending levels: occupations decrease
      const auto& c = vectors[k];
      w.x.leftCols(nocc).noalias() = c.leftCols(nocc) * f.head(nocc).cwiseSqrt().asDiagonal();
      w.y.leftCols(nocc).noalias() = w.x.leftCols(nocc) * e.head(nocc).asDiagonal();
      accumulateDensityBlocks(layout, images, grid, kpts[k], weights[k], w.x.leftCols(nocc),
                              w.y.leftCols(nocc), w.p, w.w);
    }
  }
  for (int t = 1; t < nThreads; ++t)
    for (size_t p = 0; p < work[0].p.size(); ++p) {
      work[0].p[p] += work[t].p[p];
      work[0].w[p] += work[t].w[p];
    }
  const auto t4 = Clock::now();
  const BandDerivatives d =
      contractDerivatives(cell, params, images, work[0].p, work[0].w, request.strain);
  if (request.gradient) out.gradient = d.gradient;
  out.dEdTranslation = d.dEdTranslation;
  out.dEdTwist = d.dEdTwist;
  out.extras["time_density"] = seconds(t3, t4);
  out.extras["time_forces"] = seconds(t4, Clock::now());
}

}  // namespace mesochain::dftb
