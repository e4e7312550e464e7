// The density matrices of one k-point from the occupied columns (dftb/density_matrix.hpp), and
// the stability of the occupied-column selection when the occupation cut falls inside an exactly
// degenerate level (dftb/eigensolver.hpp: occupiedStateCount, used by dftb/band_solver.cpp).
#include <cmath>
#include <complex>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "dftb/band_solver.hpp"
#include "dftb/density_matrix.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "support.hpp"

using namespace mesochain;
using cd = std::complex<double>;
template <class T>
using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

namespace {
// rho = sum_n f_n c_n c_n^+ and rho^E = sum_n f_n e_n c_n c_n^+ term by term (the definition),
// against the block products, on a plan of three groups (of 16, 14 and 7 orbitals) with every
// block on and below the diagonal.
template <class T>
void expectDefinition(unsigned seed) {
  const int n = 37, m = 23;
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 2.0);
  Matrix<T> c(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if constexpr (std::is_same_v<T, cd>) c(i, j) = cd(g(rng), g(rng));
      else c(i, j) = g(rng);
    }
  Eigen::VectorXd e(n), f(n);
  for (int s = 0; s < n; ++s) {
    e[s] = -0.6 + 0.05 * s;  // ascending, changing sign at s = 12 (one level exactly zero)
    f[s] = s < m ? u(rng) : 0.0;
  }
  Matrix<T> rho = Matrix<T>::Zero(n, n), rhoE = Matrix<T>::Zero(n, n);
  for (int s = 0; s < m; ++s) {
    rho += f[s] * c.col(s) * c.col(s).adjoint();
    rhoE += f[s] * e[s] * c.col(s) * c.col(s).adjoint();
  }
  dftb::DensityBlockPlan plan;
  plan.groupStart = {0, 16, 30, n};
  for (int i = 0; i < n; ++i) plan.groupOfOrbital.push_back(i < 16 ? 0 : i < 30 ? 1 : 2);
  plan.blocks = {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}};
  Matrix<T> work = c, y(n, n), outRho(n, n), outRhoE(n, n);
  dftb::formDensityMatrices<T>(plan, dftb::MatrixMap<T>(work.data(), n, m),
                               dftb::MatrixMap<T>(y.data(), n, m), m, f, e,
                               dftb::MatrixMap<T>(outRho.data(), n, n),
                               dftb::MatrixMap<T>(outRhoE.data(), n, n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (plan.groupOfOrbital[i] < plan.groupOfOrbital[j]) continue;  // above the blocks
      EXPECT_LT(std::abs(outRho(i, j) - rho(i, j)), 1e-12) << i << "," << j;
      EXPECT_LT(std::abs(outRhoE(i, j) - rhoE(i, j)), 1e-12) << i << "," << j;
    }
}

double largestDifference(const std::vector<dftb::OrbitalBlock>& a,
                         const std::vector<dftb::OrbitalBlock>& b) {
  double d = 0;
  for (std::size_t p = 0; p < a.size(); ++p) d = std::max(d, (a[p] - b[p]).cwiseAbs().maxCoeff());
  return d;
}
}  // namespace

TEST(DensityMatrices, BlockProductsEqualTheDefinitionWithLevelsOfBothSigns) {
  expectDefinition<double>(3);
  expectDefinition<cd>(4);
}

TEST(DensityMatrices, CutInsideAnExactlyDegenerateLevelNeverSplitsIt) {
  // A metallic zigzag (12,0) tube as its 48-atom translational cell without the rotation, 5 kappa
  // points (kappa = 0 among them), 30 K. At kappa = 0 the bands that cross the Fermi level
  // (a pair of angular momenta +-mu, folded onto one k) are exactly twofold degenerate; the
  // curvature gap leaves the lower pair nearly full and the upper pair with occupation ~6e-7, its two members'
  // occupations differing only by rounding. A threshold between those two occupations cuts the
  // level in two; the count is extended over the whole level, so the vectors entering the
  // density, and hence P and W, are the same as with the threshold just below the level.
  // (An armchair tube has no such level near the Fermi level: its crossing bands are not
  // degenerate, and in the (5,5) cell the nearest degenerate levels are over 1.3 eV away, with
  // occupations below 1e-60 at 100 K, far too small for a split to show.)
  const double bond = 1.42 * units::kAngstromInBohr;
  const auto cell = objective::buildNanotubeTranslational(12, 0, bond, false);
  const auto& params = *mesochain::testing::carbonParameters();
  const dftb::BandGeometry geo(cell, params, 5, objective::AngularSampling{});
  const double kT = 30 * units::kBoltzmannHartreePerKelvin;
  const auto ref = dftb::solveBands(cell, params, geo, geo.h0, {}, kT, true);
  // The partially filled degenerate pair.
  int kd = -1, first = -1;
  for (std::size_t k = 0; k < ref.levels.size() && kd < 0; ++k)
    for (int s = 0; s + 1 < ref.levels[k].size(); ++s) {
      const double f = ref.filling.occupations[k][s];
      if (f > 1e-9 && f < 1e-3 && ref.levels[k][s + 1] - ref.levels[k][s] < 1e-12) {
        kd = static_cast<int>(k);
        first = s;
        break;
      }
    }
  ASSERT_GE(kd, 0) << "no partially filled degenerate pair";
  const Eigen::VectorXd& e = ref.levels[kd];
  const Eigen::VectorXd& f = ref.filling.occupations[kd];
  const double fHigh = f[first], fLow = f[first + 1];
  ASSERT_GT(fHigh, fLow) << "the pair's occupations must differ by rounding for a cut inside it";
  // The threshold fLow cuts between the two members without the degeneracy extension ...
  EXPECT_EQ(dftb::occupiedStateCount(e, f, fLow, 0.0), first + 1);
  // ... and the extension takes the whole level.
  EXPECT_EQ(dftb::occupiedStateCount(e, f, fLow), first + 2);
  const double below = std::nextafter(fLow, 0.0);
  const double above = std::nextafter(fHigh, 2.0);
  const auto serial = parallel::Communicator::serial();
  for (auto path : {dftb::EigenvectorPath::AllVectors, dftb::EigenvectorPath::OccupiedOnly}) {
    auto solve = [&](double threshold) {
      return dftb::solveBands(cell, params, geo, geo.h0, {}, kT, true, path, nullptr, serial,
                              threshold);
    };
    const auto whole = solve(below);
    EXPECT_EQ(whole.statesUsed[kd], first + 2);
    for (double t : {fLow, 0.5 * (fLow + fHigh)}) {
      const auto cut = solve(t);
      EXPECT_EQ(cut.statesUsed, whole.statesUsed) << "threshold " << t;
      EXPECT_EQ(largestDifference(cut.p, whole.p), 0.0) << "threshold " << t;
      EXPECT_EQ(largestDifference(cut.w, whole.w), 0.0) << "threshold " << t;
      EXPECT_EQ((cut.onsiteDensity - whole.onsiteDensity).cwiseAbs().maxCoeff(), 0.0);
    }
    // Above the level the whole pair is left out: its share of P is resolvable, so a split
    // level (half of it) would have shown above.
    const auto without = solve(above);
    EXPECT_EQ(without.statesUsed[kd], first);
    EXPECT_GT(largestDifference(without.p, whole.p), 1e-10);
  }
}
