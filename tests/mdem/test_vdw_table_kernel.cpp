// The fast paths of the anisotropic vdW contact (docs/mdem-contacts.md, "Cost of one contact"):
// the one-lookup table D of a whole segment against the three-lookup line integral H, its forces
// against finite differences, the far-pair early out (exact: the quadrature it skips returns
// exactly zero), and the quadrature count chosen from a tolerance (once per pair of kinds).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "contact_fixture.hpp"
#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/contacts/contact_file.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

constexpr double kHalf = 0.5 * kSegmentLength;

const AnisotropicVdwKernel& tableKernel(int points) {
  static const AnisotropicVdwKernel k8(tubePotential(), kHalf, 8);
  static const AnisotropicVdwKernel k12(tubePotential(), kHalf, 12);
  return points == 8 ? k8 : k12;
}

Segment seg(const Vec3& c, const Vec3& axis, double half = kHalf) { return {c, axis.normalized(), half}; }

// A spread of pair geometries: crossed at 0-90 degrees, on the wall, in the well, in the tail,
// offset along both axes, end-on, tilted out of the contact plane.
std::vector<std::pair<Segment, Segment>> geometries() {
  const double d = tubePotential().equilibriumDistance();
  std::vector<std::pair<Segment, Segment>> out;
  const Segment a = seg(Vec3(0.1, -0.2, 0.3), Vec3(1.0, 0.2, -0.1));
  const Vec3 n = a.axis.unitOrthogonal(), m = a.axis.cross(n);
  for (double theta : {0.0, 0.3, 0.7854, 1.2, 1.5708})
    // (Not exactly at d_eq: it lies on a table node, where the C1 bicubic's second derivative
    // jumps and a central difference of the energy is off by O(eps); the forces are still the
    // exact derivative on either side.)
    for (double extra : {-0.05, 0.0013, 0.15, 0.6, 1.0})
      for (double shift : {0.0, 0.7, 1.6, 2.4}) {
        const Vec3 tb = std::cos(theta) * a.axis + std::sin(theta) * (0.9 * m + 0.1 * n).normalized();
        out.emplace_back(a, seg(a.centre + (d + extra) * n + shift * a.axis - 0.3 * shift * tb, tb));
      }
  // End-on: b continues a's line beyond its end.
  out.emplace_back(a, seg(a.centre + 2.3 * a.axis, a.axis));
  return out;
}

TEST(MdemVdwTableKernel, EqualsTheLineIntegralKernel) {
  // lb = 1 nm is 200 table steps: the interpolant of D is the difference of the H interpolants.
  const QuadratureRule rule = gaussLegendre(8);
  const double scale = std::abs(tubePotential().wellDepthPerLength()) * kSegmentLength;
  int interacting = 0;
  for (const auto& [a, b] : geometries()) {
    const ContactPairResult line = anisotropicVdw(tubePotential(), rule, a, b);
    const ContactPairResult table = anisotropicVdw(tableKernel(8), a, b);
    interacting += line.energy != 0.0;
    EXPECT_NEAR(table.energy, line.energy, 1e-11 * scale);
    const double fs = 1e-9 * (line.forceA.norm() + line.torqueA.norm() + line.torqueB.norm() + 1.0);
    EXPECT_LT((table.forceA - line.forceA).norm(), fs);
    EXPECT_LT((table.forceB - line.forceB).norm(), fs);
    EXPECT_LT((table.torqueA - line.torqueA).norm(), fs);
    EXPECT_LT((table.torqueB - line.torqueB).norm(), fs);
  }
  EXPECT_GT(interacting, 60);  // the comparison is not among zeros
}

TEST(MdemVdwTableKernel, OtherPartnerLengthFallsBackToTheLineKernel) {
  const QuadratureRule rule = gaussLegendre(8);
  const double d = tubePotential().equilibriumDistance();
  const Segment a = seg(Vec3::Zero(), Vec3::UnitX()), b = seg(Vec3(0.3, d, 0.1), Vec3(1, 0, 1), 0.7);
  const ContactPairResult table = anisotropicVdw(tableKernel(8), a, b);
  EXPECT_LT(table.energy, 0.0);
  EXPECT_EQ(table.energy, anisotropicVdw(tubePotential(), rule, a, b).energy);
}

TEST(MdemVdwTableKernel, MatchesSurfaceQuadratureLikeTheLineKernel) {
  // The rows of tests/data/mdem/vdw_vs_surface_quadrature.csv, with the table kernel.
  testing::expectSurfaceQuadratureRows(
      [](const Segment& a, const Segment& b) { return anisotropicVdw(tableKernel(12), a, b).energy; });
}

