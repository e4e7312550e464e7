// Symmetry equivalences of the band structure: an objective cell equals its replicated
// supercell, the rotation subgroup C_Na equals explicit rotated copies, a rotation of the whole
// input about z changes nothing, and an atom on the screw axis needs no angle from its position.
#include <cmath>

#include <gtest/gtest.h>

#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using mesochain::testing::armchairHelical;
using mesochain::testing::carbonCalculator;
using mesochain::testing::distort;
using mesochain::testing::zigzagHelical;

namespace {
// The cell of M screw steps: atoms S^zeta(x), zeta = 0..M-1, with screw (M T, M gamma).
ObjectiveCell screwSupercell(const ObjectiveCell& c, int m) {
  ObjectiveCell s;
  s.symmetry = Symmetry::screw(m * c.symmetry.translation(), m * c.symmetry.twist(),
                               c.symmetry.rotationOrder());
  for (int z = 0; z < m; ++z)
    for (int a = 0; a < c.atomCount(); ++a)
      s.addAtom(c.speciesOf(a), c.symmetry.apply({z, 0}, c.positions.col(a)));
  return s;
}

// The same structure without the rotation subgroup: N_a rotated copies, rotation order 1.
ObjectiveCell withoutRotation(const ObjectiveCell& c) {
  ObjectiveCell s;
  s.symmetry = Symmetry::screw(c.symmetry.translation(), c.symmetry.twist(), 1);
  for (int r = 0; r < c.symmetry.rotationOrder(); ++r)
    for (int a = 0; a < c.atomCount(); ++a)
      s.addAtom(c.speciesOf(a), c.symmetry.apply({0, r}, c.positions.col(a)));
  return s;
}
}  // namespace

TEST(BandEquivalence, HelicalCellEqualsScrewSupercell) {
  // Midpoint grids map exactly when N_kappa is divisible by 4 (doubling the screw step folds
  // kappa onto 2 kappa mod 2 pi).
  ObjectiveCell cell = armchairHelical(5);
  distort(cell, 0.05);
  const auto small = carbonCalculator(8, 1000.0).evaluate(cell, {true, false});
  const ObjectiveCell big = screwSupercell(cell, 2);
  const auto large = carbonCalculator(4, 1000.0).evaluate(big, {true, false});
  EXPECT_NEAR(small.freeEnergy / 2, large.freeEnergy / 4, 1e-10);
  EXPECT_NEAR(small.totalEnergy / 2, large.totalEnergy / 4, 1e-10);
  EXPECT_NEAR(small.extras.at("fermi_level"), large.extras.at("fermi_level"), 1e-9);
  // Forces on the first two atoms of the supercell are those of the cell.
  EXPECT_LT((small.gradient - large.gradient.leftCols(2)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(BandEquivalence, RotationSubgroupEqualsExplicitCopies) {
  ObjectiveCell cell = zigzagHelical(6);
  distort(cell, 0.04);
  const auto a = carbonCalculator(12, 600.0).evaluate(cell, {true, false});
  const ObjectiveCell full = withoutRotation(cell);
  const auto b = carbonCalculator(12, 600.0).evaluate(full, {true, false});
  EXPECT_NEAR(a.freeEnergy / 2, b.freeEnergy / 12, 1e-10);
  EXPECT_LT((a.gradient - b.gradient.leftCols(2)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(BandEquivalence, RotatingTheInputAboutTheAxisChangesNothing) {
  ObjectiveCell cell = armchairHelical(4);
  distort(cell, 0.05);
  const auto calc = carbonCalculator(10, 500.0);
  const auto a = calc.evaluate(cell, {true, true});
  ObjectiveCell turned = cell;
  const Eigen::Matrix3d q = rotationZ(0.731);
  turned.positions = q * cell.positions;
  turned.positions.row(2).array() += 0.37;  // and a shift along the axis
  const auto b = calc.evaluate(turned, {true, true});
  EXPECT_NEAR(a.freeEnergy, b.freeEnergy, 1e-11);
  EXPECT_LT((q * a.gradient - b.gradient).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_NEAR(a.dFdTranslation, b.dFdTranslation, 1e-10);
  EXPECT_NEAR(a.dFdTwist, b.dFdTwist, 1e-10);
}

TEST(BandEquivalence, AtomOnScrewAxisIsIndependentOfTheTwistAndContinuous) {
  // A straight chain of atoms on the axis is the same structure for any twist; only the
  // orientation of the image orbitals (taken from the group element) differs.
  auto chain = [](double twist, double offAxis) {
    ObjectiveCell c;
    c.symmetry = Symmetry::screw(2.6, twist, 1);
    c.addAtom("C", {offAxis, 0.0, 0.0});
    return c;
  };
  // A twist gamma shifts the kappa of the p_x +- i p_y bands by -+gamma; with gamma a multiple
  // of the grid spacing 2 pi / N the sampled set is the same and the energies agree exactly.
  const int nk = 16;
  const auto calc = carbonCalculator(nk, 2000.0);
  const double twist = 2 * units::kPi * 3 / nk;
  const double e0 = calc.evaluate(chain(0.0, 0.0), {}).freeEnergy;
  const double e1 = calc.evaluate(chain(twist, 0.0), {}).freeEnergy;
  EXPECT_NEAR(e0, e1, 1e-11);
  // A slightly off-axis atom: energy continuous (changes at second order) for a twisted chain.
  const double eOff = calc.evaluate(chain(twist, 1e-4), {}).freeEnergy;
  EXPECT_NEAR(eOff, e1, 1e-6);
  EXPECT_NE(eOff, e1);
  const auto g = calc.evaluate(chain(twist, 0.0), {true, false});
  EXPECT_LT(g.gradient.cwiseAbs().maxCoeff(), 1e-9);  // no force on the axis by symmetry
}

TEST(BandEquivalence, GammaZeroIsOneDimensionalPeriodicity) {
  // gamma = 0: the cell of M atoms with translation T equals the cell of one atom with T/M.
  ObjectiveCell one;
  one.symmetry = Symmetry::screw(2.7, 0.0, 1);
  one.addAtom("C", {0.3, 0.0, 0.0});
  const ObjectiveCell two = screwSupercell(one, 2);
  const double a = carbonCalculator(8, 1500.0).evaluate(one, {}).freeEnergy;
  const double b = carbonCalculator(4, 1500.0).evaluate(two, {}).freeEnergy;
  EXPECT_NEAR(a, b / 2, 1e-10);
}
