#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kAngstromInBohr;
using units::kPi;

namespace {

const double kBond = 1.42 * kAngstromInBohr;

// Every image of the cell atoms with lo <= z < hi (the cell atoms are near z = 0).
std::vector<Eigen::Vector3d> pointsInWindow(const ObjectiveCell& cell, double lo, double hi) {
  std::vector<Eigen::Vector3d> pts;
  const Symmetry& s = cell.symmetry;
  const long zmax = static_cast<long>(std::ceil((hi + 50.0) / s.translation()));
  for (long zeta = -zmax; zeta <= zmax; ++zeta)
    for (int c = 0; c < s.rotationOrder(); ++c)
      for (int a = 0; a < cell.atomCount(); ++a) {
        const Eigen::Vector3d y = s.apply({zeta, c}, cell.positions.col(a));
        if (y.z() >= lo && y.z() < hi) pts.push_back(y);
      }
  return pts;
}

// Number of points of `a` without a partner in `b` within tol.
int unmatched(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
              double tol) {
  int n = 0;
  for (const auto& p : a) {
    bool found = false;
    for (const auto& q : b)
      if ((p - q).norm() < tol) {
        found = true;
        break;
      }
    if (!found) ++n;
  }
  return n;
}

}  // namespace

TEST(NanotubeBuilder, TranslationalAtomCounts) {
  EXPECT_EQ(buildNanotubeTranslational(5, 5, kBond).atomCount(), 20);
  EXPECT_EQ(buildNanotubeTranslational(30, 30, kBond).atomCount(), 120);
  EXPECT_EQ(buildNanotubeTranslational(10, 0, kBond).atomCount(), 40);
  EXPECT_EQ(buildNanotubeTranslational(6, 4, kBond).atomCount(), 152);  // 4*76/2
  EXPECT_EQ(buildNanotubeTranslational(8, 2, kBond).atomCount(), 56);   // 4*84/6
  const ObjectiveCell rot = buildNanotubeTranslational(5, 5, kBond, true);
  EXPECT_EQ(rot.atomCount(), 4);
  EXPECT_EQ(rot.symmetry.rotationOrder(), 5);
  EXPECT_EQ(buildNanotubeTranslational(8, 2, kBond, true).atomCount(), 28);
}

TEST(NanotubeBuilder, RadiusAndScrewOfAchiralTubes) {
  const NanotubeRollUp t1010(10, 10, kBond);
  EXPECT_NEAR(t1010.radius() / kAngstromInBohr, 6.78, 0.01);
  const double a = std::sqrt(3.0) * kBond;
  const ObjectiveCell arm = buildNanotubeHelical(5, 5, kBond);
  EXPECT_EQ(arm.atomCount(), 2);
  EXPECT_EQ(arm.symmetry.rotationOrder(), 5);
  EXPECT_NEAR(arm.symmetry.translation(), a / 2, 1e-12);
  EXPECT_NEAR(arm.symmetry.twist(), kPi / 5, 1e-12);
  const ObjectiveCell zig = buildNanotubeHelical(10, 0, kBond);
  EXPECT_EQ(zig.symmetry.rotationOrder(), 10);
  EXPECT_NEAR(zig.symmetry.translation(), std::sqrt(3.0) * a / 2, 1e-12);
  EXPECT_NEAR(zig.symmetry.twist(), kPi / 10, 1e-12);  // +18 degrees (boundary value)
  // Every atom lies on the cylinder.
  for (const auto& c : {arm, zig})
    for (int k = 0; k < c.atomCount(); ++k)
      EXPECT_NEAR(std::hypot(c.positions(0, k), c.positions(1, k)),
                  c.positions.col(0).head<2>().norm(), 1e-12);
}

TEST(NanotubeBuilder, ChiralTwistIsReducedAndTranslationPositive) {
  for (auto [n, m] : std::vector<std::pair<int, int>>{{6, 4}, {8, 2}, {7, 3}, {12, 5}, {4, 6}}) {
    const ObjectiveCell c = buildNanotubeHelical(n, m, kBond);
    const int na = std::gcd(n, m);
    EXPECT_EQ(c.symmetry.rotationOrder(), na);
    EXPECT_GT(c.symmetry.translation(), 0.0);
    EXPECT_GT(c.symmetry.twist(), -kPi / na);
    EXPECT_LE(c.symmetry.twist(), kPi / na + 1e-15);
    // T = N_a * A_cell / |C_h| (White et al. 1993).
    const double a = std::sqrt(3.0) * kBond;
    const double ch = a * std::sqrt(n * n + n * m + m * m);
    EXPECT_NEAR(c.symmetry.translation(), na * std::sqrt(3.0) / 2 * a * a / ch, 1e-12);
  }
}

TEST(NanotubeBuilder, HelicalAndTranslationalCellsGenerateTheSameTube) {
  for (auto [n, m] : std::vector<std::pair<int, int>>{{5, 5}, {10, 0}, {6, 4}, {8, 2}}) {
    const ObjectiveCell helical = buildNanotubeHelical(n, m, kBond);
    const ObjectiveCell trans = buildNanotubeTranslational(n, m, kBond);
    const ObjectiveCell sector = buildNanotubeTranslational(n, m, kBond, true);
    const double period = trans.symmetry.translation();
    // A window of two periods, shifted off any atom plane.
    const double lo = -0.37 * period, hi = 1.63 * period;
    const auto ph = pointsInWindow(helical, lo, hi);
    const auto pt = pointsInWindow(trans, lo, hi);
    const auto ps = pointsInWindow(sector, lo, hi);
    SCOPED_TRACE(std::to_string(n) + "," + std::to_string(m));
    EXPECT_EQ(ph.size(), static_cast<std::size_t>(2 * trans.atomCount()));
    EXPECT_EQ(pt.size(), ph.size());
    EXPECT_EQ(ps.size(), ph.size());
    EXPECT_EQ(unmatched(ph, pt, 1e-8), 0);
    EXPECT_EQ(unmatched(pt, ph, 1e-8), 0);
    EXPECT_EQ(unmatched(ps, ph, 1e-8), 0);
  }
}

