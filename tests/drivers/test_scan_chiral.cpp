// A bilayer graphene sector along the chiral direction (2, 1) relaxes without atoms collapsing
// and rebends in a bend scan: energies finite, and the more curved ring costs more.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/drivers/relax.hpp"
#include "objective/drivers/scan.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
dftb::CalculatorSettings bilayerSettings() {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = 2;  // T = 11.3 Å
  s.band.angular.samples = 2;
  s.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
  s.dispersion.enabled = true;  // the LJ defaults of the cell file
  s.dispersion.epsilon = 0.069 * units::kKcalPerMolInHartree;
  s.dispersion.r0 = 3.80 * units::kAngstromInBohr;
  s.dispersion.cutoff = 20.0 * units::kAngstromInBohr;
  return s;
}

// Smallest distance between atoms of the cell and their images, and the smallest and largest
// distance of an atom from the axis, per layer.
double minDistance(const ObjectiveCell& c) {
  double d = std::numeric_limits<double>::infinity();
  const int na = c.symmetry.rotationOrder();
  for (int a = 0; a < c.atomCount(); ++a)
    for (long zeta = -1; zeta <= 1; ++zeta)
      for (int s = 0; s < na; ++s)
        for (int b = 0; b < c.atomCount(); ++b) {
          if (zeta == 0 && s == 0 && a == b) continue;
          d = std::min(d, (c.symmetry.apply({zeta, s}, c.positions.col(b)) - c.positions.col(a)).norm());
        }
  return d;
}
}  // namespace

TEST(ScanChiral, BilayerChiralSectorRelaxesAndRebends) {
  const double bond = 1.42 * units::kAngstromInBohr, layer = 3.35 * units::kAngstromInBohr;
  const int na = 60;  // R_mid = 62 Å: the outer layer stretched, the inner compressed by 2.7 %
  const ObjectiveCell sector = buildGrapheneRingSector(2, ChiralIndices{2, 1}, na, 1, layer, bond);
  ASSERT_EQ(sector.atomCount(), 56);
  const auto params = std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C"}, {{"C-C", std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf"}}, "test"));
  const dftb::Calculator calc(params, bilayerSettings());

  RelaxSettings rs;
  rs.forceTolerance = 1e-3;
  rs.maxSteps = 40;
  const RelaxOutcome relaxed = relax(calc, sector, rs);
  const double e0 = calc.evaluate(sector, {}).freeEnergy;
  EXPECT_TRUE(std::isfinite(relaxed.result.freeEnergy));
  EXPECT_LT(relaxed.result.freeEnergy, e0);
  EXPECT_GT(minDistance(relaxed.cell), 0.9 * bond);
  // The layers stay apart: the radial gap between the mean radii of the two layers.
  auto meanRadius = [&](int k) {
    double r = 0;
    for (int a = 28 * k; a < 28 * (k + 1); ++a) r += relaxed.cell.positions.col(a).head<2>().norm();
    return r / 28;
  };
  RecordProperty("relaxed_gap_angstrom", std::to_string((meanRadius(1) - meanRadius(0)) * units::kBohrInAngstrom));
  EXPECT_GT(meanRadius(1) - meanRadius(0), 3.0 * units::kAngstromInBohr);
  EXPECT_LT(meanRadius(1) - meanRadius(0), 3.8 * units::kAngstromInBohr);

  ScanSettings s;
  s.kind = ScanKind::Bend;
  s.rotationOrders = {48, 80};
  s.ringAngular.samples = 2;
  s.relax.forceTolerance = 1e-3;
  s.relax.maxSteps = 40;
  s.progressBar = false;
  const ScanResult r = runScan(sector, params, bilayerSettings(), s);
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.points.size(), 3u);  // sorted by curvature: 80, 60, 48
  EXPECT_EQ(r.points[0].rotationOrder, 80);
  EXPECT_EQ(r.points[1].rotationOrder, 60);
  EXPECT_EQ(r.points[2].rotationOrder, 48);
  for (const ScanPoint& p : r.points) {
    EXPECT_TRUE(std::isfinite(p.energy));
    EXPECT_GT(minDistance(p.cell), 0.9 * bond) << p.rotationOrder;
  }
  // Bending costs energy: more curvature, higher energy (differences, no flat point).
  EXPECT_GT(r.points[1].energy - r.points[0].energy, 0.0);
  EXPECT_GT(r.points[2].energy - r.points[1].energy, 0.0);
}
