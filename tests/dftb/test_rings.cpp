// Closed rings (T = 0): huge N_a, tiny curvature, sampled angular quantum numbers.
#include <cmath>

#include <gtest/gtest.h>

#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using mesochain::testing::carbonParameters;

namespace {
constexpr double kBond = 2.5;  // Bohr, spacing of the chain atoms along the arc

// A ring of N_a two-atom cells: a chain of atoms kBond apart along a circle in the xy plane.
ObjectiveCell chainRing(int na) {
  const double radius = 2 * kBond * na / (2 * units::kPi);
  ObjectiveCell c;
  c.symmetry = Symmetry::ring(na);
  const double half = units::kPi / na;
  c.addAtom("C", {radius, 0.0, 0.0});
  c.addAtom("C", {radius * std::cos(half), radius * std::sin(half), 0.0});
  return c;
}

// The straight chain (zero curvature): the same two atoms along z, gamma = 0.
ObjectiveCell straightChain() {
  ObjectiveCell c;
  c.symmetry = Symmetry::screw(2 * kBond, 0.0, 1);
  c.addAtom("C", {0.0, 0.0, 0.0});
  c.addAtom("C", {0.0, 0.0, kBond});
  return c;
}

dftb::Calculator calculator(int nKappa, int angularSamples) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = nKappa;
  s.band.angular.samples = angularSamples;
  s.band.electronicTemperature = 2000 * units::kBoltzmannHartreePerKelvin;
  return dftb::Calculator(carbonParameters(), s);
}
}  // namespace

TEST(Rings, HugeRingsApproachTheStraightChainAsOneOverRSquared) {
  const double straight = calculator(4096, 0).evaluate(straightChain(), {}).freeEnergy;
  double previous = 0;
  for (int na : {500, 1000, 2000, 4000}) {
    const auto r = calculator(1, 0).evaluate(chainRing(na), {true, false});
    ASSERT_TRUE(std::isfinite(r.freeEnergy));
    ASSERT_TRUE(r.gradient.allFinite());
    const double excess = r.freeEnergy - straight;  // bending energy, ~ 1/R^2
    if (na > 500) {
      EXPECT_NEAR(previous / excess, 4.0, 0.05) << na;
    }
    previous = excess;
  }
  EXPECT_LT(std::abs(previous), 1e-6);
}

TEST(Rings, SampledAngularNumbersConvergeToTheExactSum) {
  const ObjectiveCell ring = chainRing(3000);
  const double exact = calculator(1, 0).evaluate(ring, {}).freeEnergy;
  double errPrev = 1;
  for (int m : {50, 200, 800}) {
    const auto r = calculator(1, m).evaluate(ring, {});
    const double err = std::abs(r.freeEnergy - exact);
    EXPECT_LT(err, errPrev) << m;
    // The reported estimate bounds the actual error.
    EXPECT_GE(r.energies.at("angular_sampling_error_estimate"), err) << m;
    errPrev = err;
  }
  EXPECT_LT(errPrev, 1e-6);
}
