// The SCC gamma functional (Elstner et al., PRB 58, 7260 (1998)) against its analytic limits,
// its derivative against finite differences, and the image sums against explicit copies.
#include <cmath>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "dftb/coulomb_lattice_sum.hpp"
#include "dftb/gamma_functional.hpp"
#include "scc_support.hpp"

using namespace mesochain;
using namespace mesochain::dftb;

TEST(GammaFunctional, OnsiteLimitIsHubbardU) {
  // r -> 0 with equal U: gamma -> U (tau = 16/5 U gives 5 tau / 16).
  for (double u : {0.3647, 0.4195})
    EXPECT_NEAR(gammaValue(1e-5, u, u), u, 1e-5 * u) << u;
}

TEST(GammaFunctional, UnequalLimitMatchesClosedForm) {
  // r -> 0, tau_a != tau_b: gamma -> 1/2 [t_a t_b/(t_a + t_b) + t_a^2 t_b^2/(t_a + t_b)^3].
  const double ua = 0.3647, ub = 0.4195, ta = 3.2 * ua, tb = 3.2 * ub;
  const double expected = 0.5 * (ta * tb / (ta + tb) + ta * ta * tb * tb / std::pow(ta + tb, 3));
  EXPECT_NEAR(gammaValue(1e-4, ua, ub), expected, 1e-6);
}

TEST(GammaFunctional, LongRangeIsCoulomb) {
  for (double r : {20.0, 40.0}) EXPECT_NEAR(gammaValue(r, 0.3647, 0.4195) * r, 1.0, 1e-7);
}

TEST(GammaFunctional, SymmetricAndContinuousAcrossTheEqualSwitch) {
  for (double r : {1.0, 2.5, 6.0}) {
    EXPECT_DOUBLE_EQ(gammaValue(r, 0.3, 0.45), gammaValue(r, 0.45, 0.3));
    // Just outside the switch (relative difference 2e-3) against the equal form at the mean.
    const double a = gammaValue(r, 0.4, 0.4008), b = gammaValue(r, 0.4004, 0.4004);
    EXPECT_NEAR(a, b, 1e-6) << r;
  }
}

TEST(GammaFunctional, DerivativeMatchesFiniteDifference) {
  for (auto [ua, ub] : {std::pair{0.3647, 0.3647}, std::pair{0.3647, 0.4195}})
    for (double r : {0.8, 2.0, 4.5}) {
      double s, ds, sp, sm, d;
      gammaShortRange(r, ua, ub, s, ds);
      gammaShortRange(r + 1e-5, ua, ub, sp, d);
      gammaShortRange(r - 1e-5, ua, ub, sm, d);
      EXPECT_NEAR(ds, (sp - sm) / 2e-5, 1e-8 * std::max(1.0, std::abs(ds)));
    }
}

TEST(GammaFunctional, CutoffHonoursTolerance) {
  for (double tol : {1e-8, 1e-12}) {
    const double rc = shortRangeCutoff(0.3647, tol);
    double s, ds;
    gammaShortRange(rc, 0.3647, 0.3647, s, ds);
    EXPECT_LT(rc * rc * std::abs(s), tol);
    gammaShortRange(rc - 0.5, 0.3647, 0.3647, s, ds);
    EXPECT_GT((rc - 0.5) * (rc - 0.5) * std::abs(s), tol);  // not needlessly long
  }
}

TEST(GammaFunctional, RingSumsEqualExplicitCopies) {
  // Phi and S~ of the C_6 ring, summed over images, against the 12-atom molecule: the sum over
  // the six copies of atom j seen from atom i.
  const auto unit = mesochain::testing::benzeneUnit();
  const auto mol = mesochain::testing::explicitCopies(unit);
  const DirectRingCoulombSum coulomb;
  const ShortRangeGammaSum sr({0.3647, 0.4195}, 1e-14);
  const Eigen::MatrixXd pu = coulomb.matrix(unit), pm = coulomb.matrix(mol);
  const Eigen::MatrixXd su = sr.matrix(unit), sm = sr.matrix(mol);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double p = 0, s = 0;
      for (int c = 0; c < 6; ++c) {
        p += pm(i, 2 * c + j);
        s += sm(i, 2 * c + j);
      }
      EXPECT_NEAR(pu(i, j), p, 1e-13);
      EXPECT_NEAR(su(i, j), s, 1e-13);
    }
}

TEST(GammaFunctional, ScrewCellNeedsEwald) {
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(4.0, 0.3, 1);
  cell.addAtom("C", {1.0, 0.0, 0.0});
  EXPECT_THROW(DirectRingCoulombSum().matrix(cell), InputError);
}

namespace {
// Weighted sum 1/2 sum_ij w_ij M_ij of a lattice sum's matrix.
template <class Sum>
double weighted(const Sum& sum, const objective::ObjectiveCell& cell, const Eigen::MatrixXd& w) {
  return 0.5 * w.cwiseProduct(sum.matrix(cell)).sum();
}

template <class Sum>
void expectDerivativesMatch(const Sum& sum, const objective::ObjectiveCell& cell, double tol) {
  Eigen::VectorXd q(cell.atomCount());
  for (int a = 0; a < cell.atomCount(); ++a) q[a] = 0.3 * std::sin(1.3 * a + 0.2);
  const Eigen::MatrixXd w = q * q.transpose();
  const LatticeSumDerivatives d = sum.derivatives(cell, w);
  const double h = 1e-5;
  for (int a = 0; a < cell.atomCount(); ++a)
    for (int k = 0; k < 3; ++k) {
      auto p = cell, m = cell;
      p.positions(k, a) += h;
      m.positions(k, a) -= h;
      EXPECT_NEAR(d.gradient(k, a), (weighted(sum, p, w) - weighted(sum, m, w)) / (2 * h), tol)
          << a << " " << k;
    }
  if (cell.symmetry.isRing()) return;
  const auto& s = cell.symmetry;
  auto tp = cell, tm = cell, gp = cell, gm = cell;
  tp.symmetry = s.withTranslation(s.translation() + h);
  tm.symmetry = s.withTranslation(s.translation() - h);
  gp.symmetry = s.withTwist(s.twist() + h);
  gm.symmetry = s.withTwist(s.twist() - h);
  EXPECT_NEAR(d.dTranslation, (weighted(sum, tp, w) - weighted(sum, tm, w)) / (2 * h), tol);
  EXPECT_NEAR(d.dTwist, (weighted(sum, gp, w) - weighted(sum, gm, w)) / (2 * h), tol);
}
}  // namespace

TEST(GammaFunctional, ShortRangeDerivativesOnAScrewCell) {
  // A twisted CH chain with a C_2 axis: positions, T and gamma against finite differences.
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(2.6, 0.45, 2);
  cell.addAtom("C", {1.1, 0.2, 0.1});
  cell.addAtom("H", {2.9, -0.3, 0.7});
  const ShortRangeGammaSum sr({0.3647, 0.4195}, 1e-12);
  expectDerivativesMatch(sr, cell, 1e-8);
}

TEST(GammaFunctional, RingCoulombAndShortRangeDerivatives) {
  auto unit = mesochain::testing::benzeneUnit();
  unit.positions(2, 1) += 0.2;
  expectDerivativesMatch(DirectRingCoulombSum(), unit, 1e-8);
  expectDerivativesMatch(ShortRangeGammaSum({0.3647, 0.4195}, 1e-12), unit, 1e-8);
}
