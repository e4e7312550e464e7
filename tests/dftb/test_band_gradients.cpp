// Analytic gradients of the free energy against central finite differences, for screw, ring and
// combined (screw + C_Na) cells, with and without dispersion, and the derivatives with respect
// to the screw translation T and twist gamma.
#include <cmath>

#include <gtest/gtest.h>

#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using mesochain::testing::armchairHelical;
using mesochain::testing::carbonCalculator;
using mesochain::testing::distort;
using mesochain::testing::fdGradient;
using mesochain::testing::zigzagHelical;

namespace {
void expectGradientMatches(const dftb::Calculator& calc, const ObjectiveCell& cell, double tol) {
  const auto r = calc.evaluate(cell, {true, false});
  ASSERT_EQ(r.gradient.cols(), cell.atomCount());
  for (int a = 0; a < cell.atomCount(); ++a)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r.gradient(k, a), fdGradient(calc, cell, a, k, 1e-4), tol)
          << "atom " << a << " component " << k;
}

ObjectiveCell ring(int na, double radius) {
  // A ring of N_a two-atom cells (a cyclic carbon chain, bent sp chain) about z.
  ObjectiveCell c;
  c.symmetry = Symmetry::ring(na);
  const double step = 2 * units::kPi / na;
  c.addAtom("C", {radius, 0.0, 0.1});
  c.addAtom("C", {radius * std::cos(0.47 * step), radius * std::sin(0.47 * step), -0.1});
  return c;
}
}  // namespace

TEST(BandGradients, ScrewCellWithoutRotation) {
  ObjectiveCell cell = armchairHelical(3);
  cell.symmetry = Symmetry::screw(cell.symmetry.translation() * 3.0, 0.4, 1);
  distort(cell, 0.08);
  expectGradientMatches(carbonCalculator(10, 1000.0), cell, 2e-7);
}

TEST(BandGradients, CombinedScrewAndRotation) {
  ObjectiveCell cell = zigzagHelical(5);
  distort(cell, 0.07);
  expectGradientMatches(carbonCalculator(8, 800.0), cell, 2e-7);
}

TEST(BandGradients, ClosedRing) {
  ObjectiveCell cell = ring(9, 2.6 * 9 / (2 * units::kPi) * 2);
  distort(cell, 0.05);
  expectGradientMatches(carbonCalculator(1, 1000.0), cell, 2e-7);
}

TEST(BandGradients, WithDispersion) {
  ObjectiveCell cell = armchairHelical(4);
  distort(cell, 0.06);
  expectGradientMatches(carbonCalculator(6, 1000.0, true, 18.0), cell, 2e-7);
}

TEST(BandGradients, StrainDerivativesMatchFiniteDifferences) {
  for (bool dispersion : {false, true}) {
    ObjectiveCell cell = zigzagHelical(5);
    distort(cell, 0.05);
    const auto calc = carbonCalculator(8, 800.0, dispersion, 16.0);
    const auto r = calc.evaluate(cell, {false, true});
    const double t = cell.symmetry.translation(), g = cell.symmetry.twist(), h = 1e-4;
    auto energyAt = [&](double tt, double gg) {
      ObjectiveCell c = cell;
      c.symmetry = Symmetry::screw(tt, gg, cell.symmetry.rotationOrder());
      return calc.evaluate(c, {}).freeEnergy;
    };
    EXPECT_NEAR(r.dFdTranslation, (energyAt(t + h, g) - energyAt(t - h, g)) / (2 * h), 2e-7)
        << "dispersion " << dispersion;
    EXPECT_NEAR(r.dFdTwist, (energyAt(t, g + h) - energyAt(t, g - h)) / (2 * h), 2e-7)
        << "dispersion " << dispersion;
  }
}

TEST(BandGradients, DegenerateLevelsAtTheFermiLevelStayStable) {
  // The ideal armchair tube is metallic, with degenerate levels crossing the Fermi level.
  // Smearing keeps the free energy smooth: analytic forces match finite differences even at
  // 10 K, and a displacement of 1e-7 Bohr changes the forces by a proportionate amount.
  const ObjectiveCell cell = armchairHelical(5);
  for (double kelvin : {300.0, 10.0}) {
    const auto calc = carbonCalculator(32, kelvin);
    const auto r = calc.evaluate(cell, {true, false});
    ASSERT_TRUE(r.gradient.allFinite());
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r.gradient(k, 0), fdGradient(calc, cell, 0, k, 1e-4), 1e-6) << kelvin;
    ObjectiveCell nudged = cell;
    nudged.positions(0, 1) += 1e-7;
    const auto q = calc.evaluate(nudged, {true, false});
    EXPECT_LT((q.gradient - r.gradient).cwiseAbs().maxCoeff(), 1e-5) << kelvin;
  }
}
