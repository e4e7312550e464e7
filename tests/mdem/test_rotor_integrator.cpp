// The free-rotor step with rational (Cayley) sub-rotations (the default, integrator.hpp) against
// the exact-splitting step: both second order with the same rate of convergence, a bounded
// energy error without drift over a long free flight, exact conservation of the world angular
// momentum, unit quaternions, time reversibility; and the Cayley step differs from the exact
// one only at O(h^3) per step. The stepper's paired drift of two free elements equals two single
// drifts bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "mdem/body.hpp"
#include "mdem/integrator.hpp"

namespace mesochain::mdem {
namespace {

using StepFunction = void (*)(Quat&, Vec3&, const Vec3&, double);

// An asymmetric top (I_x < I_y < I_z: the brick's ratios), spinning near its unstable middle
// axis so that all three components of pi change strongly.
const Vec3 kInertia(0.0021, 0.0038, 0.0057);
const Vec3 kPi0(0.004, 0.03, 0.006);

struct RotorState {
  Quat q = normalized(axisAngle(Vec3(1, -2, 0.5).normalized(), 0.8));
  Vec3 pi = kPi0;
};

double energy(const Vec3& pi) { return 0.5 * pi.cwiseAbs2().cwiseQuotient(kInertia).sum(); }
double omegaMax() { return kPi0.norm() / kInertia.minCoeff(); }

RotorState integrate(StepFunction step, double h, long steps) {
  RotorState s;
  for (long k = 0; k < steps; ++k) step(s.q, s.pi, kInertia, h);
  return s;
}

// Distance between two states: rotation angle between the orientations plus |pi| relative.
double distance(const RotorState& a, const RotorState& b) {
  return logMap(conj(a.q) * b.q).norm() + (a.pi - b.pi).norm() / kPi0.norm();
}

TEST(MdemRotorIntegrator, BothStepsConvergeAtSecondOrder) {
  const double period = 2.0 * 3.141592653589793 / omegaMax();
  const double t = 3.0 * period;
  const long base = 200;  // h omega_max = 0.094
  // Reference: the exact splitting with 64 times smaller steps (error 4096 times smaller).
  const RotorState ref = integrate(freeRotorStepExact, t / (64 * base), 64 * base);
  for (StepFunction step : {StepFunction(freeRotorStep), StepFunction(freeRotorStepExact)}) {
    const double e1 = distance(integrate(step, t / base, base), ref);
    const double e2 = distance(integrate(step, t / (2 * base), 2 * base), ref);
    const double e4 = distance(integrate(step, t / (4 * base), 4 * base), ref);
    std::printf("errors %.3g %.3g %.3g, ratios %.3f %.3f\n", e1, e2, e4, e1 / e2, e2 / e4);
    EXPECT_NEAR(e1 / e2, 4.0, 0.4);
    EXPECT_NEAR(e2 / e4, 4.0, 0.2);
    EXPECT_LT(e1, 0.1);  // in the asymptotic regime
  }
}

TEST(MdemRotorIntegrator, CayleyDiffersFromExactAtThirdOrderPerStep) {
  // One step from the same state: the sub-rotation angles differ by alpha^3/12 + O(alpha^5).
  double previous = 0.0;
  for (double h : {0.02, 0.01, 0.005}) {
    RotorState a, b;
    freeRotorStep(a.q, a.pi, kInertia, h);
    freeRotorStepExact(b.q, b.pi, kInertia, h);
    const double d = distance(a, b);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / d, 8.0, 0.3) << h;
    }
    previous = d;
  }
}

