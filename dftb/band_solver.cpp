#include "dftb/band_solver.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include <omp.h>

#include "common/errors.hpp"
#include "dftb/density_matrix.hpp"
#include "parallel/exact_sum.hpp"
#include "parallel/work_split.hpp"

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
  ReducedProblem<std::complex<double>> hk;  // H(k) when nothing is kept per k-point
  ReducedProblem<double> hr;
  ComplexMatrix sk, c;  // c: eigenvectors of the occupied states (OccupiedOnly)
  ComplexMatrix y, rho, rhoE;  // one k-point's Y = X diag(e) and density matrices
                               // (density_matrix.hpp; viewed as real at a real k-point)
  Eigen::MatrixXd sr, cr;
  GeneralizedEigensolver solver;
  std::vector<OrbitalBlock> p, w;  // one k-point's contribution
  Eigen::VectorXd onsite;
  parallel::ExactSum sum;  // this thread's k-points: P blocks, W blocks, on-site diagonal
  double tAssembly = 0, tSolve = 0, tVectors = 0, tProducts = 0, tDensity = 0;
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

std::vector<int> kpointOwners(const objective::HelicalKGrid& grid,
                              const parallel::Communicator& comm) {
  std::vector<double> cost;
  for (const auto& kp : grid.points()) cost.push_back(kp.realPhases ? 1.0 : 4.0);
  return parallel::balancedOwners(cost, comm.size());
}

OverlapFactors::OverlapFactors(const BandGeometry& geo, double byteBudget,
                               const parallel::Communicator& comm) {
  const auto& kpts = geo.grid.points();
  const int nk = static_cast<int>(kpts.size());
  const double n = geo.layout.total;
  const std::vector<int> owner = kpointOwners(geo.grid, comm);
  for (int k = 0; k < nk; ++k)
    if (owner[k] == comm.rank()) bytes += n * n * (kpts[k].realPhases ? 8.0 : 16.0);
  kept = bytes <= byteBudget;
  if (!kept) return;
  complex.resize(nk);
  real.resize(nk);
  ready.assign(nk, 0);
  for (int k = 0; k < nk; ++k) {
    if (owner[k] != comm.rank()) continue;
    if (kpts[k].realPhases) real[k].resize(geo.layout.total, geo.layout.total);
    else complex[k].resize(geo.layout.total, geo.layout.total);
  }
}

