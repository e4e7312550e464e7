// Sectors of multi-walled tubes with different atoms per wall (objective/core/tube_sector_builder.hpp,
// buildMultiWallSector): the sector's images are the full translational cell of the existing
// builder, every atom has the three bonds of an ideal roll-up (closed-form chord lengths), the
// atom counts and symmetry follow the rotation order, and bad requests are clear errors.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/core/tube_sector_builder.hpp"

namespace mesochain::objective {
namespace {

const double kBond = 1.42 * units::kAngstromInBohr;

Eigen::Vector3d rotateZ(const Eigen::Vector3d& x, double phi) {
  return {std::cos(phi) * x.x() - std::sin(phi) * x.y(), std::sin(phi) * x.x() + std::cos(phi) * x.y(), x.z()};
}

// The family walls with their standard 3.4 Å step (armchair 5, zigzag 9).
std::vector<std::pair<int, int>> walls(TubeFamily f, int count) {
  const int step = nearestIndexStep(f, 3.4 * units::kAngstromInBohr, kBond);
  return familyWalls(f, step, count, step);
}

TEST(TubeSectorBuilder, StandardStepsAreTheVanDerWaalsSpacing) {
  EXPECT_EQ(nearestIndexStep(TubeFamily::Armchair, 3.4 * units::kAngstromInBohr, kBond), 5);
  EXPECT_EQ(nearestIndexStep(TubeFamily::Zigzag, 3.4 * units::kAngstromInBohr, kBond), 9);
  const auto w = familyWalls(TubeFamily::Zigzag, 9, 3, 9);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[2], std::make_pair(27, 0));
  EXPECT_EQ(largestSectorOrder(w), 9);
  EXPECT_EQ(largestSectorOrder({{40, 40}, {35, 35}}), 5);
  EXPECT_EQ(largestSectorOrder({{40, 0}, {35, 0}}), 5);
}

// Rotating the sector by 2 pi j / d, j = 0..d-1, gives back the translational cell atom by atom.
TEST(TubeSectorBuilder, SectorImagesAreTheFullTubeForOneToSixWalls) {
  for (TubeFamily f : {TubeFamily::Armchair, TubeFamily::Zigzag}) {
    for (int count = 1; count <= 6; ++count) {
      const auto w = walls(f, count);
      const int d = largestSectorOrder(w);
      const ObjectiveCell sector = buildMultiWallSector(w, kBond, d);
      const ObjectiveCell full = buildMultiWallTranslational(w, kBond);
      ASSERT_EQ(sector.atomCount() * d, full.atomCount()) << count;
      EXPECT_EQ(sector.symmetry.rotationOrder(), d);
      EXPECT_EQ(sector.symmetry.twist(), 0.0);
      EXPECT_NEAR(sector.symmetry.translation(), full.symmetry.translation(), 1e-12);
      std::vector<bool> matched(full.atomCount(), false);
      for (int j = 0; j < d; ++j)
        for (int a = 0; a < sector.atomCount(); ++a) {
          const Eigen::Vector3d x = rotateZ(sector.positions.col(a), 2 * units::kPi * j / d);
          int hit = -1;
          for (int b = 0; b < full.atomCount() && hit < 0; ++b) {
            Eigen::Vector3d dx = full.positions.col(b) - x;
            dx.z() -= full.symmetry.translation() * std::round(dx.z() / full.symmetry.translation());
            if (dx.norm() < 1e-8) hit = b;
          }
          ASSERT_GE(hit, 0) << "family " << static_cast<int>(f) << ", " << count << " walls: image not in the tube";
          EXPECT_FALSE(matched[hit]) << "two images on one atom";
          matched[hit] = true;
        }
    }
  }
}

// Per wall: 4 (n^2+nm+m^2) / (d_R d) atoms at the roll-up radius, and each atom's three nearest
// neighbours (over the sector's images) at the chord lengths of the three sheet bonds.
TEST(TubeSectorBuilder, EveryWallIsAnIdealRollUpWithItsOwnAtomCount) {
  for (TubeFamily f : {TubeFamily::Armchair, TubeFamily::Zigzag}) {
    const auto w = walls(f, 4);
    const int d = largestSectorOrder(w);
    const ObjectiveCell cell = buildMultiWallSector(w, kBond, d);
    const double t = cell.symmetry.translation();
    int offset = 0;
    std::vector<int> counts;
    for (const auto& [n, m] : w) {
      const NanotubeRollUp tube(n, m, kBond);
      const int count = static_cast<int>(tube.translationalAtomCount() / d);
      counts.push_back(count);
      // Closed-form bond lengths: a sheet bond (s along C_h, z along T) becomes the chord
      // sqrt((2 R sin(s / 2R))^2 + z^2).
      const Eigen::Vector2d c = tube.chiral().normalized();
      std::vector<double> expected;
      const Eigen::Vector2d b0 = (tube.a1() + tube.a2()) / 3.0;
      for (const Eigen::Vector2d& bond : {b0, Eigen::Vector2d(b0 - tube.a1()), Eigen::Vector2d(b0 - tube.a2())}) {
        const double s = bond.dot(c), z = c.x() * bond.y() - c.y() * bond.x();
        const double chord = 2 * tube.radius() * std::sin(s / (2 * tube.radius()));
        expected.push_back(std::hypot(chord, z));
      }
      std::sort(expected.begin(), expected.end());
      for (int a = offset; a < offset + count; ++a) {
        const Eigen::Vector3d x = cell.positions.col(a);
        EXPECT_NEAR(x.head<2>().norm(), tube.radius(), 1e-9);
        std::vector<double> dist;
        for (int b = offset; b < offset + count; ++b)
          for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
              Eigen::Vector3d y = rotateZ(cell.positions.col(b), 2 * units::kPi * j / d);
              y.z() += k * t;
              const double r = (y - x).norm();
              if (r > 1e-9) dist.push_back(r);
            }
        std::sort(dist.begin(), dist.end());
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(dist[i], expected[i], 1e-9) << "wall (" << n << "," << m << ")";
        EXPECT_GT(dist[3], 1.5 * kBond);  // exactly three bonds
      }
      offset += count;
    }
    EXPECT_EQ(offset, cell.atomCount());
    for (std::size_t k = 1; k < counts.size(); ++k) EXPECT_GT(counts[k], counts[k - 1]);  // outer walls hold more
  }
}

