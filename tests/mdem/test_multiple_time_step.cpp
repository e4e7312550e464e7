// Multiple time stepping (stepper.hpp, r-RESPA in impulse form): the outer group's force acts as
// an impulse ratio h / 2 at each boundary state.
//  * A constant outer force: the impulse scheme is exact at the boundary states (closed form
//    x0 + v0 t + F t^2 / 2m), and off them it is not (the splitting is really on).
//  * Two tubes in their van der Waals well without damping: the energy error of the split
//    scheme is second order in the outer step (halving h at a fixed ratio quarters it), and
//    bounded (no drift) over many outer steps.
//  * A damped relaxation (local damping, which sees the held outer force) reaches the same
//    equilibrium as the unsplit step.
//  * Thread independence, with runs that end between boundary states.
//  * Input errors name the key.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <filesystem>

#include <omp.h>
#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"

#include "common/errors.hpp"
#include "contact_fixture.hpp"
#include "mdem/contacts/network_generator.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

void expectIdentical(const Bodies& a, const Bodies& b) {
  ASSERT_EQ(a.size(), b.size());
  for (int i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.position[i], b.position[i]) << i;
    ASSERT_EQ(a.velocity[i], b.velocity[i]) << i;
    ASSERT_EQ(a.angularMomentumBody[i], b.angularMomentumBody[i]) << i;
  }
}

TEST(MdemMultipleTimeStep, ConstantOuterForceIsExactAtBoundaryStates) {
  Scene s = tubeScene({});
  s.bodies.add(0, s.elementTypes[0], Vec3::Zero(), Quat());
  s.bodies.velocity[0] = Vec3(3.0, -1.0, 0.5);
  Load load;
  load.element = 0, load.force = Vec3(40.0, 10.0, -25.0);
  s.boundary.loads.push_back(load);
  s.run.timeStep = 1e-4;
  s.run.outerStepRatio = 5;
  s.run.outerEffects = {"loads"};
  Simulation sim(s);
  ASSERT_EQ(sim.outerStepRatio(), 5);
  const double m = s.elementTypes[0].mass;
  double worstOn = 0.0, worstOff = 0.0;
  for (int k = 1; k <= 60; ++k) {
    sim.step();
    const double t = sim.time();
    const Vec3 exact = s.bodies.velocity[0] * t + 0.5 * t * t / m * load.force;
    const double err = (sim.bodies().position[0] - exact).norm();
    (k % 5 == 0 ? worstOn : worstOff) = std::max(k % 5 == 0 ? worstOn : worstOff, err);
  }
  std::printf("constant outer force: error at boundaries %.3g nm, between %.3g nm\n", worstOn, worstOff);
  EXPECT_LT(worstOn, 1e-12);
  EXPECT_GT(worstOff, 1e-6);  // between boundaries the impulse has not been paid out evenly
}

// Two parallel unbonded tubes of 6 elements each, 0.05 nm outside their equilibrium distance,
// each a filament of bonded elements (the inner step), with van der Waals contacts.
Scene wellScene(double timeStep, int ratio) {
  Scene s = tubeScene({"bonds", "vdw_contact"});
  const double d = tubePotential().equilibriumDistance() + 0.05;
  addTube(s, 6, Vec3::Zero(), Vec3::UnitX());
  addTube(s, 6, Vec3(0.3, d, 0.0), Vec3::UnitX());
  s.bodies.velocity[0] = Vec3(0.0, 0.0, 20.0);  // and a bending wave along the first tube
  s.run.timeStep = timeStep;
  s.run.outerStepRatio = ratio;
  return s;
}

// Largest deviation of the total energy from its initial value over `time` ns.
double energyError(const Scene& s, double time) {
  Simulation sim(s);
  const double e0 = sim.energies().total();
  double worst = 0.0;
  const long steps = std::lround(time / sim.timeStep());
  for (long k = 0; k < steps; k += 10) {
    sim.run(10);
    worst = std::max(worst, std::abs(sim.energies().total() - e0));
  }
  return worst;
}

