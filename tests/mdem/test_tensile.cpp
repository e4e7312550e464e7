// Tensile test with grips (mdem/tensile.hpp) on a single straight tube between the grips: the
// grips follow the prescribed ramp profile; the unstressed tube has zero stress at zero strain;
// the stress-strain slope is Y A_tube / A_film (closed form for bonds in series over the gauge
// length); the grips' work equals the change of the total energy (energy decomposition closes).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"

#include "contact_fixture.hpp"
#include "mdem/run.hpp"
#include "mdem/tensile.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

constexpr double kFilm = 100.0;  // nm^2, the cross-section given

Scene tubeBetweenGrips(std::vector<std::string> effects, double ramp) {
  Scene s = tubeScene(std::move(effects));
  addTube(s, 12, Vec3::Zero(), Vec3::UnitX());  // centres 0, 2, ..., 22 nm
  s.tensile.enabled = true;
  s.tensile.gripWidth = 3.0;  // two elements per grip
  s.tensile.strainRate = 1.0;
  s.tensile.ramp = ramp;
  s.tensile.crossSection = kFilm;
  setUpTensile(s);
  s.run.timeStepFraction = 0.5;
  return s;
}

// A free tube of 6 elements lying on the gripped one at a wall gap of 0.32 nm, with vdW contacts
// and dashpots (no local damping): the pull drags it along, the dashpots taking their share.
Scene draggedTubeScene(double timeStepFraction) {
  Scene s = tubeBetweenGrips({"bonds", "vdw_contact", "contact_damping"}, 0.002);
  s.contacts.damping.translational = 1.0, s.contacts.damping.rotational = 0.1;
  addTube(s, 6, Vec3(6.0, 2.0 * kTubeRadius + 0.32, 0.0), Vec3::UnitX());
  s.run.timeStepFraction = timeStepFraction;
  return s;
}

// Runs `sim` to `until` (ns), `every` steps at a time, recording a sample after each (the grips'
// work is the trapezoid rule over the samples); `each` sees every new sample.
template <class Each>
void recordUntil(Simulation& sim, TensileRecorder& rec, double until, long every, Each&& each) {
  while (sim.time() < until) {
    sim.run(every);
    each(rec.record(sim));
  }
}
void recordUntil(Simulation& sim, TensileRecorder& rec, double until, long every) {
  recordUntil(sim, rec, until, every, [](const TensileSample&) {});
}

// Runs `s` to 0.01 ns, sampling every step; returns the samples and the largest
// |total - total(0) - (grip work - dissipated)| over the samples, relative to the final grip work.
struct Balance {
  std::vector<TensileSample> samples;
  double worst = 0.0;  // of W
};
Balance energyBalance(const Scene& s) {
  Simulation sim(s);
  TensileRecorder rec(s, "");
  const double start = rec.record(sim).energies.total();
  double mismatch = 0.0;
  recordUntil(sim, rec, 0.01, 1, [&](const TensileSample& t) {
    mismatch = std::max(mismatch, std::abs(t.energies.total() - start - (t.gripWork - t.energies.dissipated())));
  });
  return {rec.samples(), mismatch / rec.samples().back().gripWork};
}

TEST(MdemTensile, GripsFollowTheRampProfile) {
  Scene s = tubeBetweenGrips({"bonds"}, 0.004);
  ASSERT_EQ(s.tensile.leftGrip.size(), 2u);
  ASSERT_EQ(s.tensile.rightGrip.size(), 2u);
  EXPECT_NEAR(s.tensile.gaugeLength, 18.0, 1e-12);  // from the centre at 2 nm to the one at 20 nm
  const double v = s.tensile.gripSpeed, ramp = s.tensile.ramp;
  EXPECT_NEAR(v, 9.0, 1e-12);  // each grip: strain rate x L0 / 2
  Simulation sim(s);
  double worst = 0.0;
  while (sim.time() < 3.0 * ramp) {
    sim.run(5);
    const double t = sim.time();
    const double expected = t <= ramp ? v * t * t / (2.0 * ramp) : v * (t - 0.5 * ramp);
    for (int i : {10, 11}) worst = std::max(worst, std::abs(sim.bodies().position[i].x() - s.bodies.position[i].x() - expected));
    for (int i : {0, 1}) worst = std::max(worst, std::abs(s.bodies.position[i].x() - sim.bodies().position[i].x() - expected));
  }
  // The velocity is set at the half steps: the displacement error is O(v h^2 / ramp) per step.
  EXPECT_LT(worst, 2.0 * v * sim.timeStep());
}

