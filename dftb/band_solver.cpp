#include "dftb/band_solver.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include <omp.h>

#include "common/errors.hpp"

// OpenBLAS's own threads would compete with the k-point threads; switch them off while the
// k loop runs (weak: absent when another BLAS is in use).
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
extern "C" int openblas_get_num_threads() __attribute__((weak));

namespace mesochain::dftb {

using objective::HelicalKPoint;
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
  Eigen::VectorXd onsite;
  double tAssembly = 0, tSolve = 0;
};
}  // namespace

BandGeometry::BandGeometry(const ObjectiveCell& cell, const ParameterSet& params, int nKappa,
                           objective::AngularSampling angular)
    : layout(cell, params),
      images(cell, params.integralCutoff()),
      grid(cell.symmetry, nKappa, angular) {
  computeRealSpaceBlocks(cell, params, images, h0, s);
  for (int a = 0; a < cell.atomCount(); ++a)
    electrons += params.species(cell.species[a]).valenceElectrons;
}

BandSolution solveBands(const ObjectiveCell& cell, const ParameterSet& params,
                        const BandGeometry& geo, const std::vector<OrbitalBlock>& h,
                        const Eigen::VectorXd& onsiteShift, double kT, bool density) {
  const auto& kpts = geo.grid.points();
  const int nk = static_cast<int>(kpts.size());
  const int n = geo.layout.total;
  BandSolution sol;
  sol.levels.assign(nk, Eigen::VectorXd(n));
  // Eigenvectors are needed only for the density matrices; without them LAPACK is asked for
  // eigenvalues alone.
  std::vector<ComplexMatrix> vectors(density ? nk : 0, ComplexMatrix(n, n));
  sol.weights.resize(nk);
  bool anyReal = false;
  for (int k = 0; k < nk; ++k) {
    sol.weights[k] = kpts[k].weight;
    anyReal = anyReal || kpts[k].realPhases;
  }
  const int nThreads = std::max(1, std::min(omp_get_max_threads(), nk));
  std::vector<ThreadWork> work(nThreads);
  for (auto& w : work) {
    w.sk.resize(n, n);
    if (!density) w.hk.resize(n, n);
    w.solver.resize(n);
    if (anyReal) {
      w.hr.resize(n, n);
      w.sr.resize(n, n);
    }
    if (density) {
      w.x.resize(n, n);
      w.y.resize(n, n);
      w.p.assign(geo.images.pairs().size(), OrbitalBlock::Zero());
      w.w.assign(geo.images.pairs().size(), OrbitalBlock::Zero());
      w.onsite = Eigen::VectorXd::Zero(n);
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
          assembleBlochReal(cell, params, geo.layout, geo.images, h, geo.s, geo.grid, kp, w.hr,
                            w.sr, onsiteShift);
          const auto b = Clock::now();
          w.solver.solveReal(w.hr, w.sr, sol.levels[k], density, "band structure (real k-point)");
          if (density) vectors[k] = w.hr.cast<std::complex<double>>();
          w.tAssembly += seconds(a, b);
          w.tSolve += seconds(b, Clock::now());
        } else {
          ComplexMatrix& hk = density ? vectors[k] : w.hk;
          assembleBloch(cell, params, geo.layout, geo.images, h, geo.s, geo.grid, kp, hk, w.sk,
                        onsiteShift);
          const auto b = Clock::now();
          w.solver.solveComplex(hk, w.sk, sol.levels[k], density, "band structure");
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
  sol.filling = fillFermiDirac(sol.levels, sol.weights, geo.electrons, kT);
  const auto t3 = Clock::now();
  sol.timeFilling = seconds(t2, t3);
  double tA = 0, tS = 0;
  for (const auto& w : work) {
    tA += w.tAssembly;
    tS += w.tSolve;
  }
  // Thread-time shares scaled to the wall time of the k loop.
  const double loop = seconds(t1, t2);
  sol.timeAssembly = (tA + tS) > 0 ? loop * tA / (tA + tS) : 0.0;
  sol.timeEigensolver = (tA + tS) > 0 ? loop * tS / (tA + tS) : 0.0;
  if (!density) return sol;

  // Density and energy-weighted density folded onto the image pairs.
  {
    BlasThreadsOff blasOff;
#pragma omp parallel for num_threads(nThreads) schedule(dynamic)
    for (int k = 0; k < nk; ++k) {
      ThreadWork& w = work[omp_get_thread_num()];
      const Eigen::VectorXd& f = sol.filling.occupations[k];
      const Eigen::VectorXd& e = sol.levels[k];
      int nocc = 0;
      while (nocc < n && f[nocc] > 1e-15) ++nocc;  // ascending levels: occupations decrease
      const auto& c = vectors[k];
      w.x.leftCols(nocc).noalias() = c.leftCols(nocc) * f.head(nocc).cwiseSqrt().asDiagonal();
      w.y.leftCols(nocc).noalias() = w.x.leftCols(nocc) * e.head(nocc).asDiagonal();
      accumulateDensityBlocks(geo.layout, geo.images, geo.grid, kpts[k], sol.weights[k],
                              w.x.leftCols(nocc), w.y.leftCols(nocc), w.p, w.w);
      w.onsite += sol.weights[k] * w.x.leftCols(nocc).rowwise().squaredNorm();
    }
  }
  for (int t = 1; t < nThreads; ++t) {
    for (size_t p = 0; p < work[0].p.size(); ++p) {
      work[0].p[p] += work[t].p[p];
      work[0].w[p] += work[t].w[p];
    }
    work[0].onsite += work[t].onsite;
  }
  sol.p = std::move(work[0].p);
  sol.w = std::move(work[0].w);
  sol.onsiteDensity = std::move(work[0].onsite);
  sol.timeDensity = seconds(t3, Clock::now());
  return sol;
}

}  // namespace mesochain::dftb
