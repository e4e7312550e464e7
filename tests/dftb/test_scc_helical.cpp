// SCC on screw cells through the helical Ewald sum: a helical CH chain against its
// translational supercell, finite-difference forces with respect to positions, T and gamma, and
// a neutral carbon tube where SCC and non-SCC nearly agree, and a twisted H-terminated armchair
// graphene nanoribbon against its translational supercell.
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
  EXPECT_NEAR(ru.energies.at("scc_coulomb") / 2, rs.energies.at("scc_coulomb") / 24, 1e-7);
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

TEST(SccHelical, TwistedRibbonEqualsItsTranslationalSupercell) {
  // H-terminated 3-AGNR twisted by 60 degrees per unit (4.26 A): 6 units close a full turn, so
  // the helical cell (10 atoms, screw T, 2 pi / 6) is the same structure as its 60-atom
  // translational supercell. C-H charge transfer and the twist make the charges differ per atom.
  const auto unit = mesochain::testing::twistedArmchairRibbonUnit(3, 2 * units::kPi / 6);
  ASSERT_EQ(unit.atomCount(), 10);
  const auto super = mesochain::testing::translationalSupercell(unit, 6);
  double closest = 1e9;  // sanity of the built geometry (Bohr): no overlapping atoms
  for (int i = 0; i < super.atomCount(); ++i)
    for (int j = 0; j < i; ++j)
      closest = std::min(closest, (super.positions.col(i) - super.positions.col(j)).norm());
  ASSERT_GT(closest, 1.9);
  // Matched k-points: 12 kappa points of the unit <-> 2 of the 6-unit cell.
  const auto ru = mesochain::testing::sccCalculator(300.0, 12).evaluate(unit, {true, true});
  const auto rs = mesochain::testing::sccCalculator(300.0, 2).evaluate(super, {true, false});
  const auto& qu = ru.series.at("mulliken_charges");
  const auto& qs = rs.series.at("mulliken_charges");
  double maxH = 0;
  for (int a = 0; a < 10; ++a)
    if (unit.species[a] == unit.species[9]) maxH = std::max(maxH, std::abs(qu[a]));
  EXPECT_GT(maxH, 0.05);  // real charge transfer to/from the H
  EXPECT_NEAR(ru.freeEnergy / 10, rs.freeEnergy / 60, 1e-7);
  EXPECT_NEAR(ru.energies.at("scc_coulomb") / 10, rs.energies.at("scc_coulomb") / 60, 1e-7);
  for (int c = 0; c < 6; ++c)
    for (int a = 0; a < 10; ++a) EXPECT_NEAR(qu[a], qs[10 * c + a], 1e-7) << c << " " << a;
  for (int a = 0; a < 10; ++a)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(ru.gradient(k, a), rs.gradient(k, a), 1e-7);
  // The torque dF/dgamma of the twisted ribbon against a central difference.
  const double h = 1e-4;
  auto gp = unit, gm = unit;
  gp.symmetry = unit.symmetry.withTwist(unit.symmetry.twist() + h);
  gm.symmetry = unit.symmetry.withTwist(unit.symmetry.twist() - h);
  const auto calc = mesochain::testing::sccCalculator(300.0, 12);
  EXPECT_NEAR(ru.dFdTwist,
              (calc.evaluate(gp, {}).freeEnergy - calc.evaluate(gm, {}).freeEnergy) / (2 * h), 5e-8);
  // Not a trivial zero (at fixed cell atoms the sign depends on the unit's internal twist).
  EXPECT_GT(std::abs(ru.dFdTwist), 1e-4);
}

