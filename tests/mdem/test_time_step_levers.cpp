// The levers on the mDEM time step (docs/scene-file.md, [run] critical_step and
// rotational_inertia_scale; docs/benchmarks.md, "What sets the mDEM time step"):
//  * the bond spectrum (bond_spectrum.hpp) per filament equals the dense eigenfrequencies of the
//    whole assembly (normal_modes.hpp), and both Gershgorin bounds (world and body axes) lie at
//    or above it, the body-axes one at or below the world-axes one for an oblique chain;
//  * a twisted element with scaled inertia vibrates at the analytic torsion frequency over
//    sqrt(scale); scaling keeps the angular velocities and puts the scaled inertia into the
//    rotational kinetic energy; energy is conserved with scaled inertia;
//  * the scene file reads the keys (mass_scale too, in [run] and per stage) and refuses bad
//    values; a checkpoint of another scale (rotational, mass, a stage's mass) or frame is refused,
//    one of the same is accepted.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "tests/support/expect_input_error.hpp"

#include "mdem/bond_spectrum.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/normal_modes.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;
using mesochain::testing::expectInputError;

// Two oblique filaments of bricks (6 and 4 elements), one of them turned about its axis.
Scene twoObliqueFilaments() {
  Scene s = filament(6, Vec3::Zero(), Vec3(1.0, 0.7, 0.3).normalized(), Vec3(0.2, -1.0, 0.4));
  FilamentSpec f;
  f.count = 4, f.start = Vec3(0.0, 0.0, 10.0), f.direction = Vec3(-0.3, 1.0, 0.5).normalized();
  f.thicknessAxis = Vec3(1.0, 0.0, 0.0);
  addFilament(s, f);
  return s;
}

TEST(MdemTimeStepLevers, BondSpectrumMatchesDenseEigenfrequenciesAndLiesBelowBothBounds) {
  for (double scale : {1.0, 16.0}) {
    Scene s = twoObliqueFilaments();
    scaleInertia(s.bodies, s.elementTypes, 1.0, scale);
    const KinematicMap kin(s.boundary, s.bodies.size());
    const BondSpectrum b = bondSpectrum(s.bodies, s.bonds, kin);
    const Eigen::VectorXd w = eigenfrequencies(s.bodies, s.bonds, std::vector<bool>(6 * s.bodies.size(), true));
    EXPECT_EQ(b.components, 2);
    EXPECT_EQ(b.largestComponent, 6);
    EXPECT_NEAR(b.omegaMax, w.maxCoeff(), 1e-9 * w.maxCoeff());
    const double world = criticalTimeStep(s.bodies, s.bonds, kin).omegaMax;
    const double body = criticalTimeStep(s.bodies, s.bonds, kin, {}, GershgorinFrame::Body).omegaMax;
    EXPECT_GE(body, b.omegaMax * (1.0 - 1e-12));
    EXPECT_LE(body, world * (1.0 + 1e-12));
    EXPECT_LT(body, 0.95 * world);  // the oblique chain's axial rows: tighter in body axes
    const double shares = b.mode.axial + b.mode.transverse + b.mode.torsion + b.mode.bendingRotation;
    EXPECT_NEAR(shares, 1.0, 1e-12);
    if (scale == 16.0) {
      EXPECT_GT(b.mode.axial, 0.9);  // rotations slowed: the axial mode is the fastest
    }
  }
}

TEST(MdemTimeStepLevers, StraightChainAxialRowsAreExactInBodyAxes) {
  // Rotations scaled away: the fastest mode is axial, omega^2 -> 4 k_n A / m (zone boundary) as the
  // chain grows; the body-axes Gershgorin row of an interior element is 4 k_n A / m exactly.
  // Direction (2, 1, 1): the world row x of the block k_s 1 + (k_n - k_s) e e^T sums to
  // k_n c_x^2 + k_s (1 - c_x^2) + (k_n - k_s) c_x (c_y + c_z) = 1.2 k_n (k_s = 0.4 k_n) against
  // k_n in body axes: omega 1.095x.
  Scene s = filament(40, Vec3::Zero(), Vec3(2.0, 1.0, 1.0).normalized(), Vec3::UnitZ());
  scaleInertia(s.bodies, s.elementTypes, 1.0, 1e4);
  const KinematicMap kin(s.boundary, s.bodies.size());
  const double kn = kYoung / kL;
  const double exact = std::sqrt(4.0 * kn * area() / kMass);
  const double body = criticalTimeStep(s.bodies, s.bonds, kin, {}, GershgorinFrame::Body).omegaMax;
  const double world = criticalTimeStep(s.bodies, s.bonds, kin).omegaMax;
  const double truth = bondSpectrum(s.bodies, s.bonds, kin).omegaMax;
  EXPECT_NEAR(body, exact, 1e-9 * exact);
  EXPECT_GT(world, std::sqrt(1.2) * exact * (1.0 - 1e-9));  // the stiffness spread over three world rows
  EXPECT_LE(truth, body);
  EXPECT_GT(truth, 0.99 * body);
}

