// The dashpot probe of `bench zipping` (mdem/contacts/dashpot_probe.hpp): pairs sorted into the
// wall-gap bands and their relative speeds on a hand-made configuration (closed forms); its power
// equals the work rate of the dashpot forces; along a damped zipping run its integrated power is
// the ledger's "contact_dissipated", and kinetic + potential + dissipated closes the energy
// balance without local damping (the split the bench reports).
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "contact_fixture.hpp"
#include "mdem/contacts/dashpot_probe.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

ContactDampingSpec spec() {
  ContactDampingSpec d;
  d.translational = 2.0, d.rotational = 0.2, d.fullGap = 0.5, d.cutoffGap = 1.0;
  return d;
}

ProbeElement element(const Vec3& centre, const Vec3& axis, int filament, const Vec3& v = Vec3::Zero(),
                     const Vec3& w = Vec3::Zero()) {
  ProbeElement e;
  e.segment = {centre, axis.normalized(), 0.5 * kSegmentLength};
  e.radius = kTubeRadius, e.velocity = v, e.angularVelocity = w, e.filament = filament;
  return e;
}

TEST(MdemDashpotProbe, BandsSpeedsAndRatesOfAHandMadeConfiguration) {
  const double r2 = 2.0 * kTubeRadius;
  const Vec3 x = Vec3::UnitX();
  // A at rest on the x axis; B parallel at wall gap 0.3 (full band), sliding at 3 nm/ns and
  // spinning at 1 rad/ns about z; C parallel at gap 0.75 (ramp: weight 1 - smoothstep(0.5) =
  // 1/2), moving at 1 nm/ns along z; D parallel at gap 1.1 (vdW only), moving at 2 nm/ns along y.
  // The other pairs are more than 1.2 nm apart; E belongs to A's filament and lies on B.
  const std::vector<ProbeElement> el{
      element(Vec3::Zero(), x, 0),
      element(Vec3(0, r2 + 0.3, 0), x, 1, Vec3(3, 0, 0), Vec3(0, 0, 1)),
      element(Vec3(0, -(r2 + 0.75), 0), x, 2, Vec3(0, 0, 1)),
      element(Vec3(0, 0, r2 + 1.1), x, 3, Vec3(0, 2, 0)),
      element(Vec3(0, 2 * (r2 + 0.3), 0), x, 0),
  };
  const DashpotProbe p = probeDashpots(spec(), 1.2, el);
  // Full band: A-B and B-E (E is A's filament, not B's: the pair counts; E at rest). The contact
  // point of A-B is the midpoint of the axes, 0.828 nm + 0.15 nm from B's axis on A's side: B's
  // spin adds w x (c - x_B) = (0,0,1) x (0,-(R + 0.15),0) = (R + 0.15, 0, 0).
  const double spinAB = kTubeRadius + 0.15, vAB = 3.0 + spinAB, vBE = 3.0 - spinAB;
  EXPECT_EQ(p.full.pairs, 2);
  EXPECT_NEAR(p.full.sumSpeedSquared, vAB * vAB + vBE * vBE, 1e-12);
  EXPECT_EQ(p.ramp.pairs, 1);
  EXPECT_NEAR(p.ramp.rmsSpeed(), 1.0, 1e-12);
  EXPECT_EQ(p.vdwOnly.pairs, 1);
  EXPECT_NEAR(p.vdwOnly.rmsSpeed(), 2.0, 1e-12);
  // lambda s: 2 nm (full overlap, parallel) for A-B and B-E, 1 nm for A-C, none for A-D.
  EXPECT_NEAR(p.weightedLength, 5.0, 1e-12);
  EXPECT_NEAR(p.translationalRate, 2.0 * (vAB * vAB + vBE * vBE) + 1.0 * 1.0, 1e-12);
  EXPECT_NEAR(p.rotationalRate, 2.0 * 1.0 + 2.0 * 1.0, 1e-12);
  // About the origin: contact points at y = R + 0.15 (A-B), 2 (R + 0.15) + R + 0.15 (B-E) and
  // -(R + 0.375) (A-C).
  const double yAB = spinAB, yBE = 3.0 * spinAB, yAC = kTubeRadius + 0.375;
  EXPECT_NEAR(p.weightedLengthMoment, 2.0 * yAB * yAB + 2.0 * yBE * yBE + 1.0 * yAC * yAC, 1e-12);
  EXPECT_NEAR(probeDashpots(spec(), 1.2, el, Vec3(0, yAB, 0)).weightedLengthMoment,
              2.0 * 4.0 * yAB * yAB + 1.0 * (yAC + yAB) * (yAC + yAB), 1e-12);
  EXPECT_NEAR(p.power(spec()), 2.0 * p.translationalRate + 0.2 * p.rotationalRate, 1e-12);

  // One filament: nothing; beyond every cut-off: nothing.
  std::vector<ProbeElement> same = el;
  for (ProbeElement& e : same) e.filament = 0;
  const DashpotProbe none = probeDashpots(spec(), 1.2, same);
  EXPECT_EQ(none.full.pairs + none.ramp.pairs + none.vdwOnly.pairs, 0);
  EXPECT_EQ(none.weightedLength, 0.0);
  const DashpotProbe far = probeDashpots(spec(), 1.2, {element(Vec3::Zero(), x, 0), element(Vec3(0, r2 + 1.25, 0), x, 1)});
  EXPECT_EQ(far.full.pairs + far.ramp.pairs + far.vdwOnly.pairs, 0);
}

