// Static cantilever of bricks, element 0 fixed, loaded at the tip; the static state is reached
// by dynamic relaxation with local damping. With n = N - 1 bonds of length L and
// k_n = Y / L, k_s = G / L per unit area, beam theory of a chain of n segments gives
//   twist     phi = n L M / (G J)      bending  phi = n L M / (Y I)  (I_x and I_y separately)
//   stretch   u   = n L F / (Y A).
#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

constexpr int kElements = 11;  // n = 10 bonds
constexpr int kBonds = kElements - 1;


struct Relaxed {
  Vec3 tipDisplacement;
  Vec3 tipRotation;
  EnergyLedger energies;
};

Relaxed relaxCantilever(const Load& load) {
  Scene s = cantilever(kElements);
  s.boundary.loads.push_back(load);
  s.effects = {"bonds", "local_damping"};
  s.localDampingAlpha = 0.7;
  s.run.timeStep = 1.0;  // replaced by a fraction of the critical step below
  Scene probe = s;
  probe.run.timeStep = 1e-30;
  const double hc = Simulation(probe).stability().criticalTimeStep;
  s.run.timeStep = 0.5 * hc;
  Simulation sim(s);
  const double fRef = std::max(load.force.norm(), 1e-300);
  const double mRef = std::max(load.moment.norm(), 1e-300);
  int block = 0;
  double f = 0, m = 0;
  for (; block < 2000; ++block) {
    sim.run(200);
    std::tie(f, m) = sim.residual();
    if (f < 1e-9 * (fRef + mRef / kL) && m < 1e-9 * (mRef + fRef * kL)) break;
  }
  EXPECT_LT(block, 2000) << "not converged: residual force " << f << " pN, moment " << m;
  const int tip = kElements - 1;
  return {sim.bodies().position[tip] - sim.bodies().initialPosition[tip],
          sim.bodies().accumulatedRotation[tip], sim.energies()};
}

TEST(MdemCantilever, TipTwistUnderTorque) {
  Load l;
  l.element = kElements - 1;
  l.moment = {0.0, 0.0, 50.0};  // pN nm
  const Relaxed r = relaxCantilever(l);
  const double expected = kBonds * kL * l.moment.z() / (kShear * polar());
  EXPECT_NEAR(r.tipRotation.z() / expected, 1.0, 1e-4);
  EXPECT_NEAR(r.energies["twisting"] / (0.5 * l.moment.z() * expected), 1.0, 1e-4);
}

TEST(MdemCantilever, TipBendingAboutEachAxis) {
  for (int axis = 0; axis < 2; ++axis) {
    Load l;
    l.element = kElements - 1;
    l.moment[axis] = 20.0;
    const Relaxed r = relaxCantilever(l);
    const double inertia = axis == 0 ? inertiaX() : inertiaY();
    const double expected = kBonds * kL * l.moment[axis] / (kYoung * inertia);
    EXPECT_NEAR(r.tipRotation[axis] / expected, 1.0, 1e-4) << "axis " << axis;
    EXPECT_NEAR(r.energies["bending"] / (0.5 * l.moment[axis] * expected), 1.0, 1e-4);
  }
  // The two bending stiffnesses differ (I_x / I_y = (w / h)^2 = 9).
  EXPECT_NEAR(inertiaX() / inertiaY(), 9.0, 1e-12);
}

TEST(MdemCantilever, AxialStretch) {
  Load l;
  l.element = kElements - 1;
  l.force = {0.0, 0.0, 100.0};  // pN
  const Relaxed r = relaxCantilever(l);
  const double expected = kBonds * kL * l.force.z() / (kYoung * area());
  EXPECT_NEAR(r.tipDisplacement.z() / expected, 1.0, 1e-4);
  EXPECT_NEAR(r.energies["stretching"] / (0.5 * l.force.z() * expected), 1.0, 1e-4);
}

}  // namespace
}  // namespace mesochain::mdem
