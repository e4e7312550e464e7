// Loads and constraints against closed forms:
//  * a follower force on a spinning free body (its path is a cycloid) vs a fixed-direction one;
//  * a transverse tip force on the cantilever: the static deflection of the discrete chain
//    (bending plus shear) in the small-load limit, for fixed and following loads; at a larger
//    load the two differ, and the equilibrium under the follower load is the equilibrium under
//    the fixed load equal to the follower load's final world vector;
//  * viscous damping: free decay of a one-DOF oscillator against x(t) = v0/w_d e^{-gt/2} sin w_d t;
//  * prescribed velocities with a ramp: the displacement is the integral of the ramp profile;
//  * fixed DOFs stay fixed; a hinge (one free rotation axis, not a principal axis) turns about
//    that axis only with the moment of inertia e^T I_w e.
#include <cmath>
#include <cstdio>
#include <random>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// One free element of the given shape at the origin, body axes = world axes, no effects.
Scene singleElement(Shape shape, const Quat& q = Quat{}) {
  Scene s;
  ElementType t;
  t.name = "e";
  t.shape = shape;
  t.thickness = kH, t.width = kW, t.length = kL, t.radius = 0.7, t.mass = kMass;
  s.elementTypes.push_back(t);
  s.bodies.add(0, t, Vec3::Zero(), q);
  s.effects = {};
  return s;
}

TEST(MdemLoads, FollowerForceOnSpinningBodyTracesCycloid) {
  // A cylinder spinning at w about its axis z with a force F along its body x through the
  // centre: v(t) = F/(m w) (sin wt, 1 - cos wt, 0), x(t) = F/(m w^2) (1 - cos wt, wt - sin wt, 0).
  const double w = 40.0, force = 3.0;  // rad/ns, pN
  for (bool following : {true, false}) {
    Scene s = singleElement(Shape::Cylinder);
    s.bodies.setAngularVelocityWorld(0, {0.0, 0.0, w});
    Load l;
    l.element = 0, l.force = {force, 0.0, 0.0}, l.following = following;
    s.boundary.loads.push_back(l);
    const double period = 2.0 * units::kPi / w;
    s.run.timeStep = period / 4000.0;
    Simulation sim(s);
    const double scale = force / (kMass * w * w);
    double maxErr = 0.0;
    for (int k = 1; k <= 4000; ++k) {
      sim.step();
      const double t = sim.time();
      const Vec3 expected = following ? scale * Vec3(1.0 - std::cos(w * t), w * t - std::sin(w * t), 0.0)
                                      : Vec3(0.5 * force / kMass * t * t, 0.0, 0.0);
      maxErr = std::max(maxErr, (sim.bodies().position[0] - expected).norm());
    }
    // Velocity Verlet with a force turning at w: error O((h w)^2) of the displacement scale.
    const double hw = sim.timeStep() * w;
    EXPECT_LT(maxErr, 2.0 * hw * hw * 2.0 * units::kPi * scale) << "following " << following;
    // The two loads lead to different paths (the test distinguishes them).
    if (following) {
      EXPECT_NEAR(sim.bodies().position[0].x(), 0.0, 1e-3 * scale);
    }
  }
}

struct Static {
  Vec3 tipDisplacement, tipRotation;
  Quat tipOrientation;
};

// Cantilever of kElements bricks along z, root fixed, relaxed with local damping under `loads`
// until the unbalanced force and moment are below 1e-8 of `forceScale` (pN, times kL for
// moments); the residual's round-off floor is ~1e-9 pN (bond forces of k ~ 1e6 pN/nm at 20 nm).
constexpr int kElements = 11, kBonds = kElements - 1;
Static relax(const std::vector<Load>& loads, double forceScale) {
  Scene s = cantilever(kElements);
  s.boundary.loads = loads;
  s.effects = {"bonds", "local_damping"};
  s.localDampingAlpha = 0.7;
  s.run.timeStepFraction = 0.5;
  Simulation sim(s);
  int block = 0;
  double f = 0.0, m = 0.0;
  for (; block < 3000; ++block) {
    sim.run(200);
    std::tie(f, m) = sim.residual();
    if (f < 1e-8 * forceScale && m < 1e-8 * forceScale * kL) break;
  }
  EXPECT_LT(block, 3000) << "not converged: residual force " << f << " pN, moment " << m;
  const int tip = kElements - 1;
  return {sim.bodies().position[tip] - sim.bodies().initialPosition[tip],
          sim.bodies().accumulatedRotation[tip], sim.bodies().orientation[tip]};
}

