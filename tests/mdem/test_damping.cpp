// Cundall's local damping (mdem/damping.hpp) applies F_d -= alpha |F_d| sign(v_d) per world
// component and the same to the body components of the torque with sign(L_body), bit for bit
// as that formula with the sign a double in {-1, 0, +1}: signed and unsigned zeros of force and
// velocity, tiny and huge values, any orientation.
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/damping.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

double signOf(double v) { return (v > 0.0) - (v < 0.0); }

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

TEST(MdemLocalDamping, IsAlphaTimesTheForceAgainstTheVelocityBitForBit) {
  Scene s = filament(1);
  const double alpha = 0.37;
  const LocalDamping damping(alpha, false, s);
  Bodies& b = s.bodies;
  const double values[] = {0.0, -0.0, 1.0, -1.0, 3.7e-300, -2.2e-308, 1.0e300, -4.5, 0.125, -1e-12};
  std::mt19937_64 random(5);
  std::uniform_int_distribution<int> pick(0, 9);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 4000; ++trial) {
    Vec3 f, t, v, l;
    for (int d = 0; d < 3; ++d)
      f[d] = values[pick(random)], t[d] = values[pick(random)], v[d] = values[pick(random)], l[d] = values[pick(random)];
    b.velocity[0] = v, b.angularMomentumBody[0] = l;
    b.orientation[0] = trial % 2 ? normalized(Quat{normal(random), normal(random), normal(random), normal(random)}) : Quat{};
    Vec3 force = f, torque = t;
    damping.dampElement(b, 0, force, torque);
    Vec3 expectedForce = f;
    for (int d = 0; d < 3; ++d) expectedForce[d] -= alpha * std::abs(f[d]) * signOf(v[d]);
    Vec3 tb = rotateInverse(b.orientation[0], t);
    for (int d = 0; d < 3; ++d) tb[d] -= alpha * std::abs(tb[d]) * signOf(l[d]);
    const Vec3 expectedTorque = rotate(b.orientation[0], tb);
    EXPECT_TRUE(sameBits(force, expectedForce)) << f.transpose() << " | " << v.transpose();
    EXPECT_TRUE(sameBits(torque, expectedTorque)) << t.transpose() << " | " << l.transpose();
  }
  // A zero velocity component leaves that force component as it was, sign of zero included.
  b.velocity[0] = Vec3(0.0, -0.0, 1.0);
  Vec3 force(-0.0, 2.0, -0.0), torque = Vec3::Zero();
  damping.dampElement(b, 0, force, torque);
  EXPECT_TRUE(std::signbit(force[0]));
  EXPECT_EQ(force[1], 2.0);
}

}  // namespace
}  // namespace mesochain::mdem