TEST(MdemDashpotProbe, PowerIsTheWorkRateOfTheDashpotForces) {
  // Random crossings near contact, random velocities: P = -(sum F.v + M.w) of contactDashpot.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  int contacts = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<ProbeElement> el;
    for (int k = 0; k < 4; ++k)
      el.push_back(element(Vec3(0.7 * u(rng), 1.9 * k + 0.2 * u(rng), 0.5 * u(rng)), vec() + Vec3(2, 0, 0), k % 2,
                           3.0 * vec(), 2.0 * vec()));
    const DashpotProbe p = probeDashpots(spec(), 1.2, el);
    double work = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < el.size(); ++i)
      for (std::size_t j = i + 1; j < el.size(); ++j) {
        if (el[i].filament == el[j].filament) continue;
        const ContactPairResult r = contactDashpot(spec(), el[i].segment, el[j].segment, kTubeRadius, kTubeRadius,
                                                   el[i].velocity, el[i].angularVelocity, el[j].velocity,
                                                   el[j].angularVelocity);
        const double w = r.forceA.dot(el[i].velocity) + r.torqueA.dot(el[i].angularVelocity) +
                         r.forceB.dot(el[j].velocity) + r.torqueB.dot(el[j].angularVelocity);
        work -= w, scale += std::abs(w);
      }
    EXPECT_NEAR(p.power(spec()), work, 1e-12 * std::max(1.0, scale)) << "trial " << trial;
    EXPECT_GE(p.power(spec()), 0.0);
    contacts += p.full.pairs + p.ramp.pairs;
  }
  EXPECT_GT(contacts, 20);  // the trials do exercise the dashpots
}

// Two crossed tubes of 4 elements at 45 degrees, wall gap 0.34 nm, dashpots gamma = 2,
// gamma_r = 0.2, h = 2e-5 ns (bench zipping's set-up, shorter tubes).
Scene zippingPair(double alpha) {
  std::vector<std::string> effects{"bonds", "vdw_contact", "contact_damping"};
  if (alpha > 0) effects.push_back("local_damping");
  Scene s = tubeScene(effects);
  s.contacts.damping = spec();
  s.localDampingAlpha = alpha;
  const int n = 4;
  const double d = 2 * kTubeRadius + 0.34, half = 0.5 * (n - 1) * kSegmentLength, angle = 0.7854;
  const Vec3 tb(std::cos(angle), 0.0, std::sin(angle));
  addTube(s, n, -half * Vec3::UnitX(), Vec3::UnitX());
  addTube(s, n, Vec3(0, d, 0) - half * tb, tb);
  s.run.timeStepFraction = 0.0, s.run.timeStep = 2e-5;
  return s;
}

DashpotProbe probe(const Simulation& sim) {
  const Bodies& b = sim.bodies();
  std::vector<ProbeElement> el;
  for (int i = 0; i < b.size(); ++i)
    el.push_back(element(b.position[i], rotate(b.orientation[i], Vec3::UnitZ()), i < 4 ? 0 : 1, b.velocity[i],
                         b.angularVelocityWorld(i)));
  return probeDashpots(spec(), 1.2, el);
}

TEST(MdemDashpotProbe, DampedZippingRunClosesTheEnergySplit) {
  for (double alpha : {0.0, 0.3}) {
    Simulation sim(zippingPair(alpha));
    const EnergyLedger e0 = sim.energies();
    const double h = sim.timeStep();
    double integrated = 0.0, previous = probe(sim).power(spec()), minVdw = e0["vdw"];
    for (int k = 0; k < 3000; ++k) {  // 0.06 ns: the zipping of 4-element tubes
      sim.step();
      const double now = probe(sim).power(spec());
      integrated += 0.5 * h * (previous + now);  // trapezoid rule
      previous = now;
      if (k % 100 == 0) minVdw = std::min(minVdw, sim.energies()["vdw"]);
    }
    const EnergyLedger e = sim.energies();
    const double dashpots = e["contact_dissipated"], residual = e0.total() - e.total() - dashpots;
    const double released = e0["vdw"] - minVdw;
    std::printf("alpha %.1f: vdW released %.1f zJ, dashpots %.2f zJ (probe %.2f), residual %.3f zJ\n", alpha,
                released, dashpots, integrated, residual);
    EXPECT_GT(released, 100.0);
    EXPECT_GT(dashpots, 0.05 * released);
    // The ledger integrates the same power with the stepper's velocities: agreement to O(h).
    EXPECT_NEAR(integrated, dashpots, 0.005 * dashpots);
    if (alpha == 0.0)
      EXPECT_LT(std::abs(residual), 0.01 * released);  // integrator error only
    else
      EXPECT_GT(residual, 0.05 * released);  // the work of the local damping
  }
}

}  // namespace
}  // namespace mesochain::mdem
