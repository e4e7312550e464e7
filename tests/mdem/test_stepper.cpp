// The fused time step (stepper.hpp) gives the same trajectory, bit for bit, on 1 and 2 OpenMP
// threads, in its barrier-free scheme (independent filaments) and its barrier scheme (one long
// filament, or contacts coupling the filaments), and the same as the plain definition of the step
// (velocity Verlet with one serial force evaluation of every effect per step).
#include <omp.h>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "contact_fixture.hpp"
#include "mdem/bond_effect.hpp"
#include "mdem/contacts/network_generator.hpp"
#include "mdem/integrator.hpp"
#include "mdem/stepper.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// Scenes above this many elements run the parallel region on more than one thread.
constexpr int kSmallScene = 512;

// `filaments` filaments of `length` elements side by side, shaken, with loads, a fixed root,
// a hinge and both dampings: every per-element code path.
Scene shakenFilaments(int filaments, int length) {
  Scene s = filament(length);
  for (int f = 1; f < filaments; ++f) {
    FilamentSpec spec;
    spec.count = length;
    spec.start = {5.0 * f, 0.0, 0.0};
    addFilament(s, spec);
  }
  for (int i = 0; i < s.bodies.size(); ++i) {
    s.bodies.velocity[i] = Vec3(std::sin(1.3 * i), std::cos(0.7 * i), std::sin(0.3 * i));
    s.bodies.setAngularVelocityWorld(i, Vec3(std::cos(1.1 * i), std::sin(0.9 * i), 0.5));
  }
  FixedDofs root, hinge;
  root.element = 0, root.fixed.fill(true);
  hinge.element = 3, hinge.fixed = {false, false, false, true, true, false};
  s.boundary.fixed = {root, hinge};
  Load l;
  l.element = s.bodies.size() - 1, l.force = {1.0, 2.0, 3.0}, l.moment = {0.5, 0.0, 1.0};
  l.following = true;
  s.boundary.loads.push_back(l);
  s.effects = {"bonds", "local_damping", "viscous_damping"};
  s.localDampingAlpha = 0.1;
  s.viscousRate = 10.0;
  s.run.timeStepFraction = 0.5;
  return s;
}

void expectIdentical(const Bodies& a, const Bodies& b) {
  ASSERT_EQ(a.size(), b.size());
  for (int i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.position[i], b.position[i]) << "element " << i;
    ASSERT_EQ(a.velocity[i], b.velocity[i]) << "element " << i;
    ASSERT_EQ(a.angularMomentumBody[i], b.angularMomentumBody[i]) << "element " << i;
    ASSERT_EQ(a.orientation[i].w, b.orientation[i].w) << "element " << i;
    ASSERT_EQ(a.orientation[i].z, b.orientation[i].z) << "element " << i;
  }
}

// The partition a simulation of `s` would use on `threads` threads (bonds only).
ThreadPartition partitionOf(const Scene& s, int threads) {
  BondEffect bonds(s.bonds, s.bodies.size());
  return partitionElements(s.bodies.size(), s.bonds, EffectSequence({&bonds}), threads);
}

Bodies runWithThreads(const Scene& s, int threads, long steps) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim(s);
  sim.run(steps / 2);
  sim.step();
  sim.run(steps - steps / 2 - 1);
  omp_set_num_threads(saved);
  return sim.bodies();
}

TEST(MdemStepper, SameResultOnOneAndTwoThreads) {
  // 6 filaments of 100: cut between filaments, no barrier inside the run.
  const Scene independent = shakenFilaments(6, 100);
  EXPECT_TRUE(partitionOf(independent, 2).independent);
  expectIdentical(runWithThreads(independent, 1, 100), runWithThreads(independent, 2, 100));
  // One filament of 600: no cut, the barrier scheme.
  const Scene single = shakenFilaments(1, 600);
  EXPECT_FALSE(partitionOf(single, 2).independent);
  expectIdentical(runWithThreads(single, 1, 40), runWithThreads(single, 2, 40));
  // And the runs really moved.
  EXPECT_GT((runWithThreads(single, 1, 40).position[599] - single.bodies.position[599]).norm(), 1e-5);
}

