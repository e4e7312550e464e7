// SCC on screw cells through the helical Ewald sum: a helical CH chain against its
// translational supercell, finite-difference forces with respect to positions, T and gamma, and
// a neutral carbon tube where SCC and non-SCC nearly agree.
#include <cmath>

#include <gtest/gtest.h>

#include "scc_support.hpp"
#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;

TEST(SccHelical, ChainEqualsItsTranslationalSupercell) {
  const auto unit = mesochain::testing::helicalChUnit();
  const auto super = mesochain::testing::translationalSupercell(unit, 12);
  // Matched k-points: 48 helical kappa points of the unit <-> 4 of the 12-unit cell.
  const auto ru = mesochain::testing::sccCalculator(300.0, 48).evaluate(unit, {true, true});
  const auto rs = mesochain::testing::sccCalculator(300.0, 4).evaluate(super, {true, false});
  const auto& qu = ru.series.at("mulliken_charges");
  const auto& qs = rs.series.at("mulliken_charges");
  EXPECT_GT(std::abs(qu[0]), 0.02);  // real charge transfer
  EXPECT_NEAR(ru.freeEnergy / 2, rs.freeEnergy / 24, 1e-7);
  EXPECT_NEAR(ru.extras.at("scc_energy") / 2, rs.extras.at("scc_energy") / 24, 1e-7);
  for (int c = 0; c < 12; ++c)
    for (int a = 0; a < 2; ++a) EXPECT_NEAR(qu[a], qs[2 * c + a], 1e-7);
  // The unit's atoms are the supercell's first two; forces in the same frame.
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(ru.gradient(k, a), rs.gradient(k, a), 1e-6);
}

TEST(SccHelical, ForcesTranslationAndTwistMatchFiniteDifferences) {
  auto cell = mesochain::testing::helicalChUnit();
  const auto calc = mesochain::testing::sccCalculator(2000.0, 16);
  const auto r = calc.evaluate(cell, {true, true});
  const double h = 1e-4;
  auto f = [&](ObjectiveCell c) { return calc.evaluate(c, {}).freeEnergy; };
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 3; ++k) {
      auto p = cell, m = cell;
      p.positions(k, a) += h;
      m.positions(k, a) -= h;
      EXPECT_NEAR(r.gradient(k, a), (f(p) - f(m)) / (2 * h), 5e-8) << a << " " << k;
    }
  const auto& s = cell.symmetry;
  auto tp = cell, tm = cell, gp = cell, gm = cell;
  tp.symmetry = s.withTranslation(s.translation() + h);
  tm.symmetry = s.withTranslation(s.translation() - h);
  gp.symmetry = s.withTwist(s.twist() + h);
  gm.symmetry = s.withTwist(s.twist() - h);
  EXPECT_NEAR(r.dFdTranslation, (f(tp) - f(tm)) / (2 * h), 5e-8);
  EXPECT_NEAR(r.dFdTwist, (f(gp) - f(gm)) / (2 * h), 5e-8);
}

TEST(SccHelical, NeutralCarbonTubeNearlyAgreesWithNonScc) {
  auto cell = mesochain::testing::zigzagHelical(8);
  mesochain::testing::distort(cell, 0.05);
  auto s = mesochain::testing::sccSettings(1000.0, 16);
  const auto scc = dftb::Calculator(mesochain::testing::carbonParameters(), s).evaluate(cell, {});
  // The SCC functional is minimised by the SCC density, and its Coulomb term is >= 0: the
  // non-SCC free energy is a lower bound, and the functional at the non-SCC density (the first
  // iteration, started from neutral atoms) an upper bound.
  s.scc.maxIterations = 1;
  s.scc.stopIfUnconverged = false;
  const auto first = dftb::Calculator(mesochain::testing::carbonParameters(), s).evaluate(cell, {});
  s.scc.enabled = false;
  const auto plain = dftb::Calculator(mesochain::testing::carbonParameters(), s).evaluate(cell, {});
  const auto& q = scc.series.at("mulliken_charges");
  EXPECT_LT(std::abs(q[0]), 5e-3);
  EXPECT_NEAR(q[0] + q[1], 0.0, 1e-10);
  EXPECT_LT(std::abs(scc.freeEnergy - plain.freeEnergy), 1e-4);
  EXPECT_GE(scc.freeEnergy, plain.freeEnergy - 1e-12);
  EXPECT_LE(scc.freeEnergy, first.freeEnergy + 1e-12);
  EXPECT_GT(first.freeEnergy - plain.freeEnergy, 0.0);  // the non-SCC density has charges
}