// Tip deflection of the discrete chain under a transverse tip force P along y (bending about
// the bond x axis, I = I_x): bond k sits half-way between elements k and k+1 and carries the
// moment M_k = P (n - k - 1/2) L, rotating by M_k L / (Y I_x), and the shear force P, sliding by
// P L / (G A); summing over the n bonds, with sum_{j<n} (j + 1/2)^2 = n^3/3 - n/12:
//   u = P L^3 (n^3/3 - n/12) / (Y I_x) + n P L / (G A).
double chainDeflection(double p) {
  const double n = kBonds;
  return p * kL * kL * kL * (n * n * n / 3.0 - n / 12.0) / (kYoung * inertiaX()) +
         n * p * kL / (kShear * area());
}

Load tipForce(double p, bool following) {
  Load l;
  l.element = kElements - 1;
  l.force = {0.0, p, 0.0};
  l.following = following;
  return l;
}

TEST(MdemLoads, TipForceSmallLoadMatchesChainDeflection) {
  const double p = 1.0;  // pN: u / (n L) ~ 1e-4, geometric nonlinearity ~ 1e-8
  for (bool following : {false, true}) {
    const Static r = relax({tipForce(p, following)}, p);
    EXPECT_NEAR(r.tipDisplacement.y() / chainDeflection(p), 1.0, 1e-4) << "following " << following;
    EXPECT_NEAR(r.tipDisplacement.x(), 0.0, 1e-9 * chainDeflection(p));
  }
}

TEST(MdemLoads, FollowerTipLoadIsTheFixedLoadOfItsFinalDirection) {
  // u / (n L) ~ 0.1: the follower force turns with the tip by ~0.13 rad, so it deflects the
  // chain differently from the fixed-direction force.
  const double p = 600.0;
  const Static followingForce = relax({tipForce(p, true)}, p);
  const Static fixedForce = relax({tipForce(p, false)}, p);
  std::printf("tip deflection: following %.6g nm, fixed %.6g nm, linear %.6g nm\n",
              followingForce.tipDisplacement.y(), fixedForce.tipDisplacement.y(),
              chainDeflection(p));
  EXPECT_GT((followingForce.tipDisplacement - fixedForce.tipDisplacement).norm(),
            1e-3 * fixedForce.tipDisplacement.norm());
  // Force and twisting moment both following: the twist turns the tip about its axis, so the
  // bending force also turns sideways.
  Load follower = tipForce(p, true);
  follower.moment = {0.0, 0.0, 3000.0};
  const Static a = relax({follower}, p);
  const Vec3 fWorld = rotate(a.tipOrientation, follower.force);
  const Vec3 mWorld = rotate(a.tipOrientation, follower.moment);
  // The follower force stays perpendicular to the tip's axis and turned with it.
  EXPECT_NEAR(fWorld.dot(rotate(a.tipOrientation, Vec3::UnitZ())), 0.0, 1e-12 * p);
  EXPECT_GT(std::abs(fWorld.z()), 0.05 * p);
  EXPECT_GT(std::abs(fWorld.x()), 0.05 * p);
  // Statics only sees the current load: the fixed load (fWorld, mWorld) has the same equilibrium.
  Load same;
  same.element = kElements - 1, same.force = fWorld, same.moment = mWorld;
  const Static b = relax({same}, p);
  EXPECT_LT((a.tipDisplacement - b.tipDisplacement).norm(), 1e-6 * a.tipDisplacement.norm());
  // (Orientations, not the probe integral of omega dt, which depends on the path.)
  EXPECT_LT((toMatrix(a.tipOrientation) - toMatrix(b.tipOrientation)).norm(), 1e-6);
}

