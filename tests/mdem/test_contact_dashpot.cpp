// The dashpot's one-pass kernel (dashpotPair, mdem/contacts/contact_dashpot.hpp), which the
// contact_damping effect runs per listed pair, against the two documented steps it fuses
// (dashpotContact, dashpotForces): the same bits for pairs crossed, tilted, exactly and nearly
// parallel, end to end, in the full band, in the ramp and beyond the cut-off.
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "mdem/contacts/contact_dashpot.hpp"

namespace mesochain::mdem {
namespace {

bool sameBits(const Vec3& x, const Vec3& y) { return std::memcmp(x.data(), y.data(), 3 * sizeof(double)) == 0; }

TEST(MdemContactDashpot, OnePassKernelEqualsTheTwoStepsBitForBit) {
  ContactDampingSpec spec;
  spec.translational = 1.7, spec.rotational = 0.13, spec.fullGap = 0.5, spec.cutoffGap = 1.0;
  const double ra = 0.68, rb = 0.55;
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto randomVec = [&](double scale) -> Vec3 { return Vec3(unit(rng), unit(rng), unit(rng)) * scale; };
  int withDashpot = 0, beyond = 0, ramp = 0, parallel = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 axisA = randomVec(1.0).normalized();
    Vec3 axisB;
    switch (k % 4) {
      case 0: axisB = randomVec(1.0).normalized(); break;                                  // any angle
      case 1: axisB = axisA; break;                                                        // parallel
      case 2: axisB = (axisA + randomVec(1e-6)).normalized(); break;                      // nearly so
      default: axisB = (axisA + randomVec(0.2)).normalized(); break;                      // tilted
    }
    const Segment a{randomVec(0.1), axisA, 1.0};
    // b's centre: beside a at a wall gap of -0.1 ... 1.4 nm, anywhere along it and a bit beyond.
    const Vec3 side = axisA.cross(randomVec(1.0)).normalized();
    const double gap = -0.1 + 0.75 * (unit(rng) + 1.0);
    const Segment b{a.centre + (ra + rb + gap) * side + 1.6 * unit(rng) * axisA, axisB, k % 3 == 0 ? 1.0 : 2.0};
    const Vec3 va = randomVec(3.0), wa = randomVec(2.0), vb = randomVec(3.0), wb = randomVec(2.0);
    const DashpotContact two = dashpotContact(spec, a, b, ra, rb);
    ContactPairResult one;
    one.energy = 7.0;  // untouched when the pair has no dashpot
    const bool has = dashpotPair(spec, a, b, ra, rb, va, wa, vb, wb, &one);
    ASSERT_EQ(has, two.weightedLength > 0.0) << "pair " << k;
    if (!has) {
      EXPECT_EQ(one.energy, 7.0);
      ++beyond;
      continue;
    }
    ++withDashpot;
    parallel += k % 4 == 1;
    ramp += wallGap(a, b, ra, rb) > spec.fullGap;
    const ContactPairResult r = dashpotForces(spec, two, a, b, va, wa, vb, wb);
    EXPECT_TRUE(sameBits(one.forceA, r.forceA) && sameBits(one.forceB, r.forceB) && sameBits(one.torqueA, r.torqueA) &&
                sameBits(one.torqueB, r.torqueB))
        << "pair " << k << ": force " << one.forceA.transpose() << " against " << r.forceA.transpose();
    EXPECT_EQ(one.energy, 0.0);
  }
  // Every kind of pair was met.
  EXPECT_GT(withDashpot, 5000);
  EXPECT_GT(beyond, 2000);
  EXPECT_GT(ramp, 1000);
  EXPECT_GT(parallel, 1000);
}

}  // namespace
}  // namespace mesochain::mdem