TEST(NanotubeBuilder, NearestNeighboursAreTheRolledBonds) {
  for (auto [n, m] : std::vector<std::pair<int, int>>{{5, 5}, {10, 0}, {6, 4}, {8, 2}}) {
    const ObjectiveCell c = buildNanotubeHelical(n, m, kBond);
    // Independent chord lengths: the three bond vectors of the sheet, split along C_h (arc s)
    // and across it (z); on the cylinder the arc s becomes a chord 2 R sin(s / 2R).
    const double a = std::sqrt(3.0) * kBond;
    const Eigen::Vector2d a1(a * std::sqrt(3.0) / 2, a / 2), a2(a * std::sqrt(3.0) / 2, -a / 2);
    const Eigen::Vector2d ch = n * a1 + m * a2;
    const Eigen::Vector2d u = ch.normalized();
    const double radius = ch.norm() / (2 * kPi);
    const Eigen::Vector2d d1 = (a1 + a2) / 3;
    std::vector<double> expected;
    for (const Eigen::Vector2d& d : {d1, Eigen::Vector2d(d1 - a1), Eigen::Vector2d(d1 - a2)}) {
      EXPECT_NEAR(d.norm(), kBond, 1e-12);  // flat sheet bond length
      const double s = d.dot(u), z = u.x() * d.y() - u.y() * d.x();
      expected.push_back(std::hypot(2 * radius * std::sin(s / (2 * radius)), z));
    }
    std::sort(expected.begin(), expected.end());
    for (int i = 0; i < c.atomCount(); ++i) {
      std::vector<double> dist;
      const Eigen::Vector3d xi = c.positions.col(i);
      for (long zeta = -20; zeta <= 20; ++zeta)
        for (int cc = 0; cc < c.symmetry.rotationOrder(); ++cc)
          for (int j = 0; j < c.atomCount(); ++j) {
            if (i == j && zeta == 0 && cc == 0) continue;
            dist.push_back((c.symmetry.apply({zeta, cc}, c.positions.col(j)) - xi).norm());
          }
      std::sort(dist.begin(), dist.end());
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(dist[k], expected[k], 1e-10);
      EXPECT_GT(dist[3], 1.5 * kBond);
    }
  }
}

TEST(NanotubeBuilder, UnrollingGivesBackTheSheet) {
  const NanotubeRollUp tube(6, 4, kBond);
  const ObjectiveCell c = buildNanotubeHelical(6, 4, kBond);
  const Eigen::Vector2d u = tube.chiral().normalized();
  const Eigen::Vector2d w(-u.y(), u.x());  // z = (C_h x r)/|C_h| = r . w
  Eigen::Matrix2d lat;
  lat << tube.a1(), tube.a2();
  const Eigen::Matrix2d inv = lat.inverse();
  for (long zeta = -6; zeta <= 6; ++zeta)
    for (int cc = 0; cc < 2; ++cc)
      for (int j = 0; j < 2; ++j) {
        const Eigen::Vector3d y = c.symmetry.apply({zeta, cc}, c.positions.col(j));
        const Eigen::Vector2d sz = tube.unrollToSheetFrame(y);
        // Sheet point (modulo C_h) minus the basis atom must be a lattice vector.
        const Eigen::Vector2d basis =
            j ? Eigen::Vector2d((tube.a1() + tube.a2()) / 3) : Eigen::Vector2d::Zero();
        const Eigen::Vector2d r = sz.x() * u + sz.y() * w - basis;
        const Eigen::Vector2d f = inv * r;
        EXPECT_NEAR(f.x(), std::round(f.x()), 1e-9);
        EXPECT_NEAR(f.y(), std::round(f.y()), 1e-9);
      }
}

TEST(NanotubeBuilder, MirrorImageAndInvalidIndices) {
  EXPECT_NEAR(NanotubeRollUp(4, 6, kBond).radius(), NanotubeRollUp(6, 4, kBond).radius(), 1e-12);
  EXPECT_THROW(buildNanotubeHelical(0, 0, kBond), InputError);
  EXPECT_THROW(buildNanotubeHelical(-1, 2, kBond), InputError);
  EXPECT_THROW(buildNanotubeHelical(5, -1, kBond), InputError);
  EXPECT_THROW(buildNanotubeHelical(5, 5, 0.0), InputError);
  EXPECT_THROW(buildNanotubeTranslational(5, 5, NAN), InputError);
}

TEST(NanotubeBuilder, MultiWallNeedsOnePeriod) {
  const ObjectiveCell dw = buildMultiWallTranslational({{5, 5}, {10, 10}}, kBond);
  EXPECT_EQ(dw.atomCount(), 60);
  EXPECT_NEAR(dw.symmetry.translation(), std::sqrt(3.0) * kBond, 1e-12);
  EXPECT_EQ(dw.symmetry.rotationOrder(), 1);
  EXPECT_NO_THROW(dw.validate("dw", 0.5 * kAngstromInBohr));
  try {
    buildMultiWallTranslational({{5, 5}, {10, 0}}, kBond);
    FAIL() << "incommensurate walls accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("incommensurate"), std::string::npos) << e.what();
  }
  EXPECT_THROW(buildMultiWallTranslational({{5, 5}, {5, 5}}, kBond), InputError);
  EXPECT_THROW(buildMultiWallTranslational({}, kBond), InputError);
}
