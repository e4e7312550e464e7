// The bond kernel against independent computations: forces and torques equal minus the
// numerical derivatives of the bond energy (central differences), the bond exerts no net force
// or moment, the tracked log follows a rotation through several turns, and the closed-form
// linearised stiffness equals the numerical derivative of the kernel's forces at rest.
#include <cmath>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/normal_modes.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

struct Pair {
  Scene scene = filament(2);
  Bond bond;
  Vec3 xa, xb;
  Quat qa, qb;
  Pair() {
    bond = scene.bonds[0];
    // A finitely deformed configuration: large relative rotation, stretch and shear.
    xa = {0.1, -0.2, 0.05};
    qa = normalized(axisAngle(Vec3(1, 2, 3).normalized(), 0.7));
    xb = xa + rotate(qa, Vec3(0.05, -0.03, 2.04));
    qb = normalized(qa * axisAngle(Vec3(0.3, -0.5, 1.0).normalized(), 1.9));
    bond.theta = evaluateBond(bond, xa, qa, xb, qb).theta;
  }
  double energy(const Vec3& xa2, const Quat& qa2, const Vec3& xb2, const Quat& qb2) const {
    return evaluateBond(bond, xa2, qa2, xb2, qb2).energy.total();
  }
};

TEST(MdemParallelBond, ForcesAreMinusEnergyGradient) {
  const Pair p;
  const BondResult r = evaluateBond(p.bond, p.xa, p.qa, p.xb, p.qb);
  const double eps = 1e-6;
  for (int d = 0; d < 3; ++d) {
    const Vec3 e = eps * Vec3::Unit(d);
    const double fa = -(p.energy(p.xa + e, p.qa, p.xb, p.qb) - p.energy(p.xa - e, p.qa, p.xb, p.qb)) / (2 * eps);
    const double fb = -(p.energy(p.xa, p.qa, p.xb + e, p.qb) - p.energy(p.xa, p.qa, p.xb - e, p.qb)) / (2 * eps);
    // Torque = -dE/dphi for a world-frame rotation q -> exp(phi) q.
    const double ta = -(p.energy(p.xa, expMap(e) * p.qa, p.xb, p.qb) -
                        p.energy(p.xa, expMap(-e) * p.qa, p.xb, p.qb)) / (2 * eps);
    const double tb = -(p.energy(p.xa, p.qa, p.xb, expMap(e) * p.qb) -
                        p.energy(p.xa, p.qa, p.xb, expMap(-e) * p.qb)) / (2 * eps);
    const double fs = r.forceA.norm(), ts = r.torqueA.norm() + r.torqueB.norm();
    EXPECT_NEAR(r.forceA[d], fa, 1e-6 * fs) << d;
    EXPECT_NEAR(r.forceB[d], fb, 1e-6 * fs) << d;
    EXPECT_NEAR(r.torqueA[d], ta, 1e-6 * ts) << d;
    EXPECT_NEAR(r.torqueB[d], tb, 1e-6 * ts) << d;
  }
  // All four energy kinds are present in this configuration.
  EXPECT_GT(r.energy.stretching, 0.0);
  EXPECT_GT(r.energy.shearing, 0.0);
  EXPECT_GT(r.energy.twisting, 0.0);
  EXPECT_GT(r.energy.bending, 0.0);
}

TEST(MdemParallelBond, NoNetForceOrMoment) {
  const Pair p;
  const BondResult r = evaluateBond(p.bond, p.xa, p.qa, p.xb, p.qb);
  const double f = r.forceA.norm();
  EXPECT_LT((r.forceA + r.forceB).norm(), 1e-12 * f);
  const Vec3 m = p.xa.cross(r.forceA) + r.torqueA + p.xb.cross(r.forceB) + r.torqueB;
  EXPECT_LT(m.norm(), 1e-11 * (r.torqueA.norm() + f * p.xb.norm()));
}

TEST(MdemParallelBond, TrackedLogFollowsSeveralTurns) {
  // Rotate about z in steps of 0.3 rad up to 3 pi + 0.2: the tracked angle grows continuously.
  Vec3 prev = Vec3::Zero();
  double angle = 0.0;
  for (int k = 1; angle < 3 * units::kPi + 0.2; ++k) {
    angle = 0.3 * k;
    prev = trackedLog(axisAngle(Vec3::UnitZ(), angle), prev);
    EXPECT_NEAR(prev.z(), angle, 1e-12);
  }
  // The principal log wraps into [0, pi].
  EXPECT_LE(logMap(axisAngle(Vec3::UnitZ(), angle)).norm(), units::kPi + 1e-12);
}

TEST(MdemParallelBond, LinearStiffnessMatchesKernelDerivative) {
  Scene s = filament(2, Vec3(0.3, 0.1, -0.2), Vec3(1, 1, 2), Vec3(0, 1, 0));
  const Bond& bond = s.bonds[0];
  const Bodies& b = s.bodies;
  const Eigen::Matrix<double, 12, 12> k = linearStiffness(bond, b);
  const double eps = 1e-7;
  auto generalizedForce = [&](const Eigen::Matrix<double, 12, 1>& u) {
    const BondResult r = evaluateBond(bond, b.position[0] + u.segment<3>(0),
                                      expMap(u.segment<3>(3)) * b.orientation[0],
                                      b.position[1] + u.segment<3>(6),
                                      expMap(u.segment<3>(9)) * b.orientation[1]);
    Eigen::Matrix<double, 12, 1> f;
    f << r.forceA, r.torqueA, r.forceB, r.torqueB;
    return f;
  };
  const double scale = k.cwiseAbs().maxCoeff();
  for (int j = 0; j < 12; ++j) {
    Eigen::Matrix<double, 12, 1> u = Eigen::Matrix<double, 12, 1>::Zero();
    u[j] = eps;
    const Eigen::Matrix<double, 12, 1> col = -(generalizedForce(u) - generalizedForce(-u)) / (2 * eps);
    for (int i = 0; i < 12; ++i) EXPECT_NEAR(k(i, j), col[i], 1e-6 * scale) << i << "," << j;
  }
}

}  // namespace
}  // namespace mesochain::mdem