// Element 1 bonded to a clamped element 0 and free only along z: a one-DOF oscillator of
// stiffness k = k_n A = Y A / L and mass m, released with velocity v0 under viscous damping
// F = -g m v (c = g m): x(t) = v0 / w_d exp(-g t / 2) sin(w_d t), w_d^2 = k/m - g^2/4.
double viscousDecayError(double stepsPerPeriod, double* envelopeRatio) {
  Scene s = cantilever(2);
  FixedDofs f;
  f.element = 1;
  f.fixed = {true, true, false, true, true, true};
  s.boundary.fixed.push_back(f);
  const double v0 = 2.0;
  s.bodies.velocity[1] = {0.0, 0.0, v0};
  const double k = kYoung * area() / kL, w0 = std::sqrt(k / kMass);
  const double g = 0.1 * w0;  // damping ratio 0.05
  s.effects = {"bonds", "viscous_damping"};
  s.viscousRate = g;
  const double wd = std::sqrt(w0 * w0 - 0.25 * g * g);
  s.run.timeStep = 2.0 * units::kPi / wd / stepsPerPeriod;
  Simulation sim(s);
  const long steps = static_cast<long>(10 * stepsPerPeriod);  // ten periods
  double maxErr = 0.0;
  for (long n = 1; n <= steps; ++n) {
    sim.step();
    const double t = sim.time();
    const double expected = v0 / wd * std::exp(-0.5 * g * t) * std::sin(wd * t);
    maxErr = std::max(maxErr, std::abs(sim.bodies().position[1].z() - kL - expected));
  }
  // Energy E = 1/2 m v^2 + 1/2 k x^2 after whole periods against the envelope exp(-g t).
  const double x = sim.bodies().position[1].z() - kL, v = sim.bodies().velocity[1].z();
  *envelopeRatio = (0.5 * kMass * v * v + 0.5 * k * x * x) / (0.5 * kMass * v0 * v0) /
                   std::exp(-g * sim.time());
  // Nothing but z moved.
  EXPECT_EQ(sim.bodies().position[1].x(), 0.0);
  EXPECT_EQ(sim.bodies().position[1].y(), 0.0);
  return maxErr / (v0 / wd);
}

TEST(MdemConstraints, ViscousFreeDecayFollowsAnalyticEnvelope) {
  double ratioCoarse = 0.0, ratioFine = 0.0;
  const double coarse = viscousDecayError(200.0, &ratioCoarse);
  const double fine = viscousDecayError(400.0, &ratioFine);
  // The damping force uses the half-step velocity, so the scheme is first order in h for the
  // damped part: the error halves with h, and is small against the amplitude.
  EXPECT_LT(fine, 0.6 * coarse);
  EXPECT_LT(fine, 1e-2);
  EXPECT_NEAR(ratioFine, 1.0, 1e-2);
  EXPECT_LT(std::abs(ratioFine - 1.0), 0.6 * std::abs(ratioCoarse - 1.0));
}

TEST(MdemConstraints, PrescribedVelocityRampIntegratesExactly) {
  // Middle element of a 3-element filament: v(t) = v0 min(1, t/T), w(t) = w0 min(1, t/T).
  // Displacement v0 S(t), rotation w0 S(t), S = t^2 / (2T) for t <= T, t - T/2 after (the
  // midpoint rule of the drift is exact on each linear piece when T is a whole number of steps).
  Scene s = filament(3);
  s.run.timeStepFraction = 0.5;
  Prescribed p;
  p.element = 1;
  p.velocity = {1.0, 2.0, -0.5};
  p.angularVelocity = {3.0, -2.0, 5.0};
  const double h = Simulation(s).timeStep();
  p.ramp = 40 * h;
  s.boundary.prescribed.push_back(p);
  s.run.timeStepFraction = 0.0;
  s.run.timeStep = h;
  Simulation sim(s);
  const Quat q0 = sim.bodies().orientation[1];
  const Vec3 x0 = sim.bodies().position[1];
  for (int n = 1; n <= 100; ++n) {
    sim.step();
    const double t = n * h, T = p.ramp;
    const double integral = t <= T ? t * t / (2.0 * T) : t - 0.5 * T;
    const Vec3 u = sim.bodies().position[1] - x0;
    EXPECT_LT((u - integral * p.velocity).norm(), 1e-12 * p.velocity.norm() * t) << "step " << n;
    EXPECT_LT((sim.bodies().accumulatedRotation[1] - integral * p.angularVelocity).norm(),
              1e-12 * p.angularVelocity.norm() * t);
    const Quat q = expMap(integral * p.angularVelocity) * q0;
    EXPECT_LT((toMatrix(q) - toMatrix(sim.bodies().orientation[1])).norm(), 1e-12);
    EXPECT_LT((sim.bodies().velocity[1] - std::min(1.0, t / T) * p.velocity).norm(),
              1e-12 * p.velocity.norm());
  }
  // The neighbours were dragged along by the bonds.
  EXPECT_GT((sim.bodies().position[2] - sim.bodies().initialPosition[2]).norm(), 0.1 * h * 60);
}