// The example of issue 15: the C5 sectors of (35,35)@(40,40) and (35,0)@(40,0), 28 + 32 atoms.
TEST(TubeSectorBuilder, FiveFoldSectorOfTwoWallsHas28Plus32Atoms) {
  for (const auto& w : {std::vector<std::pair<int, int>>{{35, 35}, {40, 40}},
                        std::vector<std::pair<int, int>>{{35, 0}, {40, 0}}}) {
    const ObjectiveCell c = buildMultiWallSector(w, kBond, 5);
    ASSERT_EQ(c.atomCount(), 60);
    int inner = 0;
    const double rMid = 0.5 * (NanotubeRollUp(w[0].first, w[0].second, kBond).radius() +
                               NanotubeRollUp(w[1].first, w[1].second, kBond).radius());
    for (int a = 0; a < c.atomCount(); ++a) inner += c.positions.col(a).head<2>().norm() < rMid;
    EXPECT_EQ(inner, 28);
    // A wider sector (order 1 of the same walls) is the translational cell: 5x the atoms.
    EXPECT_EQ(buildMultiWallSector(w, kBond, 1).atomCount(), 300);
  }
}

TEST(TubeSectorBuilder, BadRequestsAreClearErrors) {
  auto fails = [](auto f, const std::string& text) {
    try {
      f();
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  fails([] { buildMultiWallSector({{35, 35}, {40, 40}}, kBond, 10); }, "divisor of gcd");
  fails([] { buildMultiWallSector({{35, 35}, {40, 40}}, kBond, 0); }, "rotation order");
  fails([] { buildMultiWallSector({{10, 10}, {20, 0}}, kBond, 10); }, "incommensurate");
  fails([] { familyWalls(TubeFamily::Armchair, 0, 2, 5); }, "inner wall index");
  fails([] { familyWalls(TubeFamily::Armchair, 5, 0, 5); }, "walls");
  fails([] { tubeFamily("chiral", "<command line>", "--family"); }, "armchair or zigzag");
}

}  // namespace
}  // namespace mesochain::objective