// Forces and torques of the table kernel against central differences of its energy.
TEST(MdemVdwTableKernel, ForcesAndTorquesAreMinusEnergyGradient) {
  const double eps = 1e-6;
  int geometry = -1;
  for (const auto& [a0, b0] : geometries()) {
    SCOPED_TRACE(++geometry);
    const ContactPairResult r = anisotropicVdw(tableKernel(8), a0, b0);
    if (r.energy == 0.0) continue;
    // The end-on pair has |E| ~ 1e4 zJ and neither torque nor lateral force (the scales:
    // expectPairForcesAreMinusGradient, contact_fixture.hpp).
    auto energy = [](const Segment& a, const Segment& b) { return anisotropicVdw(tableKernel(8), a, b).energy; };
    testing::expectPairForcesAreMinusGradient(r, a0, b0, energy, eps, kHalf);
  }
}

// The early out (closest axis distance >= d_c + 3 steps: no quadrature) skips only quadratures
// that return exactly zero: between d_c + sqrt(5) steps and the early-out distance the full
// quadrature runs and must give exactly 0, so the energy has no jump at the early-out boundary.
TEST(MdemVdwTableKernel, FarPairEarlyOutSkipsOnlyExactZeros) {
  const TubePairPotential& p = tubePotential();
  const double dc = p.cutoffDistance(), step = p.gridStep(), farCut = dc + 3.0 * step;
  const QuadratureRule rule = gaussLegendre(8);
  const Segment a = seg(Vec3::Zero(), Vec3::UnitX());
  int evaluated = 0, nonzeroInside = 0;
  for (double theta : {0.0, 0.4, 1.5708})
    for (double endOn : {0.0, 1.0}) {
      // endOn = 0: b crosses above a's middle (distance along y); 1: b beyond a's end (along x).
      for (double dist = dc - 0.02; dist <= farCut + 0.01; dist += 2.5e-4) {
        const Vec3 tb = endOn > 0 ? Vec3(std::cos(theta), std::sin(theta), 0.0) : Vec3(std::cos(theta), 0.0, std::sin(theta));
        const Vec3 centre = endOn > 0 ? Vec3(kHalf + dist, 0, 0) + kHalf * tb : Vec3(0, dist, 0);
        const Segment b = seg(centre, tb);
        double sa, sb;
        closestPoints(a, b, &sa, &sb);
        const double gap = (a.centre + sa * a.axis - b.centre - sb * b.axis).norm();
        const double line = anisotropicVdw(p, rule, a, b).energy, table = anisotropicVdw(tableKernel(8), a, b).energy;
        if (gap >= dc + 2.3 * step) {
          EXPECT_EQ(line, 0.0) << theta << " " << endOn << " " << gap;
          EXPECT_EQ(table, 0.0) << theta << " " << endOn << " " << gap;
          evaluated += gap < farCut;
        } else if (gap < dc - 0.01) {
          nonzeroInside += line != 0.0;
        }
      }
    }
  EXPECT_GT(evaluated, 10);      // the band below the early out was sampled
  EXPECT_GT(nonzeroInside, 10);  // and the sweep starts where the contact is felt
}

// The quadrature skips single points beyond b's end whose distance from the segment (from its end)
// is at least the early-out distance: there the table's value and both slopes are exactly zero,
// so a pair's sums are those of the full rule bit for bit. Swept over the corner region up to the
// table's cuts, including the band just outside the early-out distance.
TEST(MdemVdwTableKernel, PointsBeyondTheEarlyOutDistanceFromAnEndAreExactZeros) {
  const TubePairPotential& p = tubePotential();
  const double farCut = p.cutoffDistance() + 3.0 * p.gridStep();
  const SegmentLineTable& table = tableKernel(8).table;
  const double lb = table.halfLength();
  int checked = 0, band = 0, nonzeroJustInside = 0;
  for (double h = 0.0; h < table.hCut(); h += 0.0037)
    for (double u = lb; u < table.uCut(); u += 0.0041) {
      const double r = std::hypot(h, u - lb);
      double dh, du;
      const double d = table.eval(h, u, &dh, &du);
      if (r >= farCut) {
        ++checked, band += r < farCut + 0.02;
        ASSERT_EQ(d, 0.0) << h << " " << u;
        ASSERT_EQ(dh, 0.0) << h << " " << u;
        ASSERT_EQ(du, 0.0) << h << " " << u;
      } else if (r < p.cutoffDistance() - 0.05) {
        nonzeroJustInside += d != 0.0;
      }
    }
  EXPECT_GT(band, 100);  // the band next to the early-out distance was sampled
  EXPECT_GT(checked, 10000);
  EXPECT_GT(nonzeroJustInside, 1000);  // inside, the table is not zero: the test sees the edge
}