TEST(MdemConstraints, FixedDofsStayFixed) {
  // A loaded, shaken filament; element 2 has x, z, ry fixed, element 4 has y, rx, rz fixed.
  Scene s = filament(5, Vec3(0.3, -0.2, 0.1), Vec3(1.0, 0.5, 2.0), Vec3(0.0, 1.0, 0.3));
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 5; ++i) {
    s.bodies.velocity[i] = 5.0 * Vec3(u(gen), u(gen), u(gen));
    s.bodies.setAngularVelocityWorld(i, 5.0 * Vec3(u(gen), u(gen), u(gen)));
  }
  FixedDofs a, b;
  a.element = 2, a.fixed = {true, false, true, false, true, false};
  b.element = 4, b.fixed = {false, true, false, true, false, true};
  s.boundary.fixed = {a, b};
  Load l;
  l.element = 4, l.force = {30.0, -20.0, 10.0}, l.moment = {5.0, 7.0, -3.0};
  s.boundary.loads.push_back(l);
  s.run.timeStepFraction = 0.5;
  Simulation sim(s);
  const Bodies& bd = sim.bodies();
  double moved = 0.0;
  for (int n = 0; n < 2000; ++n) {
    sim.step();
    for (const FixedDofs& f : {a, b}) {
      const int i = f.element;
      const Vec3 w = bd.angularVelocityWorld(i);
      for (int d = 0; d < 3; ++d) {
        if (f.fixed[d]) {
          ASSERT_EQ(bd.position[i][d], bd.initialPosition[i][d]) << "element " << i << " dof " << d;
          ASSERT_EQ(bd.velocity[i][d], 0.0);
        }
        if (f.fixed[3 + d]) {
          ASSERT_LT(std::abs(w[d]), 1e-12 * w.norm() + 1e-300) << "element " << i << " r" << d;
          ASSERT_LT(std::abs(bd.accumulatedRotation[i][d]), 1e-12) << "element " << i << " r" << d;
        }
      }
    }
    moved = std::max(moved, std::abs(bd.position[2].y() - bd.initialPosition[2].y()));
  }
  EXPECT_GT(moved, 1e-3);  // the free DOFs did move
}

TEST(MdemConstraints, HingeAboutNonPrincipalAxisIsExact) {
  // A brick in a generic orientation (world z is no principal axis), translations and rx, ry
  // fixed, under a constant torque with components on all axes: it turns about z only, by
  // phi = tau_z t^2 / (2 I_zz) with I_zz = (R diag(I) R^T)_zz (Verlet is exact for constant
  // acceleration), and its orientation is exp(phi z) q0.
  const Quat q0 = normalized(axisAngle(Vec3(1.0, 2.0, -0.5).normalized(), 0.9));
  Scene s = singleElement(Shape::Brick, q0);
  FixedDofs f;
  f.element = 0, f.fixed = {true, true, true, true, true, false};
  s.boundary.fixed.push_back(f);
  Load l;
  l.element = 0, l.moment = {4.0, -3.0, 2.0};
  s.boundary.loads.push_back(l);
  s.run.timeStep = 1e-3;
  Simulation sim(s);
  const Mat3 r = toMatrix(q0);
  const double izz = (r * s.bodies.inertia[0].asDiagonal() * r.transpose())(2, 2);
  const double iPrincipalMin = s.bodies.inertia[0].minCoeff();
  ASSERT_GT(std::abs(izz - iPrincipalMin), 0.05 * izz);
  for (int n = 1; n <= 500; ++n) {
    sim.step();
    const double t = sim.time();
    const double phi = 0.5 * l.moment.z() * t * t / izz;
    ASSERT_NEAR(sim.bodies().accumulatedRotation[0].z(), phi, 1e-10 * std::max(phi, 1e-3));
    const Mat3 expected = toMatrix(axisAngle(Vec3::UnitZ(), phi) * q0);
    ASSERT_LT((expected - toMatrix(sim.bodies().orientation[0])).norm(), 1e-10) << "step " << n;
  }
  EXPECT_GT(sim.bodies().accumulatedRotation[0].z(), 1.0);  // a large rotation
}

}  // namespace
}  // namespace mesochain::mdem
