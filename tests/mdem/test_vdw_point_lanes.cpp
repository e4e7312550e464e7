// The two-lane quadrature of the table kernel (vdw_contact.cpp, tableQuadrature): two Gauss
// points of a pair at a time, their bicubic lookups interleaved (BicubicTable::evalPair). The
// lookup of two points must be the lookup of each point bit for bit, and the rule must add each
// point once, for even and odd point counts (an odd rule's last point runs in both lanes).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "contact_fixture.hpp"
#include "mdem/contacts/segment_line_table.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

constexpr double kHalf = 0.5 * kSegmentLength;

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Points (h, u) over the whole table and beyond it (the clamps), on nodes (local coordinate 0),
// on the last row and column, and in cells next to the cuts.
std::vector<std::pair<double, double>> lookupPoints(const SegmentLineTable& table) {
  std::vector<std::pair<double, double>> out;
  const double hMax = table.hCut() + 3 * table.step(), uMax = table.uCut() + 3 * table.step();
  std::uint64_t state = 12345;
  auto uniform = [&state]() {  // a fixed LCG: the same points on every platform
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int k = 0; k < 4000; ++k) out.emplace_back(hMax * uniform(), uMax * uniform());
  for (int i = 0; i < 40; ++i) out.emplace_back(i * table.step() * 7, i * table.step() * 11);  // nodes
  for (double h : {0.0, table.hCut() - 1e-9, table.hCut(), table.hCut() + table.step(), 1e3})
    for (double u : {0.0, 0.5 * table.uCut(), table.uCut() - 1e-9, table.uCut(), 1e3}) out.emplace_back(h, u);
  return out;
}

TEST(MdemVdwPointLanes, PairLookupEqualsTheScalarLookupBitForBit) {
  const SegmentLineTable table(tubePotential(), kHalf);
  const auto points = lookupPoints(table);
  int nonzero = 0;
  // Each point in lane 0 with its successor in lane 1, so every point is seen in both lanes.
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& [h0, u0] = points[k];
    const auto& [h1, u1] = points[(k + 1) % points.size()];
    Lanes dh, du;
    const Lanes v = table.evalPair(Lanes{h0, h1}, Lanes{u0, u1}, &dh, &du);
    for (int lane = 0; lane < 2; ++lane) {
      const double h = lane ? h1 : h0, u = lane ? u1 : u0;
      double sdh, sdu;
      const double sv = table.eval(h, u, &sdh, &sdu);
      nonzero += sv != 0.0;
      ASSERT_EQ(bits(v[lane]), bits(sv)) << h << " " << u << " lane " << lane;
      ASSERT_EQ(bits(dh[lane]), bits(sdh)) << h << " " << u << " lane " << lane;
      ASSERT_EQ(bits(du[lane]), bits(sdu)) << h << " " << u << " lane " << lane;
    }
  }
  EXPECT_GT(nonzero, 2000);  // the comparison is not among zeros
}

// Crossed and nearly parallel pairs on the wall, in the well and in the tail, offset so that some
// Gauss points lie beyond the cuts (masked) and others inside.
std::vector<std::pair<Segment, Segment>> pairGeometries() {
  const double d = tubePotential().equilibriumDistance();
  std::vector<std::pair<Segment, Segment>> out;
  const Segment a{Vec3(0.1, -0.2, 0.3), Vec3(1.0, 0.2, -0.1).normalized(), kHalf};
  const Vec3 n = a.axis.unitOrthogonal(), m = a.axis.cross(n);
  for (double theta : {0.0, 0.02, 0.4, 1.1, 1.5708})
    for (double extra : {-0.04, 0.0013, 0.3, 1.0})
      for (double shift : {0.0, 1.3, 2.9}) {
        const Vec3 tb = (std::cos(theta) * a.axis + std::sin(theta) * (0.8 * m + 0.2 * n).normalized()).normalized();
        out.emplace_back(a, Segment{a.centre + (d + extra) * n + shift * a.axis, tb, kHalf});
      }
  return out;
}

// The line kernel (tube_potential.hpp's H, three lookups a point, one point at a time) against the
// two-lane table kernel with the same rule: equal to round-off for every point count, so no point
// is dropped or added twice (a point adds about |E| / n; the tolerance is 1e-11 of the scale).
TEST(MdemVdwPointLanes, EveryRuleSizeEqualsThePointByPointLineKernel) {
  AnisotropicVdwKernel kernel(tubePotential(), kHalf, 8);
  const double scale = std::abs(tubePotential().wellDepthPerLength()) * kSegmentLength;
  for (int points : {1, 2, 3, 5, 7, 8, 9, 12}) {
    SCOPED_TRACE(points);
    kernel.rule = gaussLegendre(points);
    int interacting = 0;
    for (const auto& [a, b] : pairGeometries()) {
      const ContactPairResult line = anisotropicVdw(tubePotential(), kernel.rule, a, b);
      const ContactPairResult lanes = anisotropicVdw(kernel, a, b);
      interacting += line.energy != 0.0;
      EXPECT_NEAR(lanes.energy, line.energy, 1e-11 * scale);
      const double fs = 1e-9 * (line.forceA.norm() + line.torqueA.norm() + line.torqueB.norm() + 1.0);
      EXPECT_LT((lanes.forceA - line.forceA).norm(), fs);
      EXPECT_LT((lanes.forceB - line.forceB).norm(), fs);
      EXPECT_LT((lanes.torqueA - line.torqueA).norm(), fs);
      EXPECT_LT((lanes.torqueB - line.torqueB).norm(), fs);
    }
    EXPECT_GT(interacting, 30);
  }
}

}  // namespace
}  // namespace mesochain::mdem
