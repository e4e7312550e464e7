// Bent graphene stacks along any sheet direction (n, m): the sheet cell C x T, the unstrained
// middle layer, Bernal stacking by the same sheet vector for every direction, armchair and
// zigzag as (1, 1) and (1, 0), and the monolayer sector as a piece of the (c N_a n, c N_a m) tube.
#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kAngstromInBohr;
using units::kPi;

namespace {
const double kBond = 1.42 * kAngstromInBohr;
const double kLayer = 3.35 * kAngstromInBohr;

// The sheet lattice of nanotube_builder.hpp, written out here.
const double kA = std::sqrt(3.0) * kBond;
const Eigen::Vector2d kA1 = kA * Eigen::Vector2d(std::sqrt(3.0) / 2, 0.5);
const Eigen::Vector2d kA2 = kA * Eigen::Vector2d(std::sqrt(3.0) / 2, -0.5);

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// (arc, z) of the atoms of layer k, flattened with the middle radius (arc = R_mid * phi), and
// of their images over a few sectors and translations.
std::vector<Eigen::Vector2d> flatLayer(const ObjectiveCell& c, int perLayer, int k, double rMid,
                                       bool images) {
  std::vector<Eigen::Vector2d> pts;
  const int na = c.symmetry.rotationOrder();
  const int range = images ? 2 : 0;
  for (long zeta = -range; zeta <= range; ++zeta)
    for (int s = -range; s <= range; ++s)
      for (int a = perLayer * k; a < perLayer * (k + 1); ++a) {
        const Eigen::Vector3d y = c.symmetry.apply({zeta, (s + na) % na}, c.positions.col(a));
        pts.emplace_back(rMid * std::atan2(y.y(), y.x()), y.z());
      }
  return pts;
}

bool contains(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& p, double tol) {
  for (const auto& q : pts)
    if ((q - p).norm() < tol) return true;
  return false;
}

}  // namespace

// The cell of the old rectangle construction (x zigzag, y armchair, 4 atoms; Bernal shift of
// one bond along y), written independently here: (1, 0) and (1, 1) give the same atoms.
TEST(GrapheneChiral, ZigzagAndArmchairAreTheRectangleCells) {
  const double b = kBond, a = kA;
  const double cellX[4] = {0.0, a / 2, a / 2, 0.0};
  const double cellY[4] = {0.0, b / 2, 1.5 * b, 2.0 * b};
  for (bool zigzag : {true, false}) {
    const int na = 30, cells = 2, layers = 3;
    const ChiralIndices dir = zigzag ? ChiralIndices{1, 0} : ChiralIndices{1, 1};
    const ObjectiveCell c = buildGrapheneRingSector(layers, dir, na, cells, kLayer, kBond);
    const double arcPeriod = zigzag ? a : 3 * b, axialPeriod = zigzag ? 3 * b : a;
    const double rMid = na * cells * arcPeriod / (2 * kPi);
    std::vector<Eigen::Vector3d> ref;
    for (int k = 0; k < layers; ++k)
      for (int cell = 0; cell < cells; ++cell)
        for (int s = 0; s < 4; ++s) {
          const double y = std::fmod(cellY[s] + (k % 2 ? b : 0.0), 3 * b);
          const double arc = (zigzag ? cellX[s] : y) + cell * arcPeriod;
          const double radius = rMid + (k - 1) * kLayer;
          ref.emplace_back(radius * std::cos(arc / rMid), radius * std::sin(arc / rMid),
                           zigzag ? y : cellX[s]);
        }
    ASSERT_EQ(c.atomCount(), static_cast<int>(ref.size()));
    EXPECT_NEAR(c.symmetry.translation(), axialPeriod, 1e-12);
    for (int i = 0; i < c.atomCount(); ++i) {
      int matches = 0;
      for (const auto& r : ref)
        if ((c.positions.col(i) - r).norm() < 1e-9) ++matches;
      EXPECT_EQ(matches, 1) << (zigzag ? "zigzag" : "armchair") << " atom " << i;
    }
    // The enum overload is the same builder.
    const ObjectiveCell viaEnum = buildGrapheneRingSector(
        layers, zigzag ? Direction::Zigzag : Direction::Armchair, na, cells, kLayer, kBond);
    EXPECT_LT((viaEnum.positions - c.positions).cwiseAbs().maxCoeff(), 1e-15);
  }
}