TEST(MdemMultipleTimeStep, EnergyErrorIsSecondOrderInTheOuterStep) {
  const Scene probe = wellScene(1e-5, 4);
  const Simulation sim(probe);
  ASSERT_EQ(sim.outerStepRatio(), 4);
  // Inner step near the bonds' limit; outer step a sizeable part of the contacts' own limit.
  const double h = 0.2 * sim.outerStability().criticalTimeStep / 4;
  ASSERT_LT(h, sim.stability().criticalTimeStep);
  const double time = 0.05;  // ns: many periods of the vdW well and of the bending modes
  const double coarse = energyError(wellScene(h, 4), time);
  const double fine = energyError(wellScene(0.5 * h, 4), time);
  const double unsplit = energyError(wellScene(h, 1), time);
  std::printf("vdW well, ratio 4: energy error %.4g zJ (h %.3g ns), %.4g zJ (h/2); ratio 1: %.4g zJ\n", coarse, h, fine,
              unsplit);
  EXPECT_GT(coarse / fine, 3.0);  // second order: 4
  EXPECT_LT(coarse / fine, 5.5);
  // Bounded: the error over a four times longer run is not four times larger (no drift).
  EXPECT_LT(energyError(wellScene(h, 4), 4 * time), 1.5 * coarse);
}

// A cantilever tube (6 elements, the first clamped) beside a clamped parallel tube, 0.3 nm
// outside the vdW equilibrium distance: the contact pulls the cantilever over, its bonds hold
// it; one equilibrium (no sliding direction).
Scene cantileverScene(int ratio, double alpha) {
  Scene s = tubeScene({"bonds", "vdw_contact", "local_damping"});
  const double d = tubePotential().equilibriumDistance() + 0.3;
  addTube(s, 6, Vec3::Zero(), Vec3::UnitX());
  addTube(s, 6, Vec3(0.0, d, 0.0), Vec3::UnitX());
  for (int i : {0, 1, 2, 3, 4, 5, 6}) {
    FixedDofs f;
    f.element = i;
    f.fixed.fill(true);
    s.boundary.fixed.push_back(f);
  }
  s.run.timeStep = 1e-5;
  s.run.outerStepRatio = ratio;
  s.localDampingAlpha = alpha;
  return s;
}

TEST(MdemMultipleTimeStep, LocalDampingRelaxesToTheUnsplitEquilibrium) {
  // Local damping sees the held outer force: the split relaxation ends where the unsplit one
  // does, to within the impulse's own position offset (about F_outer H^2 / m).
  auto tip = [](int ratio) {
    Simulation sim(cantileverScene(ratio, 0.3));
    sim.run(60000);
    return sim.bodies().position[11];
  };
  const Vec3 start = cantileverScene(1, 0.3).bodies.position[11];
  const Vec3 unsplit = tip(1), split = tip(4);
  const double deflection = (unsplit - start).norm(), difference = (split - unsplit).norm();
  std::printf("cantilever tip: deflection %.5g nm; split (ratio 4) - unsplit %.3g nm\n", deflection, difference);
  EXPECT_GT(deflection, 0.05);
  EXPECT_LT(difference, 1e-4 * deflection);
}

TEST(MdemMultipleTimeStep, ThreadCountDoesNotChangeTheResult) {
  Scene s = dampedNetworkScene();
  s.run.outerStepRatio = 2;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  Simulation one(s);
  one.run(121);
  omp_set_num_threads(2);
  Simulation two(s);
  two.run(61), two.run(7), two.run(53);  // runs that end between boundaries
  omp_set_num_threads(saved);
  EXPECT_EQ(one.outerEffectNames(), std::vector<std::string>{"vdw_contact"});
  expectIdentical(one.bodies(), two.bodies());
  EXPECT_EQ(one.energies()["contact_dissipated"], two.energies()["contact_dissipated"]);
}

