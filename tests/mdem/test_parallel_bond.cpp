// The bond kernel against independent computations: forces and torques equal minus the
// numerical derivatives of the bond energy (central differences), the bond exerts no net force
// or moment, the tracked log follows a rotation through several turns, and the closed-form
// linearised stiffness equals the numerical derivative of the kernel's forces at rest.
#include <algorithm>
#include <cmath>
#include <vector>

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

// A bond of the 2-filament scene in a deformed state: b displaced by `offset` (in a's frame)
// and turned relative to a by `angle` about `axis` (a's frame); the branch memory is the tracked
// log reached by winding up to `angle` continuously (so several turns stay several turns).
struct Deformed {
  Scene scene = filament(2);
  Bond bond;
  Vec3 xa, xb;
  Quat qa, qb;
  Deformed(const Vec3& offset, const Vec3& axis, double angle) {
    bond = scene.bonds[0];
    xa = {0.3, -0.1, 0.2};
    qa = normalized(axisAngle(Vec3(-1, 2, 0.5).normalized(), 2.1));
    xb = xa + rotate(qa, offset);
    const Vec3 n = axis.normalized();
    // Wind up in steps of < pi/2 so that the tracked branch follows the whole angle.
    const int parts = 1 + static_cast<int>(std::abs(angle) / 1.0);
    for (int k = 1; k <= parts; ++k) {
      qb = normalized(qa * axisAngle(n, angle * k / parts));
      bond.theta = evaluateBond(bond, xa, qa, xb, qb).theta;
    }
  }
  double energy(const Vec3& xa2, const Quat& qa2, const Vec3& xb2, const Quat& qb2) const {
    return evaluateBond(bond, xa2, qa2, xb2, qb2).energy.total();
  }
};

// The configurations of the kernel tests: small relative rotations (the series branch of the
// log), both sides of the branch threshold (phi = 0.1993), large rotations and multi-turn twist
// (the general branch).
std::vector<Deformed> kernelCases() {
  const Vec3 stretch(0.04, -0.03, 2.03);
  return {Deformed(stretch, Vec3(0.3, -0.5, 1.0), 0.02),
          Deformed(stretch, Vec3(1.0, 0.2, 0.1), 1e-7),
          Deformed(stretch, Vec3(0.2, 1.0, -0.4), 0.1990),
          Deformed(stretch, Vec3(0.2, 1.0, -0.4), 0.1996),
          Deformed(stretch, Vec3(0.3, -0.5, 1.0), 1.9),
          Deformed(stretch, Vec3(0.05, 0.02, 1.0), 2.0 * units::kPi + 0.4),
          Deformed(stretch, Vec3(0.0, 0.0, 1.0), -5.0 * units::kPi - 0.3)};
}

TEST(MdemParallelBond, ForcesKernelEqualsEnergyKernel) {
  for (const Deformed& c : kernelCases()) {
    const BondResult e = evaluateBond(c.bond, c.xa, c.qa, c.xb, c.qb);
    const BondForces f = bondForces(c.bond, c.xa, c.qa, c.xb, c.qb);
    const double fs = e.forceA.norm(), ts = e.torqueA.norm() + e.torqueB.norm();
    const double angle = e.theta.norm();
    EXPECT_LT((f.theta - e.theta).norm(), 1e-13 * std::max(1.0, angle)) << angle;
    EXPECT_LT((f.forceA - e.forceA).norm(), 1e-12 * fs) << angle;
    EXPECT_LT((f.forceB - e.forceB).norm(), 1e-12 * fs) << angle;
    EXPECT_LT((f.torqueA - e.torqueA).norm(), 1e-12 * ts) << angle;
    EXPECT_LT((f.torqueB - e.torqueB).norm(), 1e-12 * ts) << angle;
  }
}

TEST(MdemParallelBond, ForcesKernelIsMinusEnergyGradient) {
  for (const Deformed& c : kernelCases()) {
    const BondForces r = bondForces(c.bond, c.xa, c.qa, c.xb, c.qb);
    const double eps = 1e-6;
    const double fs = r.forceA.norm(), ts = r.torqueA.norm() + r.torqueB.norm();
    for (int d = 0; d < 3; ++d) {
      const Vec3 e = eps * Vec3::Unit(d);
      const double fa = -(c.energy(c.xa + e, c.qa, c.xb, c.qb) - c.energy(c.xa - e, c.qa, c.xb, c.qb)) / (2 * eps);
      const double fb = -(c.energy(c.xa, c.qa, c.xb + e, c.qb) - c.energy(c.xa, c.qa, c.xb - e, c.qb)) / (2 * eps);
      const double ta = -(c.energy(c.xa, expMap(e) * c.qa, c.xb, c.qb) -
                          c.energy(c.xa, expMap(-e) * c.qa, c.xb, c.qb)) / (2 * eps);
      const double tb = -(c.energy(c.xa, c.qa, c.xb, expMap(e) * c.qb) -
                          c.energy(c.xa, c.qa, c.xb, expMap(-e) * c.qb)) / (2 * eps);
      EXPECT_NEAR(r.forceA[d], fa, 1e-6 * fs) << d << " angle " << r.theta.norm();
      EXPECT_NEAR(r.forceB[d], fb, 1e-6 * fs) << d << " angle " << r.theta.norm();
      EXPECT_NEAR(r.torqueA[d], ta, 1e-6 * ts) << d << " angle " << r.theta.norm();
      EXPECT_NEAR(r.torqueB[d], tb, 1e-6 * ts) << d << " angle " << r.theta.norm();
    }
  }
}

