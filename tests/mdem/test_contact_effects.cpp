// Contacts as effects: built only when named; the neighbour list against brute force (periodic,
// exclusions, skin); dashpot friction F = gamma v per length for aligned tubes sliding under
// periodic boundaries and zero vdW friction; momentum and energy conservation of two crossed
// tubes zipping; damped zipping aligns them, and a rotated scene gives the same result.
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "chain_fixture.hpp"
#include "contact_fixture.hpp"
#include "momentum.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/integrator.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;
using test_support::angularMomentum;
using test_support::linearMomentum;

TEST(MdemContactEffects, BuiltOnlyWhenNamed) {
  {
    Scene s = tubeScene({"bonds"});
    addTube(s, 4, Vec3::Zero(), Vec3::UnitX());
    addTube(s, 4, Vec3(0, 1.7, 0), Vec3::UnitX());
    s.run.timeStepFraction = 0.5;
    Simulation sim(s);
    EXPECT_EQ(NeighbourList::live(), 0);
    EXPECT_EQ(sim.effect("vdw_contact"), nullptr);
    EXPECT_EQ(sim.energies()["vdw"], 0.0);
  }
  Scene s = tubeScene({"bonds", "vdw_contact", "contact_damping"});
  addTube(s, 4, Vec3::Zero(), Vec3::UnitX());
  addTube(s, 4, Vec3(0, 1.7, 0), Vec3::UnitX());
  s.run.timeStepFraction = 0.5;
  Simulation sim(s);
  EXPECT_EQ(NeighbourList::live(), 1);  // one list shared by both effects
  EXPECT_NE(sim.effect("vdw_contact"), nullptr);
  EXPECT_NE(sim.effect("contact_damping"), nullptr);
  EXPECT_LT(sim.energies()["vdw"], 0.0);
}

TEST(MdemContactEffects, NeighbourListMatchesBruteForce) {
  // Random short segments in a box periodic along x and z; filaments of 3 bonded elements.
  Scene s = tubeScene({"vdw_contact"});
  s.periodic.periodic = {true, false, true};
  s.periodic.length = Vec3(14.0, 0.0, 11.0);
  s.contacts.excludeWithin = 1;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int f = 0; f < 30; ++f) {
    const Vec3 start(14.0 * u(gen), 20.0 * u(gen), 11.0 * u(gen));
    addTube(s, 3, start, Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5));
  }
  const double range = VdwContactEffect::interactionRange(s);
  ContactNeighbourhood nb(s, range);
  auto check = [&](const Bodies& b, double slack) {
    std::set<std::pair<int, int>> listed(nb.list().pairs().begin(), nb.list().pairs().end());
    int expected = 0;
    for (int i = 0; i < b.size(); ++i)
      for (int j = i + 1; j < b.size(); ++j) {
        const double r = s.periodic.minimumImage(b.position[j] - b.position[i]).norm();
        const bool sameNear = i / 3 == j / 3 && std::abs(i - j) <= 1;
        if (r < range && !sameNear) {
          ++expected;
          EXPECT_TRUE(listed.count({i, j})) << i << " " << j << " r=" << r;
        }
        if (sameNear) {
          EXPECT_FALSE(listed.count({i, j}));
        }
      }
    for (const auto& [i, j] : listed)
      EXPECT_LT(s.periodic.minimumImage(b.position[j] - b.position[i]).norm(), range + s.contacts.skin + slack);
    return expected;
  };
  EXPECT_GT(check(s.bodies, 1e-9), 20);
  // Move every element by less than skin/2 (ends included): no rebuild, still complete.
  Bodies moved = s.bodies;
  for (int i = 0; i < moved.size(); ++i) moved.position[i] += 0.12 * Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5).normalized();
  const long builds = nb.list().builds();
  nb.update(moved);
  EXPECT_EQ(nb.list().builds(), builds);
  check(moved, 0.24);  // each element moved by 0.12 nm
  // Larger moves trigger a rebuild.
  for (int i = 0; i < moved.size(); ++i) moved.position[i] += Vec3(0.5, 0.0, -0.4);
  nb.update(moved);
  EXPECT_EQ(nb.list().builds(), builds + 1);
  check(moved, 1e-9);
}