// Atoms per layer 2 |C x T| / |a1 x a2|, |C| along the arc and |T| = sqrt3 |C| / d_R along z,
// from the lattice vectors (not from the closed forms the builder uses); non-primitive
// indices reduce by their gcd.
TEST(GrapheneChiral, SheetCellIsTheParallelogramCxT) {
  const int cases[][2] = {{1, 0}, {1, 1}, {2, 1}, {3, 1}, {3, 2}, {4, 1}, {5, 2}, {4, 4}, {6, 3}, {7, 0}};
  for (const auto& nm : cases) {
    const long g = std::gcd(nm[0], nm[1]), n = nm[0] / g, m = nm[1] / g;
    const long dr = std::gcd(2 * n + m, 2 * m + n);
    const Eigen::Vector2d ch = n * kA1 + m * kA2;
    const Eigen::Vector2d t = ((2 * m + n) / dr) * kA1 - ((2 * n + m) / dr) * kA2;
    EXPECT_NEAR(ch.dot(t), 0.0, 1e-9);
    const GrapheneSheetCell s = grapheneSheetCell({nm[0], nm[1]}, kBond);
    EXPECT_EQ(s.primitive.n, n);
    EXPECT_EQ(s.primitive.m, m);
    EXPECT_NEAR(s.arcPeriod, ch.norm(), 1e-10);
    EXPECT_NEAR(s.axialPeriod, t.norm(), 1e-10);
    EXPECT_NEAR(s.axialPeriod, std::sqrt(3.0) * ch.norm() / dr, 1e-10);
    const double atoms = 2 * std::abs(cross(ch, t)) / std::abs(cross(kA1, kA2));
    EXPECT_EQ(s.atomsPerLayer, std::lround(atoms)) << n << "," << m;
    const ObjectiveCell c = buildGrapheneRingSector(2, {nm[0], nm[1]}, 40, 2, kLayer, kBond);
    EXPECT_EQ(c.atomCount(), 2 * 2 * s.atomsPerLayer);
    EXPECT_NEAR(c.symmetry.translation(), t.norm(), 1e-10);
    EXPECT_EQ(c.symmetry.rotationOrder(), 40);
    EXPECT_EQ(c.symmetry.twist(), 0.0);
  }
  EXPECT_EQ(grapheneSheetCell({2, 1}, kBond).atomsPerLayer, 28);
}

// The middle layer, flattened (arc = R_mid phi), is graphene: every atom has exactly three
// neighbours, all one bond away, no other atom within 1.5 bonds. The outer layer is the inner
// one shifted by the sheet vector (a1 + a2)/3 (one bond along the armchair direction), in
// (angle, z): Bernal stacking by the same in-plane vector for every direction.
TEST(GrapheneChiral, MiddleLayerIsGrapheneAndLayersAreBernal) {
  const int cases[][2] = {{2, 1}, {3, 1}, {5, 2}, {1, 0}, {1, 1}};
  for (const auto& nm : cases) {
    const int na = 24, cells = 2;
    const ChiralIndices dir{nm[0], nm[1]};
    const GrapheneSheetCell sheet = grapheneSheetCell(dir, kBond);
    const ObjectiveCell c = buildGrapheneRingSector(3, dir, na, cells, kLayer, kBond);
    const int perLayer = cells * sheet.atomsPerLayer;
    const double rMid = na * cells * sheet.arcPeriod / (2 * kPi);
    for (int a = 0; a < c.atomCount(); ++a)
      EXPECT_NEAR(std::hypot(c.positions(0, a), c.positions(1, a)),
                  rMid + (a / perLayer - 1) * kLayer, 1e-9);
    const auto mid = flatLayer(c, perLayer, 1, rMid, true);
    for (const auto& p : flatLayer(c, perLayer, 1, rMid, false)) {
      int bonded = 0;
      for (const auto& q : mid) {
        const double d = (q - p).norm();
        if (d > 1e-9 && d < 1.5 * kBond) {
          EXPECT_NEAR(d, kBond, 1e-9) << nm[0] << "," << nm[1];
          ++bonded;
        }
      }
      EXPECT_EQ(bonded, 3) << nm[0] << "," << nm[1];
    }
    // The shift in the (arc, z) frame: s.C/|C| and (C x s)/|C|.
    const Eigen::Vector2d ch = sheet.primitive.n * kA1 + sheet.primitive.m * kA2;
    const Eigen::Vector2d shift = (kA1 + kA2) / 3;
    const Eigen::Vector2d s(shift.dot(ch) / ch.norm(), cross(ch, shift) / ch.norm());
    int over = 0;
    for (const auto& p : flatLayer(c, perLayer, 0, rMid, false)) {
      EXPECT_TRUE(contains(mid, p + s, 1e-9)) << nm[0] << "," << nm[1];
      if (contains(mid, p, 1e-9)) ++over;
    }
    EXPECT_EQ(over, perLayer / 2);  // AB: half of the atoms sit over atoms, half over hexagons
    // Layer 2 repeats layer 0 (ABA).
    const auto outer = flatLayer(c, perLayer, 2, rMid, false);
    const auto inner = flatLayer(c, perLayer, 0, rMid, true);
    for (const auto& p : outer) EXPECT_TRUE(contains(inner, p, 1e-9));
  }
}

