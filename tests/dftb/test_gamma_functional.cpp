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
