// A graphene bilayer with Lennard-Jones dispersion (eps = 0.069 kcal/mol, r0 = 3.80 Å, the
// defaults) binds at a physically sensible interlayer spacing (3.3-3.5 Å). The bilayer is
// represented exactly as the objective structure allows: two concentric layers of a ring of
// large radius (N_a = 600, R ~ 400 Å), periodic along z.
#include <cmath>

#include <gtest/gtest.h>

#include "objective/core/graphene_builder.hpp"
#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;

TEST(BilayerDispersion, InterlayerMinimumIsPhysical) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = 12;
  s.band.angular.samples = 48;
  s.band.electronicTemperature = 1000 * units::kBoltzmannHartreePerKelvin;
  s.dispersion.enabled = true;
  s.dispersion.epsilon = 0.069 * units::kKcalPerMolInHartree;
  s.dispersion.r0 = 3.80 * units::kAngstromInBohr;
  s.dispersion.cutoff = 30.0 * units::kAngstromInBohr;
  const dftb::Calculator calc(mesochain::testing::carbonParameters(), s);
  std::vector<double> d, e;
  for (double spacing = 3.0; spacing < 3.85; spacing += 0.1) {
    const ObjectiveCell cell = buildGrapheneRingSector(
        2, Direction::Zigzag, 600, 1, spacing * units::kAngstromInBohr, 1.42 * units::kAngstromInBohr);
    d.push_back(spacing);
    e.push_back(calc.evaluate(cell, {}).freeEnergy / cell.atomCount());
  }
  // The discrete minimum, refined by the parabola through it and its neighbours.
  const size_t i = static_cast<size_t>(std::min_element(e.begin(), e.end()) - e.begin());
  ASSERT_GT(i, 0u);
  ASSERT_LT(i + 1, e.size());
  const double h = d[i + 1] - d[i];
  const double shift = 0.5 * h * (e[i - 1] - e[i + 1]) / (e[i - 1] - 2 * e[i] + e[i + 1]);
  const double minimum = d[i] + shift;
  EXPECT_GT(minimum, 3.3);
  EXPECT_LT(minimum, 3.5);
  // Bound: the binding energy relative to 3.8 Å is positive and of the order of meV per atom.
  const double binding = (e.back() - e[i]) * units::kHartreeInEv;
  EXPECT_GT(binding, 1e-4);
  EXPECT_LT(binding, 0.1);
  RecordProperty("interlayer_minimum_angstrom", std::to_string(minimum));
}