// 1..6 layers of (2, 1): radii one interlayer apart about the unstrained middle and no two
// atoms (or images) closer than 0.9 bond (R_mid = 155 Å: the innermost of 6 layers is
// compressed along the arc by 5.4 %).
TEST(GrapheneChiral, OneToSixLayers) {
  for (int layers = 1; layers <= 6; ++layers) {
    const int na = 150;
    const ObjectiveCell c = buildGrapheneRingSector(layers, {2, 1}, na, 1, kLayer, kBond);
    ASSERT_EQ(c.atomCount(), 28 * layers);
    double rMin = 1e9, rMax = 0;
    for (int a = 0; a < c.atomCount(); ++a) {
      const double r = std::hypot(c.positions(0, a), c.positions(1, a));
      rMin = std::min(rMin, r), rMax = std::max(rMax, r);
      const double phi = std::atan2(c.positions(1, a), c.positions(0, a));
      EXPECT_GE(phi, -1e-12);
      EXPECT_LT(phi, 2 * kPi / na);
    }
    EXPECT_NEAR(rMax - rMin, (layers - 1) * kLayer, 1e-9);
    EXPECT_NEAR(0.5 * (rMax + rMin), na * std::sqrt(7.0) * kA / (2 * kPi), 1e-9);
    EXPECT_NO_THROW(c.validate("stack", 0.9 * kBond)) << layers << " layers";
  }
}

// A monolayer sector (2, 1) with N_a = 3 is one third of the (6, 3) tube: the same atoms as
// the tube's translational cell restricted to one sector, once the sheet origin is moved by
// (a1 + a2)/3 (the nanotube builder puts the other sublattice at the origin).
TEST(GrapheneChiral, MonolayerSectorIsASectorOfTheTube) {
  for (const auto& [na, cells] : {std::pair{3, 1}, std::pair{2, 2}}) {
    const int n = 2 * na * cells, m = na * cells;
    const ObjectiveCell sector = buildGrapheneRingSector(1, {2, 1}, na, cells, 0.0, kBond);
    const NanotubeRollUp tube(n, m, kBond);
    ObjectiveCell ref = buildNanotubeTranslational(n, m, kBond, true);
    const int refOrder = ref.symmetry.rotationOrder();  // gcd(n, m) = na * cells
    ASSERT_EQ(refOrder, na * cells);
    EXPECT_NEAR(ref.symmetry.translation(), sector.symmetry.translation(), 1e-10);
    ASSERT_EQ(ref.atomCount() * refOrder, sector.atomCount() * na);
    const Eigen::Vector3d moved = tube.roll((kA1 + kA2) / 3);
    const double dphi = std::atan2(moved.y(), moved.x()), dz = moved.z();
    const double period = sector.symmetry.translation(), wedge = 2 * kPi / refOrder;
    auto wrap = [](double x, double p) { return x - p * std::round(x / p); };
    for (int a = 0; a < sector.atomCount(); ++a) {
      const Eigen::Vector3d x = sector.positions.col(a);
      EXPECT_NEAR(x.head<2>().norm(), tube.radius(), 1e-9);
      const double phi = std::atan2(x.y(), x.x()) + dphi, z = x.z() + dz;
      int matches = 0;
      for (int b = 0; b < ref.atomCount(); ++b) {
        const Eigen::Vector3d y = ref.positions.col(b);
        if (std::abs(wrap(phi - std::atan2(y.y(), y.x()), wedge)) * tube.radius() < 1e-8 &&
            std::abs(wrap(z - y.z(), period)) < 1e-8)
          ++matches;
      }
      EXPECT_EQ(matches, 1) << "N_a = " << na << ", atom " << a;
    }
  }
}

TEST(GrapheneChiral, RejectsBadIndices) {
  for (const auto& nm : {ChiralIndices{0, 0}, ChiralIndices{-1, 0}, ChiralIndices{2, -1},
                         ChiralIndices{1, 2}}) {
    try {
      buildGrapheneRingSector(1, nm, 30, 1, kLayer, kBond);
      ADD_FAILURE() << nm.n << "," << nm.m << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("chiral"), std::string::npos) << e.what();
    }
  }
}
