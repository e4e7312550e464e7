// Mass (density) scaling, [run] mass_scale and [[stages]] mass_scale (docs/scene-file.md, "Longer
// steps"; mdem/body.hpp, scaleInertia):
//  * a conservative system whose every inertia is scaled by s = 4 and stepped at 2h traces the
//    unscaled trajectory stepped at h, step for step (the equations of motion in time t sqrt(s)),
//    with velocities halved and the same potential energies;
//  * the critical step of a bonded scene grows as sqrt(s);
//  * a quasi-static pull keeps the closed-form slope Y A_tube / A_film, and the grips' work still
//    equals the change of the (scaled) total energy;
//  * a stage sets its own scale and the next stage returns to the unscaled inertia, velocities
//    kept. (The keys and the checkpoint's refusal of another scale: test_time_step_levers.cpp.)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "contact_fixture.hpp"

#include "mdem/run.hpp"
#include "mdem/tensile.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// An oblique chain of 8 bricks, bonded at rest and then displaced and turned at random (at rest:
// the motion is set by the bonds alone).
Scene deformedChain() {
  Scene s = filament(8, Vec3::Zero(), Vec3(1.0, 0.4, 0.2).normalized());
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < s.bodies.size(); ++i) {
    s.bodies.position[i] += 0.01 * Vec3(u(gen), u(gen), u(gen));
    s.bodies.orientation[i] = normalized(expMap(0.01 * Vec3(u(gen), u(gen), u(gen))) * s.bodies.orientation[i]);
  }
  return s;
}

TEST(MdemMassScaling, ScaledChainFollowsTheUnscaledTrajectoryInStretchedTime) {
  Scene plain = deformedChain();
  plain.run.rotationalInertiaScale = 2.0;  // the two knobs compose
  plain.run.timeStep = 2e-5;
  Scene scaled = plain;
  scaled.run.massScale = 4.0;
  scaled.run.timeStep = 4e-5;  // sqrt(4) h
  Simulation a(plain), b(scaled);
  EXPECT_EQ(b.bodies().mass[3], 4.0 * kMass);
  EXPECT_EQ(b.bodies().inertia[3], 8.0 * plain.elementTypes[0].principalInertia());
  double moved = 0.0, positions = 0.0, velocities = 0.0, spins = 0.0;
  for (int k = 0; k < 20; ++k) {
    a.run(25), b.run(25);
    for (int i = 0; i < a.bodies().size(); ++i) {
      moved = std::max(moved, (a.bodies().position[i] - plain.bodies.position[i]).norm());
      positions = std::max(positions, (a.bodies().position[i] - b.bodies().position[i]).norm());
      velocities = std::max(velocities, (a.bodies().velocity[i] - 2.0 * b.bodies().velocity[i]).norm() /
                                            (a.bodies().velocity[i].norm() + 1e-3));
      spins = std::max(spins, (a.bodies().angularVelocityWorld(i) - 2.0 * b.bodies().angularVelocityWorld(i)).norm() /
                                  (a.bodies().angularVelocityWorld(i).norm() + 1e-3));
    }
  }
  std::printf("moved up to %.3g nm; scaled - plain: positions %.3g nm, velocities %.3g, spins %.3g (relative)\n", moved,
              positions, velocities, spins);
  ASSERT_GT(moved, 2e-3);  // the chain does vibrate
  EXPECT_LT(positions, 1e-12);
  EXPECT_LT(velocities, 1e-10);
  EXPECT_LT(spins, 1e-10);
  EXPECT_NEAR(b.time(), 2.0 * a.time(), 1e-15);
  for (const char* term : {"stretching", "shearing", "twisting", "bending"})
    EXPECT_NEAR(b.energies()[term], a.energies()[term], 1e-9 * a.energies().total()) << term;
  // Kinetic energy: (s m)(v / sqrt(s))^2 / 2, the same.
  EXPECT_NEAR(b.energies().kinetic(), a.energies().kinetic(), 1e-9 * a.energies().total());
}

TEST(MdemMassScaling, CriticalStepGrowsAsTheSquareRootOfTheScale) {
  for (bool body : {false, true}) {
    Scene s = deformedChain();
    s.run.timeStepFraction = 0.5;
    s.run.bodyFrameCriticalStep = body;
    const Simulation plain(s);
    s.run.massScale = 16.0;
    const Simulation scaled(s);
    EXPECT_NEAR(scaled.stability().criticalTimeStep, 4.0 * plain.stability().criticalTimeStep,
                1e-12 * scaled.stability().criticalTimeStep);
    EXPECT_NEAR(scaled.timeStep(), 4.0 * plain.timeStep(), 1e-12 * scaled.timeStep());
  }
}

