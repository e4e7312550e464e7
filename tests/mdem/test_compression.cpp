// Compression stages (mdem/compression.hpp) and their plates (the "walls" effect,
// mdem/wall_effect.hpp): the protocol's closed form; one tube pressed flat onto a plate
// (E = k L delta^2 / 2 exactly); the default stiffness against the contact potential's own
// curvature; energy balance with moving plates (total - initial + dissipated = plate work); plate
// errors when the scene is read. (A relax + compression scene end to end, resumed mid-cycle, and
// the stage keys' errors: test_restart.cpp.)
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contact_fixture.hpp"

#include "common/errors.hpp"
#include "mdem/compression.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/simulation.hpp"
#include "mdem/wall_effect.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;
namespace fs = std::filesystem;

CompressionSpec protocol() {
  CompressionSpec c;
  c.enabled = true;
  c.cycles = 3, c.maxStrain = 0.6, c.strainRate = 2.0, c.holdTime = 0.1;
  c.bottom0 = -1.0, c.top0 = 9.0, c.startTime = 5.0;
  return c;
}

TEST(MdemCompression, ProtocolIsTheTriangleWaveWithHolds) {
  const CompressionSpec c = protocol();
  // Close in 0.3 ns, open in 0.3 ns, hold 0.1 ns: 0.7 ns per cycle.
  EXPECT_DOUBLE_EQ(cycleDuration(c), 0.7);
  const PlateState before = plateStateAt(c, 4.0);
  EXPECT_EQ(before.strain, 0.0);
  EXPECT_EQ(before.bottom, -1.0);
  const PlateState closing = plateStateAt(c, 5.0 + 0.7 + 0.1);  // cycle 2, 0.1 ns in
  EXPECT_EQ(closing.cycle, 1);
  EXPECT_EQ(closing.phase, PlatePhase::Closing);
  EXPECT_NEAR(closing.strain, 0.2, 1e-12);
  EXPECT_NEAR(closing.bottom, -1.0 + 0.5 * 10.0 * 0.2, 1e-12);
  EXPECT_NEAR(closing.top, 9.0 - 0.5 * 10.0 * 0.2, 1e-12);
  const PlateState opening = plateStateAt(c, 5.0 + 1.4 + 0.45);  // cycle 3, 0.15 ns into opening
  EXPECT_EQ(opening.cycle, 2);
  EXPECT_EQ(opening.phase, PlatePhase::Opening);
  EXPECT_NEAR(opening.strain, 0.6 - 2.0 * 0.15, 1e-12);
  const PlateState holding = plateStateAt(c, 5.0 + 0.65);
  EXPECT_EQ(holding.phase, PlatePhase::Holding);
  EXPECT_EQ(holding.strain, 0.0);
  const PlateState done = plateStateAt(c, 5.0 + 2.1 + 1e-9);
  EXPECT_EQ(done.phase, PlatePhase::Done);
  EXPECT_EQ(done.cycle, 3);
  EXPECT_EQ(done.top, 9.0);
}