TEST(MdemTensile, SingleTubeStressStrainSlopeIsYATubeOverAFilm) {
  Scene s = tubeBetweenGrips({"bonds", "local_damping"}, 0.002);
  Simulation sim(s);
  TensileRecorder rec(s, "");
  EXPECT_EQ(rec.record(sim).stress, 0.0);  // unstressed at zero strain
  while (sim.time() < 0.012) {
    sim.run(10);
    rec.record(sim);
  }
  // Least-squares slope over the constant-velocity part (strain > 0.4 %).
  const ElasticFit fit = fitElasticSlope(rec.samples(), 0.004, rec.samples().back().strain);
  ASSERT_TRUE(fit.fitted);
  ASSERT_GT(fit.samples, 5);
  const double slope = fit.slope;
  EXPECT_GT(fit.r2, 0.99);
  const double expected = 1e6 * units::kPi * kTubeRadius * kTubeRadius / kFilm;  // Y A / A_film, MPa
  std::printf("single tube: slope %.6g MPa, Y A / A_film %.6g MPa, final strain %.4f\n", slope, expected,
              rec.samples().back().strain);
  EXPECT_NEAR(slope, expected, 0.01 * expected);
}

TEST(MdemTensile, ElasticFitRecoversALineAndIgnoresSamplesOutsideItsRange) {
  std::vector<TensileSample> samples;
  for (int k = 0; k <= 10; ++k) {
    TensileSample t;
    t.strain = 0.005 * k;
    t.stress = t.strain <= 0.03 ? 5.0 + 200.0 * t.strain : 1e3;  // beyond 3 %: not elastic
    samples.push_back(t);
  }
  const ElasticFit f = fitElasticSlope(samples, 0.0, kElasticStrain);
  EXPECT_EQ(f.samples, 7);
  EXPECT_NEAR(f.slope, 200.0, 1e-9);
  EXPECT_NEAR(f.intercept, 5.0, 1e-12);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(f.to, 0.03);
  EXPECT_TRUE(f.fitted);
  EXPECT_EQ(fitElasticSlope(samples, 0.1, 0.2).samples, 0);  // nothing in range: no fit
  EXPECT_FALSE(fitElasticSlope(samples, 0.1, 0.2).fitted);
  EXPECT_EQ(fitElasticSlope(samples, 0.1, 0.2).slope, 0.0);
}

// A stage that ends at a tiny strain (here 2 samples, or 3 over a tenth of the window) has no
// slope: a line through two nearly equal strains is noise (a 1-step pull printed -2.7e10 MPa).
TEST(MdemTensile, ElasticFitRefusesTooFewSamplesOrTooNarrowARange) {
  std::vector<TensileSample> samples;
  for (double strain : {0.0, 1.8e-10}) {
    TensileSample t;
    t.strain = strain, t.stress = strain == 0.0 ? -1.4 : -6.3;
    samples.push_back(t);
  }
  const ElasticFit two = fitElasticSlope(samples, 0.0, kElasticStrain);
  EXPECT_EQ(two.samples, 2);
  EXPECT_FALSE(two.fitted);
  EXPECT_EQ(two.slope, 0.0);
  TensileSample third;
  third.strain = 0.003, third.stress = 0.5;  // 3 samples over 10 % of the 3 % window
  samples.push_back(third);
  EXPECT_FALSE(fitElasticSlope(samples, 0.0, kElasticStrain).fitted);
  third.strain = 0.016;                       // over 53 %: fitted
  samples.back() = third;
  EXPECT_TRUE(fitElasticSlope(samples, 0.0, kElasticStrain).fitted);
}

TEST(MdemTensile, GripWorkEqualsTheChangeOfTheTotalEnergy) {
  Scene s = tubeBetweenGrips({"bonds"}, 0.002);  // no damping: the balance is exact up to Verlet
  Simulation sim(s);
  TensileRecorder rec(s, "");
  rec.record(sim);
  recordUntil(sim, rec, 0.01, 2);
  const TensileSample& last = rec.samples().back();
  const EnergyLedger& e = last.energies;
  const double parts = e["stretching"] + e["shearing"] + e["twisting"] + e["bending"] + e["vdw"] +
                       e.kinetic();
  const double change = e.total() - rec.samples().front().energies.total();
  std::printf("grip work %.6g zJ, energy change %.6g zJ (stretching %.6g, kinetic %.6g)\n", last.gripWork, change,
              e["stretching"], e["kinetic_translational"]);
  EXPECT_NEAR(parts, e.total(), 1e-9 * std::abs(e.total()));
  EXPECT_GT(last.gripWork, 0.0);
  EXPECT_NEAR(change, last.gripWork, 0.01 * last.gripWork);
}

// The energy balance with contacts and their dashpots (no local damping): a free tube lying on
// a gripped one is dragged along by the dashpots as the grips pull; the grips' work W minus the
// work D the dashpots took equals the change of the total energy at every sample. Velocity
// Verlet conserves energy to O(h^2), and the dashpots' work is charged exactly as their forces
// enter the kicks (contact_effects.hpp), so the mismatch falls about 4x per halved step and is
// below 1e-6 of W at 0.05 of the critical step.
TEST(MdemTensile, GripWorkMinusDissipatedIsTheEnergyChangeWithContacts) {
  std::vector<double> worst;
  for (double fraction : {0.4, 0.2, 0.1, 0.05}) {
    const Balance b = energyBalance(draggedTubeScene(fraction));
    const TensileSample& last = b.samples.back();
    std::printf("fraction %.2g: %zu steps, grip work %.9g zJ, dissipated %.9g, largest mismatch %.3g of W\n", fraction,
                b.samples.size() - 1, last.gripWork, last.energies.dissipated(), b.worst);
    EXPECT_GT(last.energies.dissipated(), 0.01 * last.gripWork);  // the dashpots take a real share
    worst.push_back(b.worst);
  }
  for (std::size_t k = 1; k < worst.size(); ++k) EXPECT_GT(worst[k - 1] / worst[k], 3.0) << "second order, step " << k;
  EXPECT_LT(worst.back(), 1e-6);
}