TEST(MdemMultipleTimeStep, BadSettingsNameTheKey) {
  auto expectError = [](const Scene& s, const std::string& key) {
    try {
      Simulation sim(s);
      ADD_FAILURE() << "no error for " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  Scene tooLong = wellScene(1e-5, 1000);
  expectError(tooLong, "run.outer_step_ratio");
  Scene bonds = wellScene(1e-5, 2);
  bonds.run.outerEffects = {"bonds"};
  expectError(bonds, "run.outer_effects");
  Scene unknown = wellScene(1e-5, 2);
  unknown.run.outerEffects = {"contact_damping"};  // not named in effects
  expectError(unknown, "run.outer_effects");
  Scene none = tubeScene({"bonds"});
  addTube(none, 4, Vec3::Zero(), Vec3::UnitX());
  none.run.timeStepFraction = 0.5, none.run.outerStepRatio = 2;
  expectError(none, "run.outer_step_ratio");

  // The scene file: a ratio that is neither a whole number nor "auto"; a fraction without auto.
  const std::filesystem::path dir = mesochain::testing::processTempDir("mesochain-mts-keys");
  std::filesystem::create_directories(dir);
  auto fileError = [&](const std::string& run, const std::string& key) {
    const std::string path = (dir / "scene.toml").string();
    std::ofstream(path) << "format = 1\neffects = [\"bonds\"]\n" << kTubeModelToml
                        << "[[filaments]]\nelement_type = \"cnt1010\"\nbond_type = \"cnt\"\ncount = 3\n"
                           "start_nm = [0.0, 0.0, 0.0]\ndirection = [1.0, 0.0, 0.0]\n[run]\n"
                        << run << "\nsteps = 1\n";
    try {
      loadScene(path);
      ADD_FAILURE() << "no error for " << run;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  fileError("time_step_fraction = 0.5\nouter_step_ratio = \"fast\"", "run.outer_step_ratio");
  fileError("time_step_fraction = 0.5\nouter_step_ratio = 0", "run.outer_step_ratio");
  fileError("time_step_fraction = 0.5\nouter_step_ratio = 2\nouter_step_fraction = 0.5", "run.outer_step_fraction");
  fileError("time_step_fraction = 0.5\nouter_effects = [\"vdw_contact\"]", "run.outer_effects");
  std::filesystem::remove_all(dir);
}

TEST(MdemMultipleTimeStep, AutoRatioWithoutRoomFallsBackSafely) {
  // Dashpots in the outer group, strong enough that their step is shorter than the inner one:
  // "auto" finds no ratio above 1 at the inner step. It takes ratio 2 on a shorter inner step
  // when that step is at least the unsplit one; otherwise it does not split, and then the step is
  // that of every effect together (as outer_step_ratio = 1 would give), not the inner group's.
  auto scene = [](double outerFraction) {
    Scene s = tubeScene({"bonds", "vdw_contact", "contact_damping"});
    addTube(s, 6, Vec3::Zero(), Vec3::UnitX());
    addTube(s, 6, Vec3(0.5, 2 * kTubeRadius + 0.34, 0), Vec3::UnitX());
    s.contacts.damping.translational = 2.0;
    s.run.timeStepFraction = 0.5;
    s.run.outerStepRatio = 0;
    s.run.outerStepFraction = outerFraction;
    s.run.outerEffects = {"vdw_contact", "contact_damping"};
    return s;
  };
  Scene unsplitScene = scene(1.0);
  unsplitScene.run.outerStepRatio = 1;
  const Simulation unsplit(unsplitScene);
  ASSERT_EQ(unsplit.outerStepRatio(), 1);

  const Simulation shorter(scene(1.0));
  ASSERT_LT(shorter.outerStability().criticalTimeStep, shorter.stability().criticalTimeStep);  // the premise
  EXPECT_EQ(shorter.outerStepRatio(), 2);
  EXPECT_DOUBLE_EQ(shorter.timeStep(), 0.5 * shorter.outerStability().criticalTimeStep);
  EXPECT_GE(shorter.timeStep(), unsplit.timeStep());
  EXPECT_LT(shorter.timeStep(), 0.5 * shorter.stability().criticalTimeStep);

  const Simulation none(scene(0.2));
  EXPECT_EQ(none.outerStepRatio(), 1);
  EXPECT_TRUE(none.outerEffectNames().empty());
  EXPECT_EQ(none.timeStep(), unsplit.timeStep());
  EXPECT_EQ(none.stability().criticalTimeStep, unsplit.stability().criticalTimeStep);
}

}  // namespace
}  // namespace mesochain::mdem