// One horizontal element pressed delta into the bottom plate: every quadrature point has the
// same gap, so E = k L delta^2 / 2, F = k L delta up, no torque, and the load on the plate is
// k L delta; tilted about x, the torque is about the in-plane axis t x z only.
TEST(MdemCompression, APressedTubeFeelsTheHarmonicPlate) {
  Scene s = tubeScene({"bonds"});
  addTube(s, 1, Vec3(0.0, 0.0, 0.0), Vec3::UnitX());
  s.compression = protocol();
  s.compression.stiffness = 700.0, s.compression.wallGap = 0.34;
  const double delta = 0.05;
  s.compression.bottom0 = -kTubeRadius - 0.34 + delta, s.compression.top0 = 50.0;
  const WallEffect w(s);
  const WallEffect::ElementWall e = w.element(s.bodies, 0, s.compression.bottom0, s.compression.top0);
  EXPECT_NEAR(e.energy, 0.5 * 700.0 * kSegmentLength * delta * delta, 1e-12);
  EXPECT_NEAR(e.force.z(), 700.0 * kSegmentLength * delta, 1e-10);
  EXPECT_EQ(e.force.x(), 0.0);
  EXPECT_NEAR(e.torque.norm(), 0.0, 1e-12);
  EXPECT_NEAR(e.loadBottom, 700.0 * kSegmentLength * delta, 1e-10);
  EXPECT_EQ(e.loadTop, 0.0);
  // The same element touching nothing: no energy at all (beyond the rest gap).
  const WallEffect::ElementWall free = w.element(s.bodies, 0, s.compression.bottom0 - 2.0 * delta, 50.0);
  EXPECT_EQ(free.energy, 0.0);
  // Tilted by 10 degrees about y: one end lower, a restoring torque about y (t x z = -y for t ~ x).
  s.bodies.orientation[0] = normalized(expMap(Vec3(0.0, 10.0 * units::kPi / 180.0, 0.0)) * s.bodies.orientation[0]);
  const WallEffect::ElementWall tilted = w.element(s.bodies, 0, s.compression.bottom0, s.compression.top0);
  EXPECT_GT(tilted.force.z(), 0.0);
  EXPECT_NEAR(tilted.torque.x(), 0.0, 1e-12);
  EXPECT_NEAR(tilted.torque.z(), 0.0, 1e-12);
  EXPECT_NE(tilted.torque.y(), 0.0);
}

// The default plate stiffness is the curvature of the parallel-tube contact at its minimum: the
// contact potential's own tabulated Phi, differentiated twice by central differences.
TEST(MdemCompression, DefaultStiffnessIsTheContactCurvature) {
  const TubePairPotential& p = tubePotential();
  const double d = p.equilibriumDistance(), h = 1e-3;
  const double curvature = (p.phi(d + h) - 2.0 * p.phi(d) + p.phi(d - h)) / (h * h);
  EXPECT_NEAR(parallelTubeCurvature(carbonLj(), kTubeRadius), curvature, 0.02 * curvature);
  Scene s = tubeScene({"bonds"});
  addTube(s, 2, Vec3::Zero(), Vec3::UnitX());
  s.compression = protocol();
  s.compression.area = 10.0;
  setUpCompression(s, 0.0);
  EXPECT_NEAR(s.compression.stiffness, parallelTubeCurvature(carbonLj(), kTubeRadius), 1e-9);
  // The plates start at the rest gap from the walls: no force at zero strain.
  EXPECT_NEAR(s.compression.bottom0, -kTubeRadius - 0.34, 1e-12);
  EXPECT_NEAR(s.compression.top0, kTubeRadius + 0.34, 1e-12);
}

// A small stack of tubes squeezed once to 40 % and released, without any damping: the stored and
// kinetic energy change by the work of the plates, up to the scheme's error, which is second
// order in the time step (velocity Verlet): halving the step divides the worst mismatch by about
// 4 (measured 4.3 from 0.1 to 0.05 of the critical step, 3.8 from 0.05 to 0.025).
double balanceAt(double fraction, double* workPeakOut);
TEST(MdemCompression, PlateWorkBalancesTheEnergy) {
  double work = 0.0, finer = 0.0;
  const double coarse = balanceAt(0.1, &work), fine = balanceAt(0.05, &finer);
  ASSERT_GT(work, 100.0) << "the plates did little work on the stack";
  std::printf("plate work %.6g zJ; worst balance %.4g zJ (0.1 of the critical step), %.4g zJ (0.05)\n", work, coarse, fine);
  EXPECT_LT(fine, 5e-4 * finer);
  EXPECT_LT(fine, coarse / 3.0) << "not second order";
}