// Sum over elements [first, first + count) of the forces of one effect, evaluated alone.
Vec3 forceOn(Simulation& sim, const char* effect, int first, int count) {
  State st = sim.state();
  std::fill(st.bodies.force.begin(), st.bodies.force.end(), Vec3::Zero());
  std::fill(st.bodies.torque.begin(), st.bodies.torque.end(), Vec3::Zero());
  sim.effect(effect)->addForces(st);
  Vec3 f = Vec3::Zero();
  for (int i = first; i < first + count; ++i) f += st.bodies.force[i];
  return f;
}

// The list's reach changes no result: a listed pair beyond the kernels' reach adds exact zeros,
// so a damped network (bonds, vdW contacts, dashpots, local damping) runs the same bits with a
// skin that rebuilds the list every few steps and with one that lists many far pairs
// (mesochain-bench network --skins measures what each costs).
TEST(MdemContactEffects, TheSkinChangesNoResult) {
  Scene a = dampedNetworkScene(), b = a;
  a.contacts.skin = 0.02, b.contacts.skin = 1.5;
  Simulation sa(a), sb(b);
  sa.run(300), sb.run(300);
  const ContactNeighbourhood *na = sa.contactNeighbourhood(), *nb = sb.contactNeighbourhood();
  ASSERT_TRUE(na && nb);
  EXPECT_GT(na->list().builds(), 5 * nb->list().builds());   // the small skin rebuilds often
  EXPECT_GT(nb->list().pairs().size(), 2 * na->list().pairs().size());  // the large one lists more
  for (int i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(sa.state().bodies.position[i], sb.state().bodies.position[i]) << i;
    EXPECT_EQ(sa.state().bodies.velocity[i], sb.state().bodies.velocity[i]) << i;
    EXPECT_EQ(sa.state().bodies.angularMomentumBody[i], sb.state().bodies.angularMomentumBody[i]) << i;
  }
  EXPECT_EQ(sa.energies().total(), sb.energies().total());
}

TEST(MdemContactEffects, SlidingTubesUnderPeriodicBoundaries) {
  // Two aligned tubes, each a closed chain of 6 elements across a box periodic along x. Tube A
  // (first) slides at v along x, tube B is held. Friction per length = gamma v exactly; the vdW
  // contact adds no friction (no corrugation) and holds A at its distance.
  const double d = 2 * kTubeRadius + 0.314;
  for (double gamma : {0.0, 40.0}) {
    Scene s = tubeScene({"vdw_contact", "contact_damping"});
    s.contacts.damping.translational = gamma;
    s.periodic.periodic = {true, false, false};
    s.periodic.length = Vec3(6 * kSegmentLength, 0, 0);
    s.contacts.closedFilaments = {{0, 6}, {6, 6}};
    const double v = 10.0;  // nm/ns
    for (int k = 0; k < 6; ++k) s.bodies.add(0, s.elementTypes[0], Vec3(k * kSegmentLength + 0.3, d, 0), fromMatrix(
        (Mat3() << 0, 0, 1, 0, 1, 0, -1, 0, 0).finished()));
    for (int k = 0; k < 6; ++k) s.bodies.add(0, s.elementTypes[0], Vec3(k * kSegmentLength, 0, 0), s.bodies.orientation[0]);
    for (int k = 0; k < 6; ++k) {
      Prescribed p;
      p.element = k, p.velocity = Vec3(v, 0, 0);
      s.boundary.prescribed.push_back(p);
      FixedDofs f;
      f.element = 6 + k, f.fixed.fill(true);
      s.boundary.fixed.push_back(f);
    }
    s.run.timeStep = 1e-4;
    Simulation sim(s);
    double maxVdw = 0.0;
    for (int step = 0; step < 60; ++step) {  // slides by more than an element length
      sim.run(50);
      const Vec3 fd = forceOn(sim, "contact_damping", 6, 6);
      const Vec3 fv = forceOn(sim, "vdw_contact", 6, 6);
      EXPECT_NEAR(fd.x() / (6 * kSegmentLength), gamma * v, 1e-9 * (gamma * v + 1));
      EXPECT_NEAR(fd.y(), 0.0, 1e-9 * (gamma * v + 1));
      maxVdw = std::max(maxVdw, std::abs(fv.x()));
    }
    EXPECT_GT(sim.state().bodies.position[0].x() - 0.3, 1.2 * kSegmentLength);
    EXPECT_LT(maxVdw, 1e-6);  // pN, over 12 nm of contact
  }
}

