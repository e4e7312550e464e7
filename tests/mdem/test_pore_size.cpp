// Pore-size distribution (mdem/contacts/pore_size.hpp) against the closed form of a square
// lattice of parallel rods: radius a, spacing L, the local pore diameter D(p) = 2 (distance to the
// nearest axis - a). Void fraction 1 - pi a^2 / L^2, and for a + r <= L / 2 the void with
// D >= 2 r is the cell outside four quarter discs of radius a + r:
//   P(D >= 2 r) = (L^2 - pi (a + r)^2) / (L^2 - pi a^2);
// the largest empty sphere sits at the cell centre: D_max = 2 (L / sqrt 2 - a).
#include <cmath>

#include <gtest/gtest.h>

#include "contact_fixture.hpp"

#include "mdem/contacts/film_statistics.hpp"
#include "mdem/contacts/pore_size.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// Rods along y (one 2 nm element each, periodic along y with that length: an endless rod) at
// x = i L, z = j L, periodic along x.
Scene rodLattice(double spacing, int columns, int rows) {
  Scene s = tubeScene({"bonds"});
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j <= rows; ++j) addTube(s, 1, Vec3(i * spacing, 0.0, j * spacing), Vec3::UnitY());
  s.filmSize = Vec3(columns * spacing, kSegmentLength, rows * spacing);
  s.periodic.periodic = {true, true, false};
  s.periodic.length = Vec3(columns * spacing, kSegmentLength, 0.0);
  return s;
}

TEST(MdemPoreSize, SquareRodLatticeMatchesTheClosedForm) {
  const double l = 4.0, a = kTubeRadius;
  const Scene s = rodLattice(l, 2, 1);
  PoreSizeOptions o;
  o.shell = 0.0, o.gridSpacing = 0.04, o.binWidth = 0.5;
  o.zLow = 0.0, o.zHigh = l;  // whole cells: the lattice's own distance field
  const PoreSizeDistribution p = poreSizeDistribution(s, o);
  const double cell = l * l, voidArea = cell - units::kPi * a * a;
  EXPECT_NEAR(p.voidFraction, voidArea / cell, 2e-3);
  ASSERT_GE(p.cumulative.size(), 6u);
  for (int k = 0; k < 6; ++k) {  // D = 0 .. 2.5 nm: a + r <= L / 2
    const double r = 0.5 * k * o.binWidth;
    ASSERT_LE(a + r, 0.5 * l);
    const double expected = (cell - units::kPi * (a + r) * (a + r)) / voidArea;
    EXPECT_NEAR(p.cumulative[k], expected, 3e-3) << "D >= " << 2 * r << " nm";
  }
  const double largest = 2.0 * (l / std::sqrt(2.0) - a);
  EXPECT_LE(p.largestDiameter, largest + 1e-12);
  EXPECT_GT(p.largestDiameter, largest - 2.0 * o.gridSpacing);
  double sum = 0.0;
  for (double f : p.fraction) sum += f;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_GT(p.medianDiameter, 0.0);
  EXPECT_LT(p.medianDiameter, p.largestDiameter);
}

// A van der Waals shell thickens the rods: the same closed form with a + shell.
TEST(MdemPoreSize, ShellThickensTheRods) {
  const double l = 4.0, a = kTubeRadius + 0.17;
  const Scene s = rodLattice(l, 1, 1);
  PoreSizeOptions o;
  o.shell = 0.17, o.gridSpacing = 0.04, o.binWidth = 0.5, o.zLow = 0.0, o.zHigh = l;
  const PoreSizeDistribution p = poreSizeDistribution(s, o);
  EXPECT_NEAR(p.voidFraction, 1.0 - units::kPi * a * a / (l * l), 2e-3);
  const double r = 0.5;
  EXPECT_NEAR(p.cumulative[2], (l * l - units::kPi * (a + r) * (a + r)) / (l * l - units::kPi * a * a), 3e-3);
}

// The film report carries it over the film's thickness (z from z_min - R to z_max + R).
TEST(MdemPoreSize, FilmReportIncludesTheDistribution) {
  const Scene s = rodLattice(4.0, 2, 2);
  FilmStatisticsOptions o;
  o.pores.gridSpacing = 0.1;
  const FilmStatistics f = filmStatistics(s, o);
  ASSERT_TRUE(f.hasPores);
  EXPECT_NEAR(f.pores.zLow, -kTubeRadius, 1e-12);
  EXPECT_NEAR(f.pores.zHigh, 8.0 + kTubeRadius, 1e-12);
  EXPECT_GT(f.pores.voidPoints, 0);
  // The grid's void fraction and the report's porosity measure the same void.
  EXPECT_NEAR(f.pores.voidFraction, f.porosity, 0.02);
}

}  // namespace
}  // namespace mesochain::mdem