double balanceAt(double fraction, double* workPeakOut) {
  Scene s = tubeScene({"bonds", "vdw_contact"});
  for (int k = 0; k < 4; ++k)
    addTube(s, 6, Vec3(-6.0, -1.0 + 0.7 * k, k * (2.0 * kTubeRadius + 0.34)), Vec3(1.0, 0.2 * (k % 2 ? 1 : -1), 0.0).normalized());
  s.run.timeStepFraction = fraction;
  s.compression.enabled = true;
  s.compression.cycles = 1, s.compression.maxStrain = 0.4, s.compression.strainRate = 20.0, s.compression.area = 100.0;
  setUpCompression(s, 0.0);
  Simulation sim(s);
  const EnergyLedger e0 = sim.energies();
  const auto* walls = dynamic_cast<const WallEffect*>(sim.effect("walls"));
  if (!walls) return 1e300;
  double peak = 0.0, worst = 0.0, workPeak = 0.0;
  const long steps = static_cast<long>(std::ceil(cycleDuration(s.compression) / sim.timeStep()));
  for (long k = 0; k < steps; k += 20) {
    sim.run(20);
    const EnergyLedger e = sim.energies();
    peak = std::max(peak, walls->bottomLoad());
    workPeak = std::max(workPeak, std::abs(walls->plateWork()));
    worst = std::max(worst, std::abs(e.total() - e0.total() - walls->plateWork()));
  }
  if (!(peak > 0.0)) return 1e300;  // the plates never touched the stack
  *workPeakOut = workPeak;
  return worst;
}

}  // namespace
}  // namespace mesochain::mdem

namespace mesochain::mdem {
namespace {

// The plates are checked when the scene is read, not when the stage starts: a scene without a
// [network] film needs area_nm2, one without [vdw_contact] the stiffness.
TEST(MdemCompression, PlateErrorsComeWhenTheSceneIsRead) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mesochain-compression-{}", ::getpid());
  fs::create_directories(dir);
  const std::string path = (dir / "scene.toml").string();
  auto scene = [&](const std::string& extra) {
    std::ofstream(path) << "format = 1\neffects = [\"bonds\"]\n" << testing::kTubeModelToml
                        << "[[filaments]]\nelement_type = \"cnt1010\"\nbond_type = \"cnt\"\ncount = 3\n"
                           "[run]\ntime_step_fraction = 0.5\n"
                           "[[stages]]\nname = \"squeeze\"\nkind = \"compression\"\nsteps = 10\n"
                           "[stages.compression]\nmax_strain = 0.5\nstrain_rate_per_ns = 1.0\n"
                        << extra;
  };
  auto expectError = [&](const char* key) {
    try {
      loadScene(path);
      ADD_FAILURE() << "accepted, expected an error at " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  scene("");
  expectError("stages[0].compression.wall_stiffness_pN_per_nm2");
  scene("wall_stiffness_pN_per_nm2 = 500.0\n");
  expectError("stages[0].compression.area_nm2");
  scene("wall_stiffness_pN_per_nm2 = 500.0\narea_nm2 = 20.0\n");
  const Scene s = loadScene(path);
  ASSERT_EQ(s.stages.size(), 1u);
  EXPECT_TRUE(s.stages[0].compressionStage);
  EXPECT_EQ(s.stages[0].compression.stiffness, 500.0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mesochain::mdem

namespace mesochain::mdem {
namespace {

// The example of docs/benchmarks.md stays a valid scene: relax, six 60 % cycles, rest.
TEST(MdemCompression, ExampleSceneLoads) {
  const Scene s = loadScene(std::string(MESOCHAIN_SOURCE_DIR) + "/examples/buckypaper-compression.toml");
  ASSERT_EQ(s.stages.size(), 3u);
  EXPECT_TRUE(s.stages[1].compressionStage);
  EXPECT_EQ(s.stages[1].compression.cycles, 6);
  EXPECT_EQ(s.stages[1].compression.maxStrain, 0.6);
  EXPECT_EQ(s.bodies.size(), 2397);
}

}  // namespace
}  // namespace mesochain::mdem
