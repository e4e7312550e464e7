// Large twist: the tip of a cantilever is turned by pi and by 3 pi about the filament axis
// (prescribed smooth rotation, then held), and the chain relaxes with local damping. The tip
// must reach the commanded angle, the bonds' tracked twists must add up to it (no turn wrapped
// away, also when one bond carries 1.5 pi), and the stored energy is G J theta^2 / (2 n L).
// (For the thin brick, twist beyond about pi is above the twist-buckling threshold of a real
// rod; the pure-twist state is still an equilibrium and, by exact symmetry, the one reached.)
#include <cmath>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

void checkTwist(Scene s, int bonds, double theta, double polarMoment) {
  Prescribed p;
  p.element = s.bodies.size() - 1;
  p.rotateBy = {0.0, 0.0, theta};
  p.duration = 0.05;  // ns
  s.boundary.prescribed.push_back(p);
  s.effects = {"bonds", "local_damping"};
  s.localDampingAlpha = 0.7;
  s.run.timeStepFraction = 0.5;
  Simulation sim(s);
  sim.run(static_cast<long>(std::ceil(p.duration / sim.timeStep())) + 1);
  int block = 0;
  const double mRef = kShear * polarMoment * theta / (bonds * kL);
  for (; block < 1000; ++block) {
    sim.run(200);
    const auto [f, m] = sim.residual();
    if (m < 1e-9 * mRef && f < 1e-9 * mRef / kL) break;
  }
  EXPECT_LT(block, 1000) << "not relaxed";
  const int tip = s.bodies.size() - 1;
  EXPECT_NEAR(sim.bodies().accumulatedRotation[tip].z() / theta, 1.0, 1e-6);
  double sum = 0.0;
  for (const Bond& b : sim.bonds()) sum += b.theta.z();
  EXPECT_NEAR(sum / theta, 1.0, 1e-6);
  const EnergyLedger e = sim.energies();
  const double expected = kShear * polarMoment * theta * theta / (2.0 * bonds * kL);
  EXPECT_NEAR(e["twisting"] / expected, 1.0, 1e-4);
  EXPECT_LT(e["bending"] + e["shearing"] + e["stretching"], 1e-8 * expected);
}

TEST(MdemLargeTwist, BricksByPiAndThreePi) {
  checkTwist(cantilever(11), 10, units::kPi, polar());
  checkTwist(cantilever(11), 10, 3.0 * units::kPi, polar());
  // Two bonds: 1.5 pi per bond, beyond the principal branch of the log.
  checkTwist(cantilever(3), 2, 3.0 * units::kPi, polar());
}

TEST(MdemLargeTwist, CylindersByThreePi) {
  Scene s = cantilever(6);
  ElementType& t = s.elementTypes[0];
  t.shape = Shape::Cylinder;
  t.radius = 0.7;
  // Rebuild with the cylinder type (sections and inertia follow the type).
  Scene c;
  c.elementTypes = {t};
  c.bondTypes = s.bondTypes;
  FilamentSpec f;
  f.count = 6;
  addFilament(c, f);
  c.boundary = s.boundary;
  const double j = 0.5 * units::kPi * std::pow(t.radius, 4);
  checkTwist(c, 5, 3.0 * units::kPi, j);
}

}  // namespace
}  // namespace mesochain::mdem