BandSolution solveBands(const ObjectiveCell& cell, const ParameterSet& params,
                        const BandGeometry& geo, const std::vector<OrbitalBlock>& h,
                        const Eigen::VectorXd& onsiteShift, double kT, bool density,
                        EigenvectorPath requestedPath, OverlapFactors* factors,
                        const parallel::Communicator& comm, double occupationThreshold) {
  using Mode = GeneralizedEigensolver::Mode;
  const auto& kpts = geo.grid.points();
  const int nk = static_cast<int>(kpts.size());
  const int n = geo.layout.total;
  BandSolution sol;
  sol.levels.assign(nk, Eigen::VectorXd(n));
  sol.path = resolveEigenvectorPath(requestedPath, n);
  const bool subset = sol.path == EigenvectorPath::OccupiedOnly;
  const Mode mode = !density ? Mode::ValuesOnly : subset ? Mode::OccupiedOnly : Mode::AllVectors;
  if (factors && !(factors->kept && static_cast<int>(factors->ready.size()) == nk)) factors = nullptr;
  sol.weights.resize(nk);
  bool anyReal = false;
  for (int k = 0; k < nk; ++k) {
    sol.weights[k] = kpts[k].weight;
    anyReal = anyReal || kpts[k].realPhases;
  }
  // The k-points of this rank, ascending.
  const std::vector<int> owner = kpointOwners(geo.grid, comm);
  std::vector<int> mine;
  for (int k = 0; k < nk; ++k)
    if (owner[k] == comm.rank()) mine.push_back(k);
  const int nMine = static_cast<int>(mine.size());
  // With density, every k-point keeps its eigenvectors (AllVectors) or its tridiagonal form
  // (OccupiedOnly) until the Fermi level is known; without, LAPACK is asked for eigenvalues
  // alone and nothing is kept.
  std::vector<ReducedProblem<std::complex<double>>> keptComplex(density ? nk : 0);
  std::vector<ReducedProblem<double>> keptReal(density ? nk : 0);
  for (int k : mine)
    if (density) kpts[k].realPhases ? keptReal[k].resize(n) : keptComplex[k].resize(n);
  const int nThreads = std::max(1, std::min(omp_get_max_threads(), std::max(1, nMine)));
  const std::size_t blockSize = OrbitalBlock::SizeAtCompileTime;
  const std::size_t nPairs = geo.images.pairs().size();
  std::vector<ThreadWork> work(nThreads);
  for (auto& w : work) {
    w.sk.resize(n, n);
    if (!density) w.hk.resize(n);
    w.solver.resize(n);
    if (anyReal) {
      if (!density) w.hr.resize(n);
      w.sr.resize(n, n);
    }
    if (density) {
      w.y.resize(n, n);
      w.rho.resize(n, n);
      w.rhoE.resize(n, n);
      if (subset) {
        w.c.resize(n, n);
        if (anyReal) w.cr.resize(n, n);
      }
      w.p.assign(geo.images.pairs().size(), OrbitalBlock::Zero());
      w.w.assign(geo.images.pairs().size(), OrbitalBlock::Zero());
      w.onsite = Eigen::VectorXd::Zero(n);
      w.sum.resize(2 * nPairs * blockSize + n);
    }
  }
  const auto t1 = Clock::now();

  // Pass 1: assembly, the standard problem, all eigenvalues.
  std::string failure;
  {
    BlasThreadsOff blasOff;
#pragma omp parallel for num_threads(nThreads) schedule(dynamic)
    for (int i = 0; i < nMine; ++i) {
      const int k = mine[i];
      ThreadWork& w = work[omp_get_thread_num()];
      const HelicalKPoint& kp = kpts[k];
      try {
        const auto a = Clock::now();
        const bool reuse = factors && factors->ready[k];
        if (kp.realPhases) {
          auto& hr = density ? keptReal[k] : w.hr;
          assembleBlochReal(cell, params, geo.layout, geo.images, h, geo.s, geo.grid, kp, hr.a,
                            w.sr, onsiteShift);
          const auto b = Clock::now();
          w.solver.reduce(hr, w.sr, reuse ? &factors->real[k] : nullptr, sol.levels[k], mode,
                          "band structure (real k-point)");
          if (factors && !reuse) factors->real[k].triangularView<Eigen::Lower>() = w.sr;
          w.tAssembly += seconds(a, b);
          w.tSolve += seconds(b, Clock::now());
        } else {
          auto& hk = density ? keptComplex[k] : w.hk;
          assembleBloch(cell, params, geo.layout, geo.images, h, geo.s, geo.grid, kp, hk.a, w.sk,
                        onsiteShift);
          const auto b = Clock::now();
          w.solver.reduce(hk, w.sk, reuse ? &factors->complex[k] : nullptr, sol.levels[k], mode,
                          "band structure");
          if (factors && !reuse) factors->complex[k].triangularView<Eigen::Lower>() = w.sk;
          w.tAssembly += seconds(a, b);
          w.tSolve += seconds(b, Clock::now());
        }
        if (factors && !reuse) factors->ready[k] = 1;
      } catch (const std::exception& e) {
#pragma omp critical
        failure = std::string(e.what()) + " (kappa = " + std::to_string(kp.kappa) +
                  ", mu = " + std::to_string(kp.mu) + ")";
      }
    }
  }
  failure = comm.firstFailure(failure);
  if (!failure.empty()) throw NumericalError(failure);
  if (comm.size() > 1) {
    // Every rank's levels, in rank order and within a rank by ascending k.
    std::vector<double> levels;
    levels.reserve(static_cast<std::size_t>(nMine) * n);
    for (int k : mine) levels.insert(levels.end(), sol.levels[k].data(), sol.levels[k].data() + n);
    const std::vector<double> all = comm.allgather(levels);
    std::size_t at = 0;
    for (int r = 0; r < comm.size(); ++r)
      for (int k = 0; k < nk; ++k)
        if (owner[k] == r) {
          sol.levels[k] = Eigen::Map<const Eigen::VectorXd>(all.data() + at, n);
          at += n;
        }
  }
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

  // Pass 2: the eigenvectors of the states that carry charge (OccupiedOnly), then the density
  // and energy-weighted density folded onto the image pairs.
  sol.statesUsed.assign(nk, 0);
  const DensityBlockPlan plan(geo.layout, geo.images);
  {
    BlasThreadsOff blasOff;
#pragma omp parallel for num_threads(nThreads) schedule(dynamic)
    for (int i = 0; i < nMine; ++i) {
      const int k = mine[i];
      ThreadWork& w = work[omp_get_thread_num()];
      try {
        const Eigen::VectorXd& f = sol.filling.occupations[k];
        const Eigen::VectorXd& e = sol.levels[k];
        const int m = occupiedStateCount(e, f, occupationThreshold);
        sol.statesUsed[k] = m;
        const auto a = Clock::now();
        Clock::time_point b, d;  // vectors | BLAS-3 products | folding and exact sums
        // The occupied columns (scaled in place into X: nothing reads them afterwards), and Y,
        // rho, rho^E in the thread's buffers (viewed as real ones at a real k-point).
        if (kpts[k].realPhases) {
          if (subset) w.solver.lowestVectors(keptReal[k], m, w.cr, "band structure (real k-point)");
          Eigen::MatrixXd& c = subset ? w.cr : keptReal[k].a;
          b = Clock::now();
          MatrixMap<double> rho(reinterpret_cast<double*>(w.rho.data()), n, n);
          MatrixMap<double> rhoE(reinterpret_cast<double*>(w.rhoE.data()), n, n);
          MatrixMap<double> y(reinterpret_cast<double*>(w.y.data()), n, m);
          formDensityMatrices<double>(plan, MatrixMap<double>(c.data(), n, m), y, m, f, e, rho,
                                      rhoE);
          d = Clock::now();
          foldDensityBlocks<double>(plan, geo.layout, geo.images, geo.grid, kpts[k],
                                    sol.weights[k], rho, rhoE, w.p, w.w);
          w.onsite.noalias() = sol.weights[k] * rho.diagonal();
        } else {
          if (subset) w.solver.lowestVectors(keptComplex[k], m, w.c, "band structure");
          ComplexMatrix& c = subset ? w.c : keptComplex[k].a;
          b = Clock::now();
          MatrixMap<std::complex<double>> rho(w.rho.data(), n, n), rhoE(w.rhoE.data(), n, n);
          formDensityMatrices<std::complex<double>>(
              plan, MatrixMap<std::complex<double>>(c.data(), n, m),
              MatrixMap<std::complex<double>>(w.y.data(), n, m), m, f, e, rho, rhoE);
          d = Clock::now();
          foldDensityBlocks<std::complex<double>>(plan, geo.layout, geo.images, geo.grid, kpts[k],
                                                  sol.weights[k], rho, rhoE, w.p, w.w);
          w.onsite.noalias() = sol.weights[k] * rho.diagonal().real();
        }
        // This k-point's contribution into the thread's exact sum.
        for (std::size_t p = 0; p < nPairs; ++p) {
          w.sum.add(p * blockSize, w.p[p].data(), blockSize);
          w.sum.add((nPairs + p) * blockSize, w.w[p].data(), blockSize);
        }
        w.sum.add(2 * nPairs * blockSize, w.onsite.data(), n);
        w.tVectors += seconds(a, b);
        w.tProducts += seconds(b, d);
        w.tDensity += seconds(d, Clock::now());
      } catch (const std::exception& e) {
#pragma omp critical
        failure = std::string(e.what()) + " (kappa = " + std::to_string(kpts[k].kappa) +
                  ", mu = " + std::to_string(kpts[k].mu) + ")";
      }
    }
  }
  failure = comm.firstFailure(failure);
  if (!failure.empty()) throw NumericalError(failure);
  // Threads, then ranks: integer sums, the same bits in any grouping.
  parallel::ExactSum& total = work[0].sum;
  for (int t = 1; t < nThreads; ++t) total.add(work[t].sum);
  comm.sumInPlace(total.limbs());
  for (std::size_t p = 0; p < nPairs; ++p) {
    for (std::size_t e = 0; e < blockSize; ++e) {
      work[0].p[p].data()[e] = total.value(p * blockSize + e);
      work[0].w[p].data()[e] = total.value((nPairs + p) * blockSize + e);
    }
  }
  for (int e = 0; e < n; ++e) work[0].onsite[e] = total.value(2 * nPairs * blockSize + e);
  if (comm.size() > 1) {
    std::vector<double> used;
    for (int k : mine) used.push_back(sol.statesUsed[k]);
    const std::vector<double> all = comm.allgather(used);
    std::size_t at = 0;
    for (int r = 0; r < comm.size(); ++r)
      for (int k = 0; k < nk; ++k)
        if (owner[k] == r) sol.statesUsed[k] = static_cast<int>(all[at++]);
  }
  double tV = 0, tP = 0, tD = 0;
  for (const auto& w : work) {
    tV += w.tVectors;
    tP += w.tProducts;
    tD += w.tDensity;
  }
  sol.p = std::move(work[0].p);
  sol.w = std::move(work[0].w);
  sol.onsiteDensity = std::move(work[0].onsite);
  const double pass2 = seconds(t3, Clock::now());
  const double tPass2 = tV + tP + tD;
  sol.timeEigensolver += tPass2 > 0 ? pass2 * tV / tPass2 : 0.0;
  sol.timeDensityProducts = tPass2 > 0 ? pass2 * tP / tPass2 : 0.0;
  sol.timeDensity = tPass2 > 0 ? pass2 * (tP + tD) / tPass2 : pass2;
  return sol;
}

}  // namespace mesochain::dftb