// The same balance with numerical damping on every element, its work tracked (`track_work`):
// Cundall's local damping, then the viscous drag. The grips' work W minus the work of the
// dashpots and of the damping equals the change of the total energy, to the integrator's
// O(h^2). The damping's work is charged as the dashpots' is (damping.hpp), without the
// components the grips hold (their damping is cleared). It is 0.9 % (local) and 1.0 % (viscous)
// of W here (most of W is stretching): left out, the balance would miss by 1e4 times its
// tolerance.
TEST(MdemTensile, GripWorkMinusDissipatedHoldsWithTrackedNumericalDamping) {
  for (const std::string damping : {"local_damping", "viscous_damping"}) {
    std::vector<double> worst;
    for (double fraction : {0.2, 0.1, 0.05}) {
      Scene s = draggedTubeScene(fraction);
      s.effects.push_back(damping);
      s.localDampingAlpha = 0.3, s.localDampingTracksWork = true;
      s.viscousRate = 500.0, s.viscousDampingTracksWork = true;  // 1/ns, far below the bonds' 2e4 rad/ns
      const Balance b = energyBalance(s);
      const EnergyLedger& e = b.samples.back().energies;
      const double w = b.samples.back().gripWork;
      std::printf("%s, fraction %.2g: grip work %.9g zJ, dashpots %.9g, damping %.9g, largest mismatch %.3g of W\n",
                  damping.c_str(), fraction, w, e["contact_dissipated"], e[damping + "_dissipated"], b.worst);
      EXPECT_GT(e[damping + "_dissipated"], 0.005 * w) << damping;
      worst.push_back(b.worst);
    }
    for (std::size_t k = 1; k < worst.size(); ++k) EXPECT_GT(worst[k - 1] / worst[k], 3.0) << damping << ", second order, step " << k;
    EXPECT_LT(worst.back(), 1e-6) << damping;
    // Untracked, the entry is absent.
    Scene untracked = draggedTubeScene(0.05);
    untracked.effects.push_back(damping);
    EXPECT_FALSE(Simulation(untracked).energies().has(damping + "_dissipated")) << damping;
  }
}

// The same balance across a stage boundary: the simulation rebuilt at the boundary time from
// the first one's elements and effect states, its forces refreshed (mdem/run.cpp, as between two
// [[stages]]). The replaced forces never take their second half kick and the new ones open the
// next step (contact_effects.hpp): the mismatch stays at the single simulation's O(h^2) level.
TEST(MdemTensile, GripWorkMinusDissipatedHoldsAcrossAStageBoundary) {
  const Scene s = draggedTubeScene(0.05);
  Simulation first(s);
  TensileRecorder before(s, "");
  const EnergyLedger start = before.record(first).energies;
  recordUntil(first, before, 0.005, 1);
  const double workBefore = before.samples().back().gripWork;
  Scene next = s;
  next.bodies = first.bodies();
  Simulation second(next, first.time(), first.stepCount());
  continueEffectStates(second, savedEffectStates(first), "<boundary>");
  TensileRecorder after(next, "");
  after.record(second);
  recordUntil(second, after, 0.01, 1);
  const TensileSample& end = after.samples().back();
  const double work = workBefore + end.gripWork;
  const double mismatch = end.energies.total() - start.total() - (work - end.energies.dissipated());
  std::printf("grip work %.9g zJ, dissipated %.9g, mismatch %.3g of W\n", work, end.energies.dissipated(), mismatch / work);
  EXPECT_GT(end.energies.dissipated(), 0.01 * work);
  EXPECT_LT(std::abs(mismatch), 1e-6 * work);
}

TEST(MdemTensile, ContactGapBeyondTheNeighbourListsReachIsAClearError) {
  // Contacts are counted from the contacts' neighbour list, which reaches 2 R + 1.2 nm (+ 3 table
  // steps) between the axes with vdw_contact: a wall gap of 1.2 nm is covered, 1.3 nm is not.
  for (double gap : {1.2, 1.3}) {
    Scene s = tubeScene({"bonds", "vdw_contact"});
    addTube(s, 12, Vec3::Zero(), Vec3::UnitX());
    s.tensile.enabled = true, s.tensile.gripWidth = 3.0, s.tensile.strainRate = 1.0, s.tensile.crossSection = kFilm;
    s.tensile.contactGap = gap;
    if (gap < 1.25) {
      EXPECT_NO_THROW(setUpTensile(s));
      continue;
    }
    try {
      setUpTensile(s);
      ADD_FAILURE() << "no error for contact_gap_nm = " << gap;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("tensile.contact_gap_nm"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("1.3 nm"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace mesochain::mdem