// Two tubes of n elements crossed at `angle` about their common normal, in contact at their
// middles, free; rotated as a whole by `frame`.
Scene crossedTubes(double angle, const Mat3& frame, std::vector<std::string> effects, int n = 8) {
  Scene s = tubeScene(std::move(effects));
  const double d = 2 * kTubeRadius + 0.34;
  const double half = 0.5 * (n - 1) * kSegmentLength;
  const Vec3 ta = Vec3::UnitX(), tb(std::cos(angle), 0.0, std::sin(angle));
  addTube(s, n, frame * (-half * ta), frame * ta);
  addTube(s, n, frame * (Vec3(0, d, 0) - half * tb), frame * tb);
  s.run.timeStepFraction = 0.3;
  return s;
}

double crossingAngle(const Bodies& b, int n) {
  const Vec3 ta = b.position[n - 1] - b.position[0], tb = b.position[2 * n - 1] - b.position[n];
  return std::acos(std::min(1.0, std::abs(ta.normalized().dot(tb.normalized()))));
}


TEST(MdemContactEffects, CrossedTubesZipConservingEnergyAndMomentum) {
  Simulation sim(crossedTubes(0.7854, Mat3::Identity(), {"bonds", "vdw_contact"}));
  const EnergyLedger e0 = sim.energies();
  double maxDev = 0.0, minVdw = e0["vdw"];
  for (int k = 0; k < 40; ++k) {
    sim.run(100);
    const EnergyLedger e = sim.energies();
    maxDev = std::max(maxDev, std::abs(e.total() - e0.total()));
    minVdw = std::min(minVdw, e["vdw"]);
  }
  const double released = e0["vdw"] - minVdw;  // vdW energy turned into motion and bond energy
  std::printf("zipping: vdW %.2f -> min %.2f zJ, max |E - E0| %.3g zJ, angle %.3f rad\n", e0["vdw"], minVdw,
              maxDev, crossingAngle(sim.bodies(), 8));
  EXPECT_GT(released, 50.0);
  // Verlet's energy error ~ (h omega)^2/8 of the energy exchanged; bound 1 % of it.
  EXPECT_LT(maxDev, 0.01 * released);
  const double pScale = std::sqrt(2.0 * released * 16 * sim.bodies().mass[0]);
  EXPECT_LT(linearMomentum(sim.bodies()).norm(), 1e-9 * pScale);
  EXPECT_LT(angularMomentum(sim.bodies()).norm(), 1e-8 * pScale * 10.0);
  EXPECT_LT(crossingAngle(sim.bodies(), 8), 0.7854);
}

TEST(MdemContactEffects, DampedCrossedTubesAlign) {
  Scene s = crossedTubes(0.5236, Mat3::Identity(), {"bonds", "vdw_contact", "contact_damping", "local_damping"});
  // Explicit dashpots are stable while h gamma lambda (1/m + r^2/I) < 1 (docs/mdem-contacts.md).
  s.contacts.damping.translational = 2.0;
  s.contacts.damping.rotational = 0.2;
  s.localDampingAlpha = 0.3;
  s.run.timeStepFraction = 0.0;  // the critical step with dashpots is ~2.9e-5 ns
  s.run.timeStep = 2e-5;
  Simulation sim(s);
  sim.run(5400);
  const double angle = crossingAngle(sim.bodies(), 8);
  const EnergyLedger e = sim.energies();
  std::printf("damped zipping from 30 deg: final angle %.4f rad, vdW %.3f zJ, kinetic %.3g zJ\n", angle, e["vdw"],
              e.kinetic());
  EXPECT_LT(angle, 0.1745);  // aligned within 10 degrees
  EXPECT_LT(e.kinetic(), 1.0);
}

TEST(MdemContactEffects, RotatedSceneGivesTheSameResult) {
  // vdW contacts and dashpots are frame independent (local damping, per world axis, is not).
  const Mat3 rot = toMatrix(axisAngle(Vec3(1, -2, 0.5).normalized(), 1.1));
  std::vector<double> angles, vdw, kinetic;
  for (const Mat3& frame : {Mat3(Mat3::Identity()), rot}) {
    Scene s = crossedTubes(0.7854, frame, {"bonds", "vdw_contact", "contact_damping"});
    s.contacts.damping.translational = 2.0;
    s.contacts.damping.rotational = 0.2;
    s.run.timeStepFraction = 0.0;  // the critical-step bound (Gershgorin, world frame) is not
    s.run.timeStep = 2e-5;         // frame independent; take one fixed step
    Simulation sim(s);
    sim.run(2250);
    angles.push_back(crossingAngle(sim.bodies(), 8));
    const EnergyLedger e = sim.energies();
    vdw.push_back(e["vdw"]), kinetic.push_back(e.kinetic());
  }
  EXPECT_LT(angles[0], 0.7);  // it did turn
  EXPECT_NEAR(angles[1], angles[0], 1e-7);
  EXPECT_NEAR(vdw[1], vdw[0], 1e-7 * std::abs(vdw[0]));
  EXPECT_NEAR(kinetic[1], kinetic[0], 1e-7 * std::abs(vdw[0]));
}