// A tube of 12 elements between grips, pulled at `rate` (1/ns) after a ramp of 0.002 / rate ns.
Scene tubeBetweenGrips(std::vector<std::string> effects, double massScale, double rate) {
  Scene s = tubeScene(std::move(effects));
  addTube(s, 12, Vec3::Zero(), Vec3::UnitX());
  s.tensile.enabled = true;
  s.tensile.gripWidth = 3.0;
  s.tensile.strainRate = rate;
  s.tensile.ramp = 0.002 / rate;
  s.tensile.crossSection = 100.0;
  setUpTensile(s);
  s.run.timeStepFraction = 0.5;
  s.run.massScale = massScale;
  return s;
}

// Mass scaling is for quasi-static loading: the pull must stay slow next to the time an axial
// wave takes to cross the specimen, which grows as sqrt(s). The single tube (1.8e-3 ns transit at
// s = 1) keeps Y A_tube / A_film within 1 % at 1/ns unscaled; at s = 16 its transit is 4x longer
// and the same pull reads 3 % high (inertia), while a pull 4x slower (the same ratio of loading
// to transit time) reads the closed form again.
TEST(MdemMassScaling, QuasiStaticPullKeepsTheSlopeAndTheEnergyBalance) {
  const double expected = 1e6 * units::kPi * kTubeRadius * kTubeRadius / 100.0;  // Y A / A_film, MPa
  for (auto [scale, rate] : {std::pair{1.0, 1.0}, {16.0, 1.0}, {16.0, 0.25}}) {
    Scene s = tubeBetweenGrips({"bonds", "local_damping"}, scale, rate);
    Simulation sim(s);
    TensileRecorder rec(s, "");
    while (sim.time() < 0.012 / rate) sim.run(5), rec.record(sim);
    const ElasticFit fit = fitElasticSlope(rec.samples(), 0.004, rec.samples().back().strain);
    ASSERT_TRUE(fit.fitted);
    std::printf("mass scale %g, %g/ns: h %.4g ns, slope %.6g MPa (Y A / A_film %.6g)\n", scale, rate, sim.timeStep(),
                fit.slope, expected);
    if (scale == 16.0 && rate == 1.0)
      EXPECT_GT(std::abs(fit.slope - expected), 0.01 * expected);  // too fast for the heavier tube
    else
      EXPECT_NEAR(fit.slope, expected, 0.01 * expected);

    Scene c = tubeBetweenGrips({"bonds"}, scale, rate);  // no damping: the balance is exact up to Verlet
    Simulation conservative(c);
    TensileRecorder balance(c, "");
    balance.record(conservative);
    while (conservative.time() < 0.01 / rate) conservative.run(2), balance.record(conservative);
    const TensileSample& last = balance.samples().back();
    const double change = last.energies.total() - balance.samples().front().energies.total();
    EXPECT_GT(last.gripWork, 0.0);
    EXPECT_NEAR(change, last.gripWork, 0.01 * last.gripWork) << "mass scale " << scale;
  }
}

TEST(MdemMassScaling, AStageSetsItsOwnScaleAndTheNextReturnsToTheUnscaledInertia) {
  Scene s = filament(8);  // straight and at rest: the state, and with it the critical step, stays
  s.run.timeStepFraction = 0.5;
  StageSpec scaled;
  scaled.name = "scaled", scaled.steps = 10, scaled.massScale = 4.0;
  StageSpec plain;
  plain.name = "plain", plain.steps = 10;
  s.stages = {scaled, plain};
  s.output.checkpointMinutes = 0.0;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("mesochain-mass-" + std::to_string(::getpid()));
  RunOptions options;
  options.overwrite = true;
  const RunSummary r = runScene(s, dir.string(), [](double) {}, options);
  ASSERT_EQ(r.stages.size(), 2u);
  // Bonds only: the critical step is 2/omega_max, omega_max ~ 1/sqrt(m): the scaled stage's step
  // is twice the next one's.
  EXPECT_NEAR(r.stages[0].time / r.stages[1].time, 2.0, 1e-12);

  // At the Simulation level: velocities and angular velocities carried, inertia back to the type's.
  Scene first = deformedChain();
  first.run.timeStepFraction = 0.5, first.run.massScale = 4.0;
  Simulation a(first);
  a.run(30);
  Scene next = first;
  next.run.massScale = 1.0;
  next.bodies = a.bodies();
  const Simulation b(next);
  for (int i = 0; i < b.bodies().size(); ++i) {
    EXPECT_EQ(b.bodies().mass[i], kMass);
    EXPECT_EQ(b.bodies().inertia[i], first.elementTypes[0].principalInertia());
    EXPECT_EQ(b.bodies().velocity[i], a.bodies().velocity[i]);
    EXPECT_LT((b.bodies().angularVelocityWorld(i) - a.bodies().angularVelocityWorld(i)).norm(),
              1e-12 * (1.0 + a.bodies().angularVelocityWorld(i).norm()));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mesochain::mdem