TEST(MdemStepper, PartitionCutsOnlyBetweenFilaments) {
  // 220 elements, even shares at 73 and 146: the nearest cuts between filaments, 80 and 140.
  const Scene s = shakenFilaments(11, 20);
  const ThreadPartition p = partitionOf(s, 3);
  ASSERT_TRUE(p.independent);
  EXPECT_EQ(p.elementStart[1], 80);
  EXPECT_EQ(p.elementStart[2], 140);
  // Three filaments of 100 on two threads: no cut within 10% of 150.
  EXPECT_FALSE(partitionOf(shakenFilaments(3, 100), 2).independent);
  ASSERT_EQ(p.itemStart.size(), 1u);  // the bonds
  EXPECT_EQ(p.itemStart[0][3], static_cast<int>(s.bonds.size()));
  for (int t = 0; t < 3; ++t)
    for (int e = p.itemStart[0][t]; e < p.itemStart[0][t + 1]; ++e) {
      const Bond& b = s.bonds[p.itemOrder[0][e]];
      EXPECT_GE(b.a, p.elementStart[t]);
      EXPECT_LT(b.b, p.elementStart[t + 1]);
    }
}

// The fused stepper (on one thread: the block sweep of the barrier-free scheme, which computes
// each bond just before the block of its lower element) against the plain step.
void expectFusedEqualsPlain(const Scene& s) {
  Simulation sim(s);  // the fused stepper
  Simulation plain(s);  // its effects, driven one serial force evaluation per step
  const double h = sim.timeStep();
  const KinematicMap km(s.boundary, s.bodies.size());
  std::vector<Effect*> effects;
  for (const EffectPtr& e : plain.effects()) effects.push_back(e.get());
  const EffectSequence sequence(effects);
  State& b = plain.state();
  sim.run(50);
  for (int k = 0; k < 50; ++k) {
    for (int i = 0; i < b.bodies.size(); ++i) {
      kickElement(b.bodies, i, 0.5 * h);
      km.applyElement(b.bodies, i, b.time + 0.5 * h);
      driftElement(b.bodies, i, h, km.kinematicRotation[i] != 0);
    }
    b.time += h;
    evaluateForces(b, sequence, km, true, true);
    for (int i = 0; i < b.bodies.size(); ++i) {
      kickElement(b.bodies, i, 0.5 * h);
      km.applyElement(b.bodies, i, b.time);
    }
  }
  EXPECT_EQ(sim.time(), b.time);
  expectIdentical(sim.bodies(), b.bodies);
}

TEST(MdemStepper, FusedStepEqualsThePlainStep) {
  const Scene s = shakenFilaments(2, 400);
  EXPECT_TRUE(partitionOf(s, 1).independent);
  expectFusedEqualsPlain(s);
  // Every third bond made from its higher element (a > b): the sweep orders bonds by their
  // lower element, whichever end it is.
  Scene reversed = s;
  for (std::size_t k = 0; k < reversed.bonds.size(); k += 3) {
    const Bond& b = reversed.bonds[k];
    reversed.bonds[k] = makeBond(b.b, b.a, reversed.bodies, b.k, b.section);
  }
  expectFusedEqualsPlain(reversed);
}

TEST(MdemStepper, ContactsInTheParallelRegionAreThreadIndependent) {
  // A random network with van der Waals contacts, dashpots and local damping: the contact
  // phases (neighbour list, pairs, dissipated work) run inside the stepper's region.
  Scene s = dampedNetworkScene();
  ASSERT_GT(s.bodies.size(), kSmallScene);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  Simulation one(s);
  one.run(120);
  omp_set_num_threads(2);
  Simulation two(s);
  two.run(60), two.run(60);
  omp_set_num_threads(saved);
  expectIdentical(one.bodies(), two.bodies());
  const EnergyLedger a = one.energies(), b = two.energies();
  EXPECT_EQ(a["contact_dissipated"], b["contact_dissipated"]);
  EXPECT_GT(a["contact_dissipated"], 0.0);
  EXPECT_LT(a["vdw"], 0.0);
}

}  // namespace
}  // namespace mesochain::mdem