// The crossing rule (enableCrossingRule): below the ramp the kernel's rule alone, bit for bit;
// beyond it the crossing rule alone, bit for bit; across it a blend whose forces and torques are
// the energy's gradient, the weight's included (the test fails without it), and no jump at either
// end of the ramp.
TEST(MdemVdwTableKernel, CrossingRuleBlendsAcrossItsRampWithForcesFromTheEnergy) {
  static const AnisotropicVdwKernel blended = [] {
    AnisotropicVdwKernel k(tubePotential(), kHalf, 8);
    k.enableCrossingRule(12);
    return k;
  }();
  const double d = tubePotential().equilibriumDistance(), pi = 3.14159265358979323846;
  const double scale = std::abs(tubePotential().wellDepthPerLength()) * kSegmentLength;
  const Segment a = seg(Vec3(0.1, -0.2, 0.3), Vec3(1.0, 0.2, -0.1));
  const Vec3 n = a.axis.unitOrthogonal(), m = a.axis.cross(n);
  auto partner = [&](double degrees, double shift, double extra) {
    const double t = degrees * pi / 180.0;
    const Vec3 tb = std::cos(t) * a.axis + std::sin(t) * m;
    return seg(a.centre + (d + extra) * n + shift * a.axis, tb);
  };
  auto energy = [](const Segment& x, const Segment& y) { return anisotropicVdw(blended, x, y).energy; };
  int inRamp = 0;
  for (double degrees : {10.0, 19.9, 22.0, 27.0, 31.0, 35.0, 39.9, 41.0, 60.0, 90.0})
    for (double shift : {0.0, 0.45, 1.3})
      for (double extra : {-0.03, 0.0013, 0.3}) {
        SCOPED_TRACE(::testing::Message() << degrees << " degrees, shift " << shift << ", extra " << extra);
        const Segment b = partner(degrees, shift, extra);
        const ContactPairResult r = anisotropicVdw(blended, a, b);
        ASSERT_NE(r.energy, 0.0);
        if (degrees < kCrossingRampDegrees[0]) {
          EXPECT_EQ(r.energy, anisotropicVdw(tableKernel(8), a, b).energy);
        } else if (degrees > kCrossingRampDegrees[1]) {
          EXPECT_EQ(r.energy, anisotropicVdw(tableKernel(12), a, b).energy);
        } else {
          ++inRamp;
          const double e8 = anisotropicVdw(tableKernel(8), a, b).energy, e12 = anisotropicVdw(tableKernel(12), a, b).energy;
          EXPECT_GE(r.energy, std::min(e8, e12) - 1e-12 * scale);
          EXPECT_LE(r.energy, std::max(e8, e12) + 1e-12 * scale);
        }
        testing::expectPairForcesAreMinusGradient(r, a, b, energy, 1e-6, kHalf);
      }
  EXPECT_GE(inRamp, 15);
  // No jump at the ramp's ends: 1e-7 degrees on either side.
  for (double edge : {kCrossingRampDegrees[0], kCrossingRampDegrees[1]}) {
    const double below = energy(a, partner(edge - 1e-7, 0.45, 0.0013)), above = energy(a, partner(edge + 1e-7, 0.45, 0.0013));
    EXPECT_NEAR(below, above, 1e-8 * scale) << edge;
  }
}

TEST(MdemVdwTableKernel, ToleranceChoosesTheFewestPointsMeetingIt) {
  const TubePairPotential& p = tubePotential();
  const double scale = std::abs(p.wellDepthPerLength()) * kSegmentLength;
  int previous = 0;
  for (double tol : {3e-2, 1e-2, 1e-3, 1e-4}) {
    const QuadratureChoice c = quadraturePointsForTolerance(p, kHalf, kHalf, tol);
    std::printf("tolerance %.0e: %d points, worst sampled error %.3g\n", tol, c.points, c.worstError);
    EXPECT_LE(c.worstError, tol);
    const AnisotropicVdwKernel k(p, kHalf, kHalf, tol);  // the same choice, built into a kernel
    EXPECT_EQ(static_cast<int>(k.rule.x.size()), c.points);
    EXPECT_EQ(k.sampledError, c.worstError);
    EXPECT_GE(c.points, previous);
    previous = c.points;
    // The sampled bound checked on geometries outside the sample (other angles, tilted out of
    // the contact plane, end-on): the error stays within 3x the tolerance.
    const QuadratureRule rule = gaussLegendre(c.points), reference = gaussLegendre(64);
    double worst = 0.0;
    int gi = 0, worstAt = -1;
    for (const auto& [a, b] : geometries()) {
      const double exact = anisotropicVdw(p, reference, a, b).energy;
      const double err = std::abs(anisotropicVdw(p, rule, a, b).energy - exact) / std::max(scale, std::abs(exact));
      if (err > worst) worst = err, worstAt = gi;
      ++gi;
    }
    std::printf("  off-sample worst %.3g at geometry %d (E = %.4g)\n", worst, worstAt,
                anisotropicVdw(p, reference, geometries()[worstAt].first, geometries()[worstAt].second).energy);
    EXPECT_LE(worst, 3.0 * tol) << tol;
  }
}

