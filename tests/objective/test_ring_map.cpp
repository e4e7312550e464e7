// Bending a straight cell into a ring: the ring's rotation reproduces the straight cell's
// translation images (within the 1/R strain of the cross-section), the map is proper (keeps
// handedness), and unbending returns the straight atoms.
#include <cmath>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/collapsed_tube_builder.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/core/ring_map.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
const double kBond = 1.42 * units::kAngstromInBohr;
}

TEST(RingMap, LargeRingKeepsDistancesAndUnbendsExactly) {
  const ObjectiveCell tube = buildNanotubeTranslational(6, 0, kBond);
  const BendFrame frame = bendFrame(tube, BendDirection::Soft);
  const int na = 4000;
  const ObjectiveCell ring = straightToRing(tube, frame, na);
  EXPECT_TRUE(ring.symmetry.isRing());
  EXPECT_EQ(ring.symmetry.rotationOrder(), na);
  const double t = tube.symmetry.translation();
  const double radius = na * t / (2 * units::kPi);
  // Distances between atoms and between an atom and the next cell's images: relative change
  // bounded by the cross-section radius over R.
  const double rTube = NanotubeRollUp(6, 0, kBond).radius();
  for (int a = 0; a < tube.atomCount(); ++a)
    for (int b = 0; b < tube.atomCount(); ++b)
      for (int step = 0; step <= 1; ++step) {
        const double d0 = (tube.symmetry.apply({step, 0}, tube.positions.col(b)) -
                           tube.positions.col(a)).norm();
        const double d1 = (ring.symmetry.apply({0, step}, ring.positions.col(b)) -
                           ring.positions.col(a)).norm();
        if (d0 > 0) {
          EXPECT_NEAR(d1 / d0, 1.0, 1.5 * rTube / radius);
        }
      }
  // Orientation: the triple product of three atoms' separations keeps its sign.
  auto triple = [](const Eigen::Matrix3Xd& p) {
    return (p.col(1) - p.col(0)).cross(p.col(2) - p.col(0)).dot(p.col(5) - p.col(0));
  };
  EXPECT_GT(triple(tube.positions) * triple(ring.positions), 0.0);
  // Unbending gives back the centred straight atoms, with e_r along x.
  const ObjectiveCell back = ringToStraight(ring, radius);
  EXPECT_NEAR(back.symmetry.translation(), t, 1e-9);
  const Eigen::Vector2d er = frame.radial, ea(-er.y(), er.x());
  for (int a = 0; a < tube.atomCount(); ++a) {
    const Eigen::Vector2d d = tube.positions.col(a).head<2>() - frame.centre;
    EXPECT_NEAR(back.positions(0, a), d.dot(er), 1e-9);
    EXPECT_NEAR(back.positions(1, a), d.dot(ea), 1e-9);
    EXPECT_NEAR(back.positions(2, a), tube.positions(2, a), 1e-9);
  }
  EXPECT_NEAR(meanRingRadius(ring), radius, 1e-9 * radius);
}

TEST(RingMap, SoftAndHardDirectionsOfACollapsedTube) {
  CollapseShape shape;
  shape.interlayer = 3.4 * units::kAngstromInBohr;
  shape.bulbRadius = shape.transitionRadius = 3.4 * units::kAngstromInBohr;
  const ObjectiveCell flat = buildCollapsedTube({{12, 12}}, kBond, shape);
  // Width along x, thickness along y: soft puts y along the radius, hard puts x.
  EXPECT_NEAR(std::abs(bendFrame(flat, BendDirection::Soft).radial.y()), 1.0, 1e-6);
  EXPECT_NEAR(std::abs(bendFrame(flat, BendDirection::Hard).radial.x()), 1.0, 1e-6);
  const int na = 400;
  const ObjectiveCell soft = straightToRing(flat, bendFrame(flat, BendDirection::Soft), na);
  const ObjectiveCell hard = straightToRing(flat, bendFrame(flat, BendDirection::Hard), na);
  // Spread of distances from the ring axis: the thickness (soft) or the width (hard).
  auto spread = [](const ObjectiveCell& c) {
    const Eigen::VectorXd r = c.positions.topRows(2).colwise().norm().transpose();
    return r.maxCoeff() - r.minCoeff();
  };
  const CollapsedDimensions dims = measureCollapsed(flat, shape.interlayer);
  EXPECT_LT(spread(soft), dims.thickness);
  EXPECT_NEAR(spread(hard), dims.width - shape.interlayer, 1e-6 * dims.width);
  // A ring too tight for the cross-section, and a twisted cell, are refused.
  EXPECT_THROW(straightToRing(flat, bendFrame(flat, BendDirection::Hard), 10), InputError);
  EXPECT_THROW(straightToRing(buildNanotubeHelical(5, 5, kBond), BendFrame{}, 100), InputError);
}
