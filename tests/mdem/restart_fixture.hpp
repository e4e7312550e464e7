#pragma once
// The fixture of the restart tests (test_restart.cpp, test_restart_stages.cpp): a small tensile
// film scene with every effect and output that carries state, a folder per test, and the checks
// that a resumed run's outputs equal the uninterrupted run's byte for byte.
#include <omp.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contact_fixture.hpp"

#include "common/errors.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::mdem::restart_testing {

namespace fs = std::filesystem;

// A small tensile test of a random film (520 elements: above the stepper's one-thread threshold)
// with every effect and output that carries state:
// bonds (twist branches), vdW contacts and dashpots (neighbour list, dissipated work), local
// damping, grips (grip work), the CSVs, XYZ, VTK frames and the plot.
inline std::string sceneText(long steps, long checkpointEvery) {
  return fmt::format(fmt::runtime(R"(format = 1
effects = ["bonds", "vdw_contact", "contact_damping", "local_damping"]
)" + std::string(testing::kTubeModelToml) + R"([network]
element_type = "cnt1010"
bond_type = "cnt"
size_nm = [70.0, 70.0, 6.0]
tube_length_nm = 20.0
tubes = 52
shape = "wavy"
waviness_deg = 8.0
seed = 3
[vdw_contact]
epsilon_meV = 2.84
sigma_nm = 0.34
surface_density_per_nm2 = 38.2
[contact_damping]
translational_pN_ns_per_nm2 = 1.0
rotational_pN_ns = 0.1
[local_damping]
alpha = 0.3
[run]
time_step_fraction = 0.7
steps = {}
[output]
energies_csv = "energies.csv"
energies_every = 20
plot_png = "energies.png"
xyz = "trajectory.xyz"
vtk_prefix = "frames/f"
frames_every = 25
checkpoint_every = {}
checkpoint_minutes = 0
[tensile]
grip_width_nm = 3.0
strain_rate_per_ns = 0.5
ramp_ns = 0.01
csv = "tensile.csv"
)"),
                     steps, checkpointEvery);
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class Restart : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per process and test (ctest runs the tests of this file in parallel processes).
    dir_ = fs::temp_directory_path() /
           fmt::format("mesochain-restart-{}-{}", ::getpid(), ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scenePath_ = (dir_ / "scene.toml").string();
    std::ofstream(scenePath_) << sceneText(kSteps, kEvery);
  }
  void TearDown() override { fs::remove_all(dir_); }

  RunSummary run(const std::string& out, const RunOptions& o = {}) {
    return runScene(loadScene(scenePath_), (dir_ / out).string(), nullptr, o);
  }
  // The outputs a reader compares (the plot is a picture of the same samples).
  void expectSameOutputs(const std::string& a, const std::string& b) {
    for (const char* f : {"energies.csv", "tensile.csv", "trajectory.xyz", "frames/f_000000.vtk", "frames/f_000004.vtk"})
      EXPECT_EQ(slurp(dir_ / a / f), slurp(dir_ / b / f)) << f;
    std::size_t framesA = 0, framesB = 0;
    for (const auto& e : fs::directory_iterator(dir_ / a / "frames")) framesA += e.is_regular_file();
    for (const auto& e : fs::directory_iterator(dir_ / b / "frames")) framesB += e.is_regular_file();
    EXPECT_EQ(framesA, framesB);
  }

  // The staged scene interrupted after each of `kills` steps and resumed ends as `reference`,
  // with byte-identical `files` (default: those of the relax + pull scene); `more` checks
  // anything else of the resumed run.
  void expectStagedResumesMatch(
      const RunSummary& reference, std::initializer_list<long> kills,
      std::vector<std::string> files = {"relax-energies.csv", "pull-energies.csv", "pull-tensile.csv", "trajectory.xyz"},
      const std::function<void(const RunSummary&, long)>& more = {}) {
    for (long at : kills) {
      const std::string out = fmt::format("at{}", at);
      RunOptions kill;
      kill.interruptAfter = at;
      ASSERT_TRUE(run(out, kill).interrupted);
      RunOptions resume;
      resume.resume = true;
      const RunSummary r = run(out, resume);
      EXPECT_EQ(r.steps, reference.steps) << at;
      EXPECT_EQ(r.finalEnergies.total(), reference.finalEnergies.total()) << at;
      EXPECT_EQ(r.finalStress, reference.finalStress) << at;
      if (more) more(r, at);
      for (const std::string& f : files)
        EXPECT_EQ(slurp(dir_ / "reference" / f), slurp(dir_ / out / f)) << f << " interrupted at " << at;
    }
  }

  // The scene file `text` is refused by loadScene with an error naming `key`.
  void expectSceneError(const std::string& text, const char* key) {
    std::ofstream(scenePath_) << text;
    try {
      loadScene(scenePath_);
      ADD_FAILURE() << "accepted, expected an error at " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }

  static constexpr long kSteps = 200, kEvery = 20;
  fs::path dir_;
  std::string scenePath_;
};

}  // namespace mesochain::mdem::restart_testing
