// The collapsed-tube builder: the dog-bone contour has the requested perimeter and is smooth
// (unit speed, no jumps), the collapse keeps every bond of the round tube to within the chord
// effect of the tighter curvature, the flat faces sit at the requested spacing, and
// measureCollapsed reads those dimensions back from the atoms.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_file.hpp"
#include "objective/core/collapsed_tube_builder.hpp"
#include "objective/core/nanotube_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kAngstromInBohr;
using units::kPi;

namespace {
const double kBond = 1.42 * kAngstromInBohr;
const double kGap = 3.4 * kAngstromInBohr;

CollapseShape shape() {
  CollapseShape s;
  s.interlayer = kGap;
  s.bulbRadius = 3.4 * kAngstromInBohr;
  s.transitionRadius = 3.4 * kAngstromInBohr;
  return s;
}

// Nearest-neighbour distances of atom a among all atoms and their +-1 screw images.
std::vector<double> neighbourDistances(const ObjectiveCell& c, int a, double cutoff) {
  std::vector<double> out;
  for (long zeta = -1; zeta <= 1; ++zeta)
    for (int b = 0; b < c.atomCount(); ++b) {
      if (zeta == 0 && b == a) continue;
      const Eigen::Vector3d x = c.symmetry.apply({zeta, 0}, c.positions.col(b));
      const double r = (x - c.positions.col(a)).norm();
      if (r < cutoff) out.push_back(r);
    }
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

TEST(DogBoneContour, PerimeterIsArcLengthAndCurveIsClosedAndSmooth) {
  const double perimeter = 2 * kPi * 20.0 * kAngstromInBohr;
  const DogBoneContour c(kGap / 2, 3.4 * kAngstromInBohr, 2.0 * kAngstromInBohr, perimeter);
  const int n = 20000;
  const double ds = perimeter / n;
  double length = 0;
  for (int i = 0; i < n; ++i) {
    const double step = (c.point((i + 1) * ds) - c.point(i * ds)).norm();
    EXPECT_LE(step, ds * (1 + 1e-9));  // a chord never exceeds its arc (rounding aside)
    EXPECT_GT(step, ds * (1 - 1e-3));  // and no jumps between segments
    length += step;
  }
  EXPECT_NEAR(length, perimeter, 1e-5 * perimeter);
  EXPECT_NEAR((c.point(perimeter) - c.point(0)).norm(), 0.0, 1e-9);
  // Flat faces at +-h; bulbs reach x = +-(x_c + r_b) on the x axis.
  EXPECT_NEAR(c.point(0).y(), kGap / 2, 1e-12);
  EXPECT_NEAR(c.point(perimeter / 2).y(), -kGap / 2, 1e-12);
  EXPECT_NEAR(c.point(perimeter / 4).x(), c.bulbCentre() + 3.4 * kAngstromInBohr, 1e-9);
  EXPECT_NEAR(c.point(perimeter / 4).y(), 0.0, 1e-9);
}

TEST(DogBoneContour, TooShortPerimeterIsAnInputError) {
  EXPECT_THROW(DogBoneContour(kGap / 2, 3.4 * kAngstromInBohr, 3.4 * kAngstromInBohr, 10.0),
               InputError);
  EXPECT_THROW(DogBoneContour(kGap / 2, 0.4 * kGap, 3.0, 200.0), InputError);  // r_b < h
}

TEST(CollapsedTube, SingleWallKeepsBondsAndFacesAtTheSpacing) {
  const ObjectiveCell round = buildNanotubeTranslational(30, 30, kBond);
  const ObjectiveCell flat = buildCollapsedTube({{30, 30}}, kBond, shape());
  ASSERT_EQ(flat.atomCount(), 120);
  EXPECT_DOUBLE_EQ(flat.symmetry.translation(), round.symmetry.translation());
  EXPECT_NO_THROW(flat.validate("collapsed", 0.5 * kAngstromInBohr));
  // Every atom keeps three neighbours at the round tube's bond lengths (within 1%).
  for (int a = 0; a < flat.atomCount(); ++a) {
    const auto r0 = neighbourDistances(round, a, 1.2 * kBond);
    const auto r1 = neighbourDistances(flat, a, 1.2 * kBond);
    ASSERT_EQ(r0.size(), 3u);
    ASSERT_EQ(r1.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(r1[k] / r0[k], 1.0, 0.01);
  }
  // Atoms on the flat part lie exactly on y = +-gap/2; the others bulge out to at most r_b.
  const DogBoneContour c(kGap / 2, 3.4 * kAngstromInBohr, 3.4 * kAngstromInBohr,
                         2 * kPi * NanotubeRollUp(30, 30, kBond).radius());
  int onFaces = 0;
  for (int a = 0; a < flat.atomCount(); ++a) {
    const double x = flat.positions(0, a), y = flat.positions(1, a);
    if (std::abs(x) < c.flatHalfLength() - 1e-9) {
      EXPECT_NEAR(std::abs(y), kGap / 2, 1e-12);
      ++onFaces;
    }
    EXPECT_LE(std::abs(y), 3.4 * kAngstromInBohr + 1e-9);
  }
  EXPECT_GT(onFaces, 60);
  // The principal axes of a finite set of atoms tilt slightly from x: 1e-3 Bohr is the
  // resolution of the measurement, not of the builder (checked exactly above).
  const CollapsedDimensions dims = measureCollapsed(flat, kGap);
  EXPECT_NEAR(dims.faceSeparation, kGap, 1e-3);
  EXPECT_NEAR(dims.thickness, 2 * kGap, 1e-3);
  EXPECT_NEAR(std::abs(dims.longAxis.x()), 1.0, 1e-6);
  // Width: atom extent along x is at most the bulb tips 2 (x_c + r_b), within one bond of it.
  const double tips = 2 * (c.bulbCentre() + 3.4 * kAngstromInBohr);
  EXPECT_LE(dims.width - kGap, tips + 1e-3);
  EXPECT_GT(dims.width - kGap, tips - 2 * kBond);
}

TEST(CollapsedTube, DoubleWallNestsTheWallsOneInterlayerApart) {
  const ObjectiveCell flat = buildCollapsedTube({{30, 30}, {35, 35}}, kBond, shape());
  ASSERT_EQ(flat.atomCount(), 260);
  EXPECT_NO_THROW(flat.validate("collapsed", 0.5 * kAngstromInBohr));
  // The walls are exact parallel curves when the perimeters differ by 2 pi d; here they differ
  // by 2 pi (R35 - R30) = 2 pi * 3.39 Å, so the closest approach of the walls is close to d.
  double closest = 1e9;
  for (int a = 0; a < 120; ++a)
    for (int b = 120; b < 260; ++b)
      for (long zeta = -1; zeta <= 1; ++zeta)
        closest = std::min(closest, (flat.symmetry.apply({zeta, 0}, flat.positions.col(b)) -
                                     flat.positions.col(a)).norm());
  EXPECT_GT(closest, 0.9 * kGap);
  const CollapsedDimensions dims = measureCollapsed(flat, kGap);
  EXPECT_NEAR(dims.faceSeparation, 3 * kGap, 1e-3);  // outer faces at +-(gap/2 + gap)
  EXPECT_NEAR(dims.thickness, 4 * kGap, 1e-3);
}

TEST(CollapsedTube, CellFileBuilderType) {
  const auto dir = mesochain::testing::processTempDir("mesochain-collapsed-test");
  std::filesystem::create_directories(dir);
  const auto path = (dir / "c.toml").string();
  std::ofstream(path) << "format = 1\n[builder]\ntype = \"collapsed\"\nwalls = [[30, 30]]\n"
                         "interlayer = 3.4\nbulb_radius = 3.4\n[kpoints]\nhelical = 8\n"
                         "[electrons]\ntemperature = 300\n[parameters]\nset = \"pbc-0-3\"\n";
  const CellInput in = readCellFile(path);
  EXPECT_EQ(in.cell.atomCount(), 120);
  EXPECT_NEAR(measureCollapsed(in.cell, kGap).faceSeparation, kGap, 1e-3);
  std::ofstream(path) << "format = 1\n[builder]\ntype = \"collapsed\"\nwalls = [[30, 30]]\n"
                         "bulb_radius = 1.0\n[kpoints]\nhelical = 8\n"
                         "[electrons]\ntemperature = 300\n[parameters]\nset = \"pbc-0-3\"\n";
  try {
    readCellFile(path);
    FAIL() << "bulb radius below half the gap accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bulb_radius"), std::string::npos) << e.what();
  }
}