TEST(MdemContactEffects, BadParametersAreClearErrors) {
  auto expectError = [](Scene s, const char* key) {
    addTube(s, 2, Vec3::Zero(), Vec3::UnitX());
    s.run.timeStepFraction = 0.5;
    try {
      Simulation sim(s);
      ADD_FAILURE() << "no error for " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  Scene s = tubeScene({"bonds", "vdw_contact"});
  s.contacts.vdw.lj.sigma = 3.4;  // Angstrom by mistake
  expectError(s, "sigma_nm");
  s = tubeScene({"bonds", "vdw_contact"});
  s.contacts.vdw.cutoffGap = 0.5;
  expectError(s, "cutoff_gap_nm");
  s = tubeScene({"bonds", "vdw_contact"});
  s.contacts.vdw.lj.epsilon = -1.0;
  expectError(s, "epsilon_meV");
  s = tubeScene({"bonds", "contact_damping"});
  s.contacts.damping.translational = -2.0;
  expectError(s, "translational_pN_ns_per_nm2");
  s = tubeScene({"bonds", "vdw_contact"});
  s.periodic.periodic = {true, false, false};
  s.periodic.length = Vec3(6.0, 0, 0);
  expectError(s, "periodic.length_nm");
  s = tubeScene({"bonds", "vdw_contact"});  // bricks with tubes: not implemented
  s.elementTypes.push_back(s.elementTypes[0]);
  s.elementTypes[1].shape = Shape::Brick, s.elementTypes[1].thickness = 0.68, s.elementTypes[1].width = 2.4;
  s.bodies.add(1, s.elementTypes[1], Vec3(0, 5, 0), Quat{});
  expectError(s, "brick and cylinder");
  s = tubeScene({"bonds", "vdw_contact"});  // the smooth edge must fit on the brick face
  s.elementTypes[0].shape = Shape::Brick, s.elementTypes[0].thickness = 0.68, s.elementTypes[0].width = 1.0;
  expectError(s, "edge_width_nm");
}

}  // namespace
}  // namespace mesochain::mdem

namespace mesochain::mdem {
namespace {

// Hardening (issue 14): elements that start inside each other are refused by name, not thrown
// apart by the contact's repulsion.
TEST(MdemContactEffects, ElementsStartingInsideEachOtherAreAClearError) {
  using namespace testing;
  Scene tubes = tubeScene({"bonds", "vdw_contact"});
  addTube(tubes, 2, Vec3::Zero(), Vec3::UnitX());
  addTube(tubes, 2, Vec3(1.0, -1.0, 0.5), Vec3::UnitY());  // axes 0.5 nm apart: walls overlap
  try {
    Simulation sim(tubes);
    FAIL() << "overlapping tubes accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("overlapping"), std::string::npos) << e.what();
  }
  Scene bricks = filament(1);
  bricks.bodies.add(0, bricks.elementTypes[0], Vec3::Zero(), Quat{});  // two bricks at one centre
  bricks.contacts.vdw.lj = carbonLj();
  bricks.effects = {"vdw_contact"};
  bricks.run.timeStep = 1e-6;
  try {
    Simulation sim(bricks);
    FAIL() << "bricks at one centre accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bricks 0 and 1 overlapping"), std::string::npos) << e.what();
  }
  // Apart at the contact distance: accepted.
  Scene apart = tubeScene({"bonds", "vdw_contact"});
  addTube(apart, 2, Vec3::Zero(), Vec3::UnitX());
  addTube(apart, 2, Vec3(1.0, -1.0, 2.0 * kTubeRadius + 0.3), Vec3::UnitY());
  apart.run.timeStepFraction = 0.5;
  EXPECT_NO_THROW(Simulation{apart});
}

}  // namespace
}  // namespace mesochain::mdem