// Element 0 clamped, element 1 twisted about the bond axis: theta'' = -(k_s J / I_z) theta.
double torsionPeriod(double scale) {
  Scene s = cantilever(2);
  s.run.rotationalInertiaScale = scale;
  s.run.timeStepFraction = 0.02;
  s.bodies.setAngularVelocityWorld(1, Vec3(0.0, 0.0, 1e-3));
  Simulation sim(s);
  double previous = 0.0, firstUp = -1.0;
  int upCrossings = 0;
  double lastUp = 0.0;
  for (int k = 0; k < 200000 && upCrossings < 4; ++k) {
    const double before = sim.bodies().angularVelocityWorld(1).z();
    sim.step();
    const double now = sim.bodies().angularVelocityWorld(1).z();
    if (before < 0.0 && now >= 0.0) {
      // Linear interpolation of the crossing within the step.
      const double t = sim.time() - sim.timeStep() * now / (now - before);
      if (firstUp < 0.0) firstUp = t;
      lastUp = t, ++upCrossings;
    }
    previous = now;
  }
  (void)previous;
  EXPECT_EQ(upCrossings, 4);
  return (lastUp - firstUp) / 3.0;
}

TEST(MdemTimeStepLevers, TorsionPeriodScalesWithSqrtOfInertiaScale) {
  const double ks = kShear / kL, iz = kMass * (kH * kH + kW * kW) / 12.0;
  for (double scale : {1.0, 9.0}) {
    const double analytic = 2.0 * units::kPi * std::sqrt(scale * iz / (ks * polar()));
    EXPECT_NEAR(torsionPeriod(scale), analytic, 1e-3 * analytic) << "scale " << scale;
  }
}

TEST(MdemTimeStepLevers, ScalingKeepsAngularVelocitiesAndScalesRotationalEnergy) {
  Scene s = filament(3);
  s.run.timeStepFraction = 0.5;
  s.bodies.setAngularVelocityWorld(1, Vec3(0.3, -0.2, 0.5));
  const double plain = Simulation(s).energies()["kinetic_rotational"];
  s.run.rotationalInertiaScale = 4.0;
  const Simulation sim(s);
  EXPECT_NEAR(sim.energies()["kinetic_rotational"], 4.0 * plain, 1e-12 * plain);
  EXPECT_LT((sim.bodies().angularVelocityWorld(1) - Vec3(0.3, -0.2, 0.5)).norm(), 1e-12);
  // Applying the scale to scaled bodies (a later stage) changes nothing.
  Bodies again = sim.bodies();
  scaleInertia(again, s.elementTypes, 1.0, 4.0);
  EXPECT_EQ(again.inertia[1], sim.bodies().inertia[1]);
  EXPECT_EQ(again.angularMomentumBody[1], sim.bodies().angularMomentumBody[1]);
}

// Largest |E(t) - E(0)| over the initial energy of a kicked free chain at 0.7 of the critical
// step, in the first and in the second half of the run.
struct EnergyError {
  double firstHalf = 0.0, secondHalf = 0.0;
};
EnergyError energyError(double scale, bool bodyFrame, double* step) {
  Scene s = filament(8, Vec3::Zero(), Vec3(1.0, 0.4, 0.2).normalized());
  s.run.rotationalInertiaScale = scale;
  s.run.bodyFrameCriticalStep = bodyFrame;
  s.run.timeStepFraction = 0.7;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < s.bodies.size(); ++i) {
    s.bodies.velocity[i] = 0.05 * Vec3(u(gen), u(gen), u(gen));
    s.bodies.setAngularVelocityWorld(i, 0.05 * Vec3(u(gen), u(gen), u(gen)));
  }
  Simulation sim(s);
  *step = sim.timeStep();
  const double e0 = sim.energies().total();
  EnergyError e;
  for (int k = 0; k < 400; ++k) {
    sim.run(50);
    double& worst = k < 200 ? e.firstHalf : e.secondHalf;
    worst = std::max(worst, std::abs(sim.energies().total() - e0) / e0);
  }
  return e;
}

TEST(MdemTimeStepLevers, EnergyIsConservedWithScaledInertiaAtTheLongerStep) {
  double h1, h16;
  const EnergyError plain = energyError(1.0, false, &h1);
  const EnergyError scaled = energyError(16.0, true, &h16);
  std::printf("h %.4g -> %.4g ns; energy error %.3g / %.3g -> %.3g / %.3g\n", h1, h16, plain.firstHalf,
              plain.secondHalf, scaled.firstHalf, scaled.secondHalf);
  EXPECT_GT(h16, 1.3 * h1);  // the lever: a longer step
  // The same fraction of the scaled system's own limit: an error of the same size (second order
  // in h omega), bounded (symplectic: no growth from the first half to the second).
  EXPECT_LT(scaled.secondHalf, 1.5 * plain.secondHalf);
  EXPECT_LT(scaled.secondHalf, 1.5 * scaled.firstHalf);
  EXPECT_LT(plain.secondHalf, 1.5 * plain.firstHalf);
}

