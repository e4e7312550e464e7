#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/graphene_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kAngstromInBohr;
using units::kPi;

namespace {
const double kBond = 1.42 * kAngstromInBohr;
const double kLayer = 3.35 * kAngstromInBohr;
}  // namespace

TEST(GrapheneRingSector, CountsRadiiAndSymmetry) {
  const int na = 40, cells = 2, layers = 3;
  const ObjectiveCell c =
      buildGrapheneRingSector(layers, Direction::Zigzag, na, cells, kLayer, kBond);
  EXPECT_EQ(c.atomCount(), 4 * cells * layers);
  EXPECT_EQ(c.symmetry.rotationOrder(), na);
  EXPECT_DOUBLE_EQ(c.symmetry.twist(), 0.0);
  EXPECT_NEAR(c.symmetry.translation(), 3 * kBond, 1e-12);  // armchair period along z
  const double rMid = na * cells * std::sqrt(3.0) * kBond / (2 * kPi);
  for (int a = 0; a < c.atomCount(); ++a) {
    const int k = a / (4 * cells);
    EXPECT_NEAR(std::hypot(c.positions(0, a), c.positions(1, a)), rMid + (k - 1) * kLayer, 1e-12);
    const double phi = std::atan2(c.positions(1, a), c.positions(0, a));
    EXPECT_GE(phi, -1e-12);
    EXPECT_LT(phi, 2 * kPi / na);
  }
  EXPECT_NO_THROW(c.validate("ring", 0.5 * kAngstromInBohr));
  const ObjectiveCell arm = buildGrapheneRingSector(1, Direction::Armchair, na, cells, 0, kBond);
  EXPECT_NEAR(arm.symmetry.translation(), std::sqrt(3.0) * kBond, 1e-12);
}

TEST(GrapheneRingSector, MiddleLayerIsUnstrainedAndLayersAreBernal) {
  for (Direction dir : {Direction::Zigzag, Direction::Armchair}) {
    const int na = 30, cells = 3;
    const ObjectiveCell c = buildGrapheneRingSector(3, dir, na, cells, kLayer, kBond);
    const double rMid = std::hypot(c.positions(0, 4 * cells), c.positions(1, 4 * cells));
    // Arc/axial coordinates (R_mid * phi, z) of layer k's images over a few sectors and steps.
    auto layer = [&](int k) {
      std::vector<Eigen::Vector2d> pts;
      for (long zeta = -2; zeta <= 2; ++zeta)
        for (int s = -2; s <= 2; ++s)
          for (int a = 4 * cells * k; a < 4 * cells * (k + 1); ++a) {
            const Eigen::Vector3d y = c.symmetry.apply({zeta, (s + na) % na}, c.positions.col(a));
            double phi = std::atan2(y.y(), y.x());
            pts.emplace_back(rMid * phi, y.z());
          }
      return pts;
    };
    const auto mid = layer(1);
    // Every middle-layer cell atom has exactly 3 neighbours at one bond length in the
    // unrolled frame: the middle layer is flat graphene.
    for (int a = 0; a < 4 * cells; ++a) {
      const Eigen::Vector3d x = c.positions.col(4 * cells + a);
      const Eigen::Vector2d p(rMid * std::atan2(x.y(), x.x()), x.z());
      int bonded = 0;
      for (const auto& q : mid) {
        const double d = (q - p).norm();
        if (d > 1e-9 && d < 1.2 * kBond) {
          EXPECT_NEAR(d, kBond, 1e-9);
          ++bonded;
        }
      }
      EXPECT_EQ(bonded, 3);
    }
    // AB stacking: half of the atoms of layer 0 sit (in angle and z) on atoms of layer 1.
    int over = 0;
    for (int a = 0; a < 4 * cells; ++a) {
      const Eigen::Vector3d x = c.positions.col(a);
      const Eigen::Vector2d p(rMid * std::atan2(x.y(), x.x()), x.z());
      for (const auto& q : mid)
        if ((q - p).norm() < 1e-9) ++over;
    }
    EXPECT_EQ(over, 2 * cells);
  }
}

TEST(GrapheneRingSector, RejectsBadInput) {
  EXPECT_THROW(buildGrapheneRingSector(0, Direction::Zigzag, 10, 1, kLayer, kBond), InputError);
  EXPECT_THROW(buildGrapheneRingSector(2, Direction::Zigzag, 0, 1, kLayer, kBond), InputError);
  EXPECT_THROW(buildGrapheneRingSector(2, Direction::Zigzag, 10, 0, kLayer, kBond), InputError);
  EXPECT_THROW(buildGrapheneRingSector(2, Direction::Zigzag, 10, 1, -1.0, kBond), InputError);
  // 10 layers around a ring of radius ~4 Å: the inner layers would have negative radius.
  EXPECT_THROW(buildGrapheneRingSector(10, Direction::Zigzag, 10, 1, kLayer, kBond), InputError);
}

// Stacks of 1..6 layers along both directions: the right number of atoms, layer radii one
// interlayer apart about an unstrained middle, and no atoms (or images) closer than 0.9 bond
// (layers keep the middle layer's angles, so layer k is compressed by R_k / R_mid: at
// N_a = 200 the innermost of 6 layers by 3 %; at N_a = 60 by 10 %, which this would catch).
TEST(GrapheneRingSector, OneToSixLayersArmchairAndZigzag) {
  for (Direction dir : {Direction::Armchair, Direction::Zigzag})
    for (int layers = 1; layers <= 6; ++layers) {
      const int na = 200, cells = 2;
      const ObjectiveCell c = buildGrapheneRingSector(layers, dir, na, cells, kLayer, kBond);
      ASSERT_EQ(c.atomCount(), 4 * cells * layers);
      double rMin = 1e9, rMax = 0;
      for (int a = 0; a < c.atomCount(); ++a) {
        const double r = std::hypot(c.positions(0, a), c.positions(1, a));
        rMin = std::min(rMin, r), rMax = std::max(rMax, r);
      }
      EXPECT_NEAR(rMax - rMin, (layers - 1) * kLayer, 1e-9);
      const double period = dir == Direction::Zigzag ? std::sqrt(3.0) * kBond : 3 * kBond;
      EXPECT_NEAR(0.5 * (rMax + rMin), na * cells * period / (2 * kPi), 1e-9);
      EXPECT_NO_THROW(c.validate("stack", 0.9 * kBond)) << layers << " layers";
    }
}