TEST(MdemParallelBond, MultiTurnTwistKeepsItsTurns) {
  // 2.5 turns about the bond axis: the tracked angle, and the twisting moment k_s J theta_z.
  const double angle = 5.0 * units::kPi;
  const Deformed c(Vec3(0.0, 0.0, 2.0), Vec3::UnitZ(), angle);
  const BondForces r = bondForces(c.bond, c.xa, c.qa, c.xb, c.qb);
  const Vec3 axisInBondFrame = rotateInverse(c.bond.frameA, Vec3::UnitZ());
  EXPECT_NEAR(r.theta.dot(axisInBondFrame), angle, 1e-9);
  const double ksj = c.bond.k.ks * c.bond.section.j;
  // Pure twist about the bond z axis: the torque on b is -k_s J theta_z about the world axis.
  const Vec3 worldAxis = rotate(c.qa, Vec3::UnitZ());
  EXPECT_NEAR(r.torqueB.dot(worldAxis), -ksj * angle, 1e-9 * ksj * angle);
}

TEST(MdemParallelBond, SmallAngleLogSeriesMatchesClosedForm) {
  // The series branch of trackedLogWithJacobian against atan2 and the cot form of beta.
  for (double angle : {1e-9, 1e-4, 0.03, 0.1, 0.19}) {
    const Vec3 axis = Vec3(0.6, -0.3, 0.74).normalized();
    for (double sign : {1.0, -1.0}) {
      Quat q = axisAngle(axis, angle);
      q = {sign * q.w, sign * q.x, sign * q.y, sign * q.z};  // both covers of the rotation
      const RotationVector r = trackedLogWithJacobian(q, Vec3::Zero());
      EXPECT_LT((r.theta - angle * axis).norm(), 1e-15 * std::max(angle, 1e-3)) << angle;
      const double closed = angle > 1e-3 ? 1.0 / (angle * angle) - 1.0 / (2.0 * angle * std::tan(0.5 * angle))
                                         : 1.0 / 12.0;
      EXPECT_NEAR(r.beta, closed, angle > 1e-3 ? 1e-9 : 1e-8) << angle;
    }
  }
}

TEST(MdemParallelBond, PairedKernelEqualsTwoSingleKernelsBitForBit) {
  // Every pair of the kernel cases (small angles, the series branch's edge, several turns), in
  // both orders and with itself: the paired kernel gives each bond exactly its single result.
  const std::vector<Deformed> cases = kernelCases();
  const auto same = [](const Vec3& u, const Vec3& v) { return u[0] == v[0] && u[1] == v[1] && u[2] == v[2]; };
  for (const Deformed& c0 : cases)
    for (const Deformed& c1 : cases) {
      Bodies s;
      ElementType t;
      t.mass = 1.0, t.thickness = 1.0, t.width = 1.0, t.length = 2.0;
      s.add(0, t, c0.xa, c0.qa), s.add(0, t, c0.xb, c0.qb), s.add(0, t, c1.xa, c1.qa), s.add(0, t, c1.xb, c1.qb);
      Bond b0 = c0.bond, b1 = c1.bond;
      b0.a = 0, b0.b = 1, b1.a = 2, b1.b = 3;
      BondForces p0, p1;
      bondForcesPair(b0, b1, s, p0, p1);
      const BondForces r0 = bondForces(b0, c0.xa, c0.qa, c0.xb, c0.qb), r1 = bondForces(b1, c1.xa, c1.qa, c1.xb, c1.qb);
      for (const auto& [p, r] : {std::pair{&p0, &r0}, std::pair{&p1, &r1}}) {
        EXPECT_TRUE(same(p->theta, r->theta));
        EXPECT_TRUE(same(p->forceA, r->forceA) && same(p->forceB, r->forceB));
        EXPECT_TRUE(same(p->torqueA, r->torqueA) && same(p->torqueB, r->torqueB));
      }
    }
}

}  // namespace
}  // namespace mesochain::mdem