// validateContactSpec refuses each value `set` puts into the spec, naming `key`.
template <class Set, class Value>
void expectContactSpecRefuses(Scene s, Set set, std::initializer_list<Value> bad, const std::string& key) {
  for (Value v : bad) {
    set(s.contacts.vdw, v);
    try {
      validateContactSpec(s);
      ADD_FAILURE() << key << " = " << v;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// examples/crossed-tubes.toml with `keys` added to its [vdw_contact] table, written to a temporary file.
std::string crossedTubesWithKeys(const std::string& keys, const std::string& name) {
  std::ifstream in(std::string(MESOCHAIN_SOURCE_DIR) + "/examples/crossed-tubes.toml");
  EXPECT_TRUE(in.good());
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::string anchor = "cutoff_gap_nm = 1.2\n";
  EXPECT_NE(text.find(anchor), std::string::npos);
  text.insert(text.find(anchor) + anchor.size(), keys);
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

// [vdw_contact] crossing_quadrature_points: read, validated, and wired into the effect's kernels.
TEST(MdemVdwTableKernel, CrossingQuadraturePointsKeyIsReadAndValidated) {
  Scene s = tubeScene({"bonds", "vdw_contact"});
  s.contacts.vdw.crossingQuadraturePoints = 12;
  EXPECT_NO_THROW(validateContactSpec(s));
  expectContactSpecRefuses(s, [](VdwContactSpec& v, int n) { v.crossingQuadraturePoints = n; }, {1, -3, 65},
                           "crossing_quadrature_points");
  const std::string path = crossedTubesWithKeys("crossing_quadrature_points = 12\n", "mdem-crossing-points.toml");
  const Scene read = loadScene(path);
  std::filesystem::remove(path);
  EXPECT_EQ(read.contacts.vdw.crossingQuadraturePoints, 12);
  // The crossed tubes of the example (45 degrees, beyond the ramp) get the 12-point energy.
  const VdwContactEffect effect(read, std::make_shared<ContactNeighbourhood>(read, VdwContactEffect::interactionRange(read)), true);
  ASSERT_GE(read.bodies.size(), 2);
  // The closest pair of the two tubes (elements 0-7 and 8-15).
  int i0 = -1, j0 = -1;
  double lowest = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 8; j < read.bodies.size(); ++j)
      if (const double e = effect.evaluatePair(read.bodies, i, j).energy; e < lowest) lowest = e, i0 = i, j0 = j;
  ASSERT_GE(i0, 0);
  Scene plain = read;
  plain.contacts.vdw.crossingQuadraturePoints = 0;
  const VdwContactEffect eight(plain, std::make_shared<ContactNeighbourhood>(plain, VdwContactEffect::interactionRange(plain)), true);
  const Segment first = effect.neighbourhood().segment(read.bodies, i0);
  const Segment b = effect.neighbourhood().imageNear(read.bodies, j0, first.centre);
  const double e = effect.evaluatePair(read.bodies, i0, j0).energy;
  EXPECT_NE(e, eight.evaluatePair(plain.bodies, i0, j0).energy);
  // The effect orders the pair by filament (quadrature along the lower one): either order's 12 points.
  EXPECT_TRUE(e == anisotropicVdw(tableKernel(12), first, b).energy || e == anisotropicVdw(tableKernel(12), b, first).energy);
}

TEST(MdemVdwTableKernel, QuadratureToleranceKeyIsValidated) {
  Scene s = tubeScene({"bonds", "vdw_contact"});
  s.contacts.vdw.quadratureTolerance = 1e-3;
  EXPECT_NO_THROW(validateContactSpec(s));
  expectContactSpecRefuses(s, [](VdwContactSpec& v, double x) { v.quadratureTolerance = x; }, {-1e-3, 0.5, std::nan("")},
                           "quadrature_tolerance");
}

// The scene key: read from [vdw_contact]; with quadrature_points too, or out of range, an InputError
// naming it.
TEST(MdemVdwTableKernel, QuadratureToleranceKeyIsRead) {
  std::string path;
  auto withKeys = [&](const std::string& keys) { return path = crossedTubesWithKeys(keys, "mdem-quadrature-tolerance.toml"); };
  EXPECT_EQ(loadScene(withKeys("")).contacts.vdw.quadratureTolerance, 0.0);
  EXPECT_EQ(loadScene(withKeys("quadrature_tolerance = 0.01\n")).contacts.vdw.quadratureTolerance, 0.01);
  for (const char* bad : {"quadrature_tolerance = 0.01\nquadrature_points = 6\n", "quadrature_tolerance = 0.5\n",
                          "quadrature_tolerance = 0.0\n"}) {
    try {
      loadScene(withKeys(bad));
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("quadrature_tolerance"), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mesochain::mdem
