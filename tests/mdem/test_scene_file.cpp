// Scene and model files: the example loads and runs with its outputs; every kind of bad input
// is an InputError that names the file and the key.
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {
namespace {

namespace fs = std::filesystem;

class MdemSceneFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("mdem-scene-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write("model.toml", kModel);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // Expects loading + building the simulation to throw an InputError whose message contains
  // every fragment.
  void expectError(const std::string& text, std::initializer_list<const char*> fragments) {
    const std::string path = write("scene.toml", text);
    try {
      const Scene s = loadScene(path);
      Simulation sim(s);
      ADD_FAILURE() << "no InputError for:\n" << text;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      for (const char* f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << msg << " lacks " << f;
    }
  }

  static constexpr const char* kModel = R"(
format = 1
[[element_types]]
name = "brick"
shape = "brick"
thickness_nm = 0.8
width_nm = 2.4
length_nm = 2.0
mass_ag = 0.01
[[bond_types]]
name = "b"
young_modulus_MPa = 1.0e6
shear_modulus_MPa = 0.4e6
)";
  // A valid scene; tests replace pieces of it.
  static constexpr const char* kScene = R"(format = 1
model = "model.toml"
effects = ["bonds", "local_damping"]
[[filaments]]
element_type = "brick"
bond_type = "b"
count = 5
[[fixed]]
element = 0
[[loads]]
element = -1
moment_pN_nm = [0.0, 0.0, 10.0]
[run]
time_step_fraction = 0.5
steps = 50
[output]
energies_csv = "e.csv"
energies_every = 10
xyz = "t.xyz"
vtk_prefix = "vtk/f"
frames_every = 25
probes = [-1]
)";
  static std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  }
  fs::path dir_;
};

TEST_F(MdemSceneFile, ValidSceneRunsAndWritesOutputs) {
  const Scene s = loadScene(write("scene.toml", kScene));
  EXPECT_EQ(s.bodies.size(), 5);
  EXPECT_EQ(s.bonds.size(), 4u);
  const RunSummary r = runScene(s, (dir_ / "out").string(), nullptr);
  EXPECT_EQ(r.steps, 50);
  std::ifstream csv(dir_ / "out" / "e.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_NE(header.find("twisting_zJ"), std::string::npos);
  EXPECT_NE(header.find("p4_rz_rad"), std::string::npos);
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 6);  // steps 0, 10, ..., 50
  std::ifstream xyz(dir_ / "out" / "t.xyz");
  std::getline(xyz, line);
  EXPECT_EQ(line, "5");
  std::getline(xyz, line);
  EXPECT_NE(line.find("orientation:R:4"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "vtk" / "f_000002.vtk"));
}

// [run] duration_ns instead of steps (no stages): the fewest steps that reach it; both or a bad
// value are refused naming the key.
TEST_F(MdemSceneFile, RunGivenAsADurationTakesTheStepsThatReachIt) {
  const RunSummary bySteps = runScene(loadScene(write("scene.toml", kScene)), (dir_ / "steps").string(), nullptr);
  const double h = bySteps.timeStep;
  const Scene s = loadScene(write("scene.toml", replace(kScene, "steps = 50", fmt::format("duration_ns = {:.17g}", 37.2 * h))));
  EXPECT_EQ(s.run.steps, 0);
  const RunSummary r = runScene(s, (dir_ / "out").string(), nullptr);
  EXPECT_EQ(r.steps, 38);
  EXPECT_GE(r.time, 37.2 * h);
  EXPECT_LT(r.time, 38.2 * h);
  expectError(replace(kScene, "steps = 50", "steps = 50\nduration_ns = 1.0"), {"key run.duration_ns", "exactly one of steps"});
  expectError(replace(kScene, "steps = 50", "duration_ns = 0.0"), {"key run.duration_ns"});
}

// stepsForDuration: the fewest whole steps reaching the time; a whole number within rounding.
TEST(MdemStepsForDuration, CountsTheStepsThatReachTheDuration) {
  EXPECT_EQ(stepsForDuration(3 * 0.1, 0.1), 3);     // (3 * 0.1) / 0.1 = 3.0000000000000004, not 4
  EXPECT_EQ(stepsForDuration(0.3, 0.1), 3);         // 0.3 / 0.1 = 2.9999999999999996
  EXPECT_EQ(stepsForDuration(1.05, 0.1), 11);
  EXPECT_EQ(stepsForDuration(6.0, 4.587e-5), 130805);
  EXPECT_EQ(stepsForDuration(1e-9, 1.0), 1);        // at least one step
}