TEST(MdemTimeStepLevers, SceneFileReadsTheKeysAndRefusesBadValues) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("mesochain-levers-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string model = (dir / "model.toml").string();
  std::ofstream(model) << "format = 1\n[[element_types]]\nname = \"brick\"\nshape = \"brick\"\nthickness_nm = 0.8\n"
                          "width_nm = 2.4\nlength_nm = 2.0\nmass_ag = 0.01\n[[bond_types]]\nname = \"b\"\n"
                          "young_modulus_MPa = 1.0e6\nshear_modulus_MPa = 0.4e6\n";
  // [run] with `run` after its time step; `stages` (none: a run of 10 steps).
  auto scene = [&](const std::string& run, const std::string& stages = "") {
    const std::string path = (dir / "scene.toml").string();
    std::ofstream(path) << "format = 1\nmodel = \"model.toml\"\neffects = [\"bonds\"]\n[[filaments]]\n"
                           "element_type = \"brick\"\nbond_type = \"b\"\ncount = 4\n[run]\ntime_step_fraction = 0.5\n"
                        << (stages.empty() ? "steps = 10\n" : "") << run << stages;
    return loadScene(path);
  };
  const Scene plain = scene("");
  EXPECT_EQ(plain.run.rotationalInertiaScale, 1.0);
  EXPECT_FALSE(plain.run.bodyFrameCriticalStep);
  const Scene set = scene("rotational_inertia_scale = 8.0\ncritical_step = \"gershgorin_body\"\n");
  EXPECT_EQ(set.run.rotationalInertiaScale, 8.0);
  EXPECT_TRUE(set.run.bodyFrameCriticalStep);
  expectInputError([&] { scene("rotational_inertia_scale = 0.5\n"); }, {"rotational_inertia_scale", "0.5", "[1, 10000]"});
  expectInputError([&] { scene("critical_step = \"power\"\n"); }, {"critical_step", "power", "gershgorin_body"});
  // mass_scale, in [run] and per stage (test_mass_scaling.cpp).
  EXPECT_EQ(plain.run.massScale, 1.0);
  EXPECT_EQ(scene("mass_scale = 25.0\n").run.massScale, 25.0);
  const Scene staged = scene("mass_scale = 4.0\n", "[[stages]]\nname = \"a\"\nsteps = 5\nmass_scale = 100.0\n"
                                                  "[[stages]]\nname = \"b\"\nsteps = 5\n");
  ASSERT_EQ(staged.stages.size(), 2u);
  EXPECT_EQ(staged.run.massScale, 4.0);
  EXPECT_EQ(staged.stages[0].massScale, 100.0);
  EXPECT_EQ(staged.stages[1].massScale, 0.0);  // the run's
  expectInputError([&] { scene("mass_scale = 0.5\n"); }, {"mass_scale", "0.5", "[1, 10000]"});
  expectInputError([&] { scene("", "[[stages]]\nname = \"a\"\nsteps = 5\nmass_scale = 2e4\n"); },
                   {"mass_scale", "20000", "[1, 10000]"});
  std::filesystem::remove_all(dir);
}

TEST(MdemTimeStepLevers, CheckpointOfAnotherScaleOrFrameIsRefused) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mesochain-levers-" + std::to_string(::getpid()) + ".ckpt")).string();
  Scene s = filament(4);
  s.run.timeStepFraction = 0.5;
  s.run.rotationalInertiaScale = 4.0;
  s.run.massScale = 9.0;
  StageSpec stage;
  stage.name = "a", stage.steps = 5, stage.massScale = 4.0;
  s.stages = {stage};
  Simulation sim(s);
  sim.run(10);
  writeCheckpoint(path, s, sim, {}, {});
  {
    Simulation again(s);
    CheckpointFile(path, s).restore(again);  // the same scales: accepted
    EXPECT_EQ(again.bodies().angularMomentumBody, sim.bodies().angularMomentumBody);
    EXPECT_EQ(again.bodies().mass, sim.bodies().mass);
    EXPECT_EQ(again.bodies().velocity, sim.bodies().velocity);
  }
  Scene other = s;
  other.run.rotationalInertiaScale = 1.0;
  expectInputError([&] { CheckpointFile(path, other); }, {"another scene"});
  other.run.rotationalInertiaScale = 16.0;
  expectInputError([&] { CheckpointFile(path, other); }, {"another scene"});
  Scene frame = s;
  frame.run.bodyFrameCriticalStep = true;
  expectInputError([&] { CheckpointFile(path, frame); }, {"another scene"});
  Scene mass = s;
  mass.run.massScale = 1.0;
  expectInputError([&] { CheckpointFile(path, mass); }, {"another scene"});
  mass = s;
  mass.stages[0].massScale = 16.0;
  expectInputError([&] { CheckpointFile(path, mass); }, {"another scene"});
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mesochain::mdem