TEST(MdemRotorIntegrator, LongFreeFlightBoundedEnergyExactMomentum) {
  const double h = 0.1 / omegaMax();  // h omega_max = 0.1
  constexpr long kSteps = 1000000, kWindow = 20000;
  for (StepFunction step : {StepFunction(freeRotorStep), StepFunction(freeRotorStepExact)}) {
    RotorState s;
    const double e0 = energy(s.pi);
    const Vec3 l0 = rotate(s.q, s.pi);
    double maxDev = 0.0, early = 0.0, late = 0.0, maxNormError = 0.0, maxMomentumError = 0.0;
    for (long k = 1; k <= kSteps; ++k) {
      step(s.q, s.pi, kInertia, h);
      const double dev = energy(s.pi) / e0 - 1.0;
      maxDev = std::max(maxDev, std::abs(dev));
      if (k <= kWindow) early += dev / kWindow;
      if (k > kSteps - kWindow) late += dev / kWindow;
      if (k % 1000 == 0) {
        maxNormError = std::max(maxNormError, std::abs(s.q.norm() - 1.0));
        maxMomentumError = std::max(maxMomentumError, (rotate(s.q, s.pi) - l0).norm() / l0.norm());
      }
    }
    std::printf("energy: max relative deviation %.3g, window means %.3g %.3g; |q|-1 %.2g, "
                "|dL|/L %.2g\n", maxDev, early, late, maxNormError, maxMomentumError);
    // Bounded at O((h omega)^2) and no drift: the late window mean stays within the range of
    // the early oscillation (a first-order or non-reversible scheme drifts by ~ steps * h^3).
    EXPECT_LT(maxDev, std::pow(h * omegaMax(), 2));
    EXPECT_LT(std::abs(late - early), 0.1 * maxDev);
    EXPECT_LT(maxNormError, 1e-14);
    // World angular momentum R(q) pi: each sub-rotation turns q and pi oppositely; only
    // round-off accumulates (10^6 steps of a few ulp each: ~1e-12 seen). A scheme that did not
    // conserve it would be off by its truncation error, ~(h omega)^2 = 1e-2.
    EXPECT_LT(maxMomentumError, 1e-10);
  }
}

TEST(MdemRotorIntegrator, StepsAreTimeReversible) {
  // 1000 steps forward, 1000 with -h: back to the start up to round-off (amplified by the
  // motion near the unstable middle axis: ~2e-12 for either step). A scheme that is not
  // symmetric, or a sub-rotation angle that is not odd in h, returns only to O(h^3 * steps)
  // ~ 1e-3 here.
  const double h = 0.1 / omegaMax();
  for (StepFunction step : {StepFunction(freeRotorStep), StepFunction(freeRotorStepExact)}) {
    RotorState s;
    const RotorState start = s;
    for (int k = 0; k < 1000; ++k) step(s.q, s.pi, kInertia, h);
    EXPECT_GT(distance(s, start), 0.1);  // it went somewhere
    for (int k = 0; k < 1000; ++k) step(s.q, s.pi, kInertia, -h);
    std::printf("returned to within %.3g\n", distance(s, start));
    EXPECT_LT(distance(s, start), 1e-10);
  }
}

// driftFreePair (two elements' rotor chains lane by lane, vectorised) against driftElement on
// each: positions, orientations, angular momenta and rotation probes equal bit for bit over many
// steps of bricks of different shapes spinning fast about all three axes.
TEST(MdemRotorIntegrator, PairedDriftEqualsTwoSingleDriftsBitForBit) {
  std::vector<ElementType> types(3);
  types[0].thickness = 0.8, types[0].width = 2.4, types[0].length = 2.0, types[0].mass = 0.01;
  types[1].shape = Shape::Cylinder, types[1].radius = 0.68, types[1].length = 2.0, types[1].mass = 0.0065;
  types[2].thickness = 0.4, types[2].width = 5.0, types[2].length = 4.0, types[2].mass = 0.03;
  Bodies paired, single;
  for (int i = 0; i < 6; ++i) {
    const Quat q = normalized(axisAngle(Vec3(1.0 + i, -2.0, 0.5 * i).normalized(), 0.3 + 0.7 * i));
    paired.add(i % 3, types[i % 3], Vec3(i, 0.5 * i, -i), q);
    paired.velocity[i] = Vec3(0.3 * i - 1.0, 0.2, -0.1 * i);
    paired.setAngularVelocityWorld(i, Vec3(40.0 - 9.0 * i, 25.0 * std::cos(i), -30.0 + 11.0 * i));
  }
  single = paired;
  const double h = 2e-3;  // rotations of up to ~0.1 rad per step
  for (int step = 0; step < 500; ++step) {
    for (int i = 0; i < 6; i += 2) driftFreePair(paired, i, h);
    for (int i = 0; i < 6; ++i) driftElement(single, i, h, false);
  }
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(paired.position[i], single.position[i]) << i;
    EXPECT_EQ(paired.angularMomentumBody[i], single.angularMomentumBody[i]) << i;
    EXPECT_EQ(paired.accumulatedRotation[i], single.accumulatedRotation[i]) << i;
    const Quat &a = paired.orientation[i], &b = single.orientation[i];
    EXPECT_TRUE(a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z) << i;
  }
  // The elements did turn (the comparison is not of untouched states).
  EXPECT_GT(single.accumulatedRotation[0].norm(), 10.0);
}

}  // namespace
}  // namespace mesochain::mdem