TEST_F(MdemSceneFile, ExampleSceneLoads) {
  const Scene s = loadScene(std::string(MESOCHAIN_SOURCE_DIR) + "/examples/cantilever.toml");
  EXPECT_EQ(s.bodies.size(), 11);
  Simulation sim(s);
  EXPECT_EQ(sim.effectNames(), (std::vector<std::string>{"bonds", "loads", "local_damping"}));
}

TEST_F(MdemSceneFile, UnknownKeysAreNamed) {
  expectError(replace(kScene, "format = 1\n", "format = 1\ncolour = 3\n"), {"scene.toml", "key colour"});
  expectError(replace(kScene, "steps = 50", "steps = 50\nstepz = 3"), {"key run.stepz"});
  expectError(replace(kScene, "count = 5", "count = 5\nlenght_nm = 2"), {"key filaments[0].lenght_nm"});
  expectError(replace(kScene, "\"local_damping\"]", "\"local_damping\", \"contacts\"]"),
              {"key effects", "contacts"});
}

TEST_F(MdemSceneFile, MissingModelFile) {
  expectError(replace(kScene, "model.toml", "nowhere.toml"), {"key model", "nowhere.toml"});
}

TEST_F(MdemSceneFile, NonPositiveDimensionsAndStiffness) {
  write("model.toml", replace(kModel, "thickness_nm = 0.8", "thickness_nm = 0.0"));
  expectError(kScene, {"model.toml", "element_types[0].thickness_nm", "positive"});
  write("model.toml", replace(kModel, "young_modulus_MPa = 1.0e6", "young_modulus_MPa = -1.0e6"));
  expectError(kScene, {"bond_types[0].young_modulus_MPa", "positive"});
  write("model.toml", replace(kModel, "mass_ag = 0.01", "mass_ag = 0"));
  expectError(kScene, {"mass_ag"});
}

TEST_F(MdemSceneFile, TimeStepAboveCritical) {
  expectError(replace(kScene, "time_step_fraction = 0.5", "time_step_ns = 1.0"),
              {"key run.time_step_ns", "critical time step"});
}

TEST_F(MdemSceneFile, BondsToMissingElements) {
  expectError(std::string(kScene) + "[[bonds]]\nelements = [0, 7]\ntype = \"b\"\n",
              {"key bonds[0].elements", "element 7"});
  expectError(replace(kScene, "element = -1", "element = -9"), {"key loads[0].element"});
}

TEST_F(MdemSceneFile, OtherBadInput) {
  expectError("format = 1\neffects = [\n", {"scene.toml", "syntax"});
  expectError(replace(kScene, "format = 1", "format = 2"), {"key format"});
  expectError(replace(kScene, "bond_type = \"b\"", "bond_type = \"c\""), {"bond_type", "\"c\""});
  expectError(replace(kScene, "steps = 50", "steps = 50.5"), {"key run.steps", "integer"});
}

// Each effect reads its own table (mdem/effect_registry.hpp): for every registered effect that
// has one, the table of an effect the scene does not name is refused, naming the table; a
// required table missing for a named effect is refused; an unknown key in it is named.
TEST_F(MdemSceneFile, EveryEffectTableIsReadByItsEffect) {
  const std::string bondsOnly = replace(kScene, "\"bonds\", \"local_damping\"]", "\"bonds\"]");
  int tables = 0;
  for (const EffectRegistration* r : registeredEffects()) {
    if (r->table.name.empty()) continue;
    ++tables;
    ASSERT_TRUE(r->table.read) << r->name;
    expectError(bondsOnly + "[" + r->table.name + "]\n", {("key " + r->table.name).c_str(), "not listed"});
    if (r->table.required)
      expectError(replace(bondsOnly, "\"bonds\"]", "\"bonds\", \"" + r->name + "\"]"),
                  {("key " + r->table.name).c_str()});
  }
  EXPECT_GE(tables, 4);  // local_damping, viscous_damping, vdw_contact, contact_damping
  expectError(std::string(kScene) + "[local_damping]\nalpha = 0.3\nbeta = 1\n", {"local_damping.beta"});
  expectError(std::string(kScene) + "[local_damping]\nalpha = 1.5\n", {"local_damping.alpha", "[0, 1)"});
  // Read when named: the value reaches the scene.
  const Scene s = loadScene(write("scene.toml", std::string(kScene) + "[local_damping]\nalpha = 0.3\n"));
  EXPECT_EQ(s.localDampingAlpha, 0.3);
}

}  // namespace
}  // namespace mesochain::mdem
