// Restart (checkpoint.hpp, run.hpp): a run interrupted at random steps and resumed from its last
// checkpoint ends in exactly the state of the uninterrupted run, on 1 and 2 threads, with every
// output file (energies and tensile CSVs, XYZ trajectory, VTK frames) byte-identical to the
// uninterrupted run's; corrupt, truncated or foreign checkpoints are clear errors; a fresh run
// into a folder with an interrupted run is refused.
#include <omp.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>

#include <fmt/format.h>
#include <atomic>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "contact_fixture.hpp"

#include "common/errors.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::mdem {
namespace {

namespace fs = std::filesystem;

// A small tensile test of a random film (520 elements: above the stepper's one-thread threshold)
// with every effect and output that carries state:
// bonds (twist branches), vdW contacts and dashpots (neighbour list, dissipated work), local
// damping, grips (grip work), the CSVs, XYZ, VTK frames and the plot.
std::string sceneText(long steps, long checkpointEvery) {
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

std::string slurp(const fs::path& p) {
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

  static constexpr long kSteps = 200, kEvery = 20;
  fs::path dir_;
  std::string scenePath_;
};

TEST_F(Restart, InterruptedRunsResumeBitForBitOnOneAndTwoThreads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const RunSummary reference = run("reference");
  ASSERT_FALSE(reference.interrupted);
  EXPECT_FALSE(fs::exists(dir_ / "reference" / "checkpoint.mdem"));  // a finished run keeps none
  std::mt19937 gen(12345);
  std::uniform_int_distribution<long> at(1, kSteps - 1);
  for (int trial = 0; trial < 10; ++trial) {
    const int threads = 1 + trial % 2;
    omp_set_num_threads(threads);
    const std::string out = fmt::format("trial{}", trial);
    // Kill at one or two random steps, resuming after each (a second kill may land before the
    // next checkpoint: the resume then starts from the same one again).
    RunOptions kill;
    kill.interruptAfter = at(gen);
    const RunSummary first = run(out, kill);
    ASSERT_TRUE(first.interrupted);
    RunOptions resume;
    resume.resume = true;
    if (kill.interruptAfter < kEvery) {  // no checkpoint yet: nothing to resume
      EXPECT_THROW(run(out, resume), InputError);
      RunOptions again;
      again.overwrite = true;
      run(out, again);
    } else {
      if (trial % 3 == 0) {
        resume.interruptAfter = std::min(kSteps - 1, kill.interruptAfter + at(gen) / 4 + 1);
        const RunSummary second = run(out, resume);
        ASSERT_TRUE(second.interrupted);
        resume.interruptAfter = -1;
      }
      const RunSummary last = run(out, resume);
      EXPECT_GE(last.resumedFromStep, kEvery);
      EXPECT_EQ(last.resumedFromStep % kEvery, 0);
      EXPECT_EQ(last.steps, reference.steps);
      EXPECT_EQ(last.time, reference.time);
      EXPECT_EQ(last.finalEnergies.total(), reference.finalEnergies.total()) << "trial " << trial;
      EXPECT_EQ(last.finalEnergies["contact_dissipated"], reference.finalEnergies["contact_dissipated"]);
      EXPECT_EQ(last.finalStress, reference.finalStress);
      EXPECT_EQ(last.peakStress, reference.peakStress);
    }
    expectSameOutputs("reference", out);
  }
  omp_set_num_threads(saved);
}

// readCheckpointState gives the elements as the run had them at its checkpoint's step: the same
// bits as a simulation of the scene stepped there by hand; another scene's checkpoint is refused.
TEST_F(Restart, CheckpointStateIsTheRunsStateAtItsStep) {
  RunOptions kill;
  kill.interruptAfter = 2 * kEvery + 5;  // the last checkpoint is at step 2 kEvery
  ASSERT_TRUE(run("killed", kill).interrupted);
  const Scene scene = loadScene(scenePath_);
  const CheckpointState st = readCheckpointState(scene, (dir_ / "killed" / "checkpoint.mdem").string());
  EXPECT_EQ(st.step, 2 * kEvery);
  EXPECT_EQ(st.stage, 0);
  Simulation sim(scene);
  sim.run(2 * kEvery);
  EXPECT_EQ(st.time, sim.time());
  ASSERT_EQ(st.bodies.size(), sim.bodies().size());
  for (int i = 0; i < sim.bodies().size(); ++i) {
    ASSERT_EQ(st.bodies.position[i], sim.bodies().position[i]) << i;
    ASSERT_EQ(st.bodies.velocity[i], sim.bodies().velocity[i]) << i;
    const Quat &a = st.bodies.orientation[i], &b = sim.bodies().orientation[i];
    ASSERT_TRUE(a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z) << i;
  }
  std::ofstream(scenePath_) << sceneText(kSteps + 1, kEvery);
  EXPECT_THROW(readCheckpointState(loadScene(scenePath_), (dir_ / "killed" / "checkpoint.mdem").string()), InputError);
}

// A stop request (what `mesochain dem` sets on SIGINT / SIGTERM) ends the run at its next step
// boundary with a checkpoint although the scene writes none on its own (checkpoint_every = 0,
// checkpoint_minutes = 0), and --resume continues it to the uninterrupted run's outputs, byte
// for byte. Without a request the same options change nothing.
TEST_F(Restart, AStopRequestWritesACheckpointAndResumesBitForBit) {
  std::ofstream(scenePath_) << sceneText(kSteps, 0);
  std::atomic<bool> flag{false};
  RunOptions watched;
  watched.stopRequested = &flag;
  const RunSummary reference = run("reference", watched);
  ASSERT_FALSE(reference.interrupted);
  EXPECT_FALSE(fs::exists(dir_ / "reference" / "checkpoint.mdem"));
  const RunSummary plain = run("plain");
  EXPECT_EQ(plain.finalEnergies.total(), reference.finalEnergies.total());
  // The request arrives at about a third of the run (from the progress callback, as a signal
  // would arrive between steps).
  const auto progress = [&flag](double fraction) {
    if (fraction > 0.37) flag.store(true);
  };
  const RunSummary stopped = runScene(loadScene(scenePath_), (dir_ / "stopped").string(), progress, watched);
  ASSERT_TRUE(stopped.stoppedOnRequest);
  EXPECT_TRUE(stopped.interrupted);
  EXPECT_GT(stopped.steps, kSteps / 3);
  EXPECT_LT(stopped.steps, kSteps);
  EXPECT_EQ(stopped.checkpoints, 1);
  ASSERT_TRUE(fs::exists(dir_ / "stopped" / "checkpoint.mdem"));
  RunOptions resume;
  resume.resume = true;
  const RunSummary r = run("stopped", resume);
  EXPECT_EQ(r.resumedFromStep, stopped.steps);
  EXPECT_EQ(r.steps, reference.steps);
  EXPECT_EQ(r.finalEnergies.total(), reference.finalEnergies.total());
  EXPECT_EQ(r.finalStress, reference.finalStress);
  expectSameOutputs("reference", "stopped");
}

// A resumed run tells the progress display how much the checkpoint had done (ProgressBar::skip),
// once, so that its ETA extrapolates only the steps run since (`mesochain dem --resume` showed
// "40/100 ETA 1:36" with nine hours to go); a fresh run never calls it.
TEST_F(Restart, ResumeReportsTheStepsTheCheckpointHadDone) {
  RunOptions kill;
  kill.interruptAfter = 3 * kEvery + 5;  // the last checkpoint at step 3 kEvery
  ASSERT_TRUE(run("out", kill).interrupted);
  std::vector<double> resumedAt, progress;
  RunOptions resume;
  resume.resume = true;
  resume.resumedAt = [&](double f) { resumedAt.push_back(f); };
  runScene(loadScene(scenePath_), (dir_ / "out").string(), [&](double f) { progress.push_back(f); }, resume);
  ASSERT_EQ(resumedAt.size(), 1u);
  EXPECT_DOUBLE_EQ(resumedAt[0], static_cast<double>(3 * kEvery) / kSteps);
  ASSERT_FALSE(progress.empty());
  EXPECT_GT(progress.front(), resumedAt[0]);
  EXPECT_EQ(progress.back(), 1.0);
  RunOptions fresh;
  fresh.resumedAt = [&](double f) { resumedAt.push_back(f); };
  run("fresh", fresh);
  EXPECT_EQ(resumedAt.size(), 1u);
}

// The progress display's note: before each progress report, where the run is; after the last
// one, the run's final time, strain and stress as its summary has them.
TEST_F(Restart, StatusLinesTellTheTimeStrainAndStress) {
  std::vector<std::string> status;
  int reports = 0;
  RunOptions o;
  o.status = [&](const std::string& line) { status.push_back(line); };
  const RunSummary r =
      runScene(loadScene(scenePath_), (dir_ / "out").string(), [&](double) { ++reports; }, o);
  ASSERT_GT(reports, 1);
  EXPECT_EQ(static_cast<int>(status.size()), reports);
  EXPECT_EQ(status.back(), fmt::format("t = {:.4g} ns, strain {:.4g}, stress {:.4g} MPa", r.time, r.finalStrain, r.finalStress));
}

TEST_F(Restart, BadCheckpointsAreClearErrors) {
  RunOptions kill;
  kill.interruptAfter = 2 * kEvery + 5;
  run("out", kill);
  const fs::path ck = dir_ / "out" / "checkpoint.mdem";
  ASSERT_TRUE(fs::exists(ck));
  const std::string good = slurp(ck);
  RunOptions resume;
  resume.resume = true;
  auto expectError = [&](const std::string& content, const char* words) {
    std::ofstream(ck, std::ios::binary | std::ios::trunc) << content;
    try {
      run("out", resume);
      ADD_FAILURE() << "no error for " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(ck.filename().string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expectError(good.substr(0, good.size() / 2), "checksum");             // truncated
  std::string flipped = good;
  flipped[flipped.size() / 3] ^= 0x10;
  expectError(flipped, "checksum");                                    // corrupt
  expectError("not a checkpoint at all", "not an mDEM checkpoint");    // foreign file
  // The scene changed since the checkpoint (another seed: another film).
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << good;
  std::string text = sceneText(kSteps, kEvery);
  text.replace(text.find("seed = 3"), 8, "seed = 4");
  std::ofstream(scenePath_) << text;
  expectError(good, "another scene");
}

TEST_F(Restart, FreshRunIntoAnInterruptedRunsFolderIsRefused) {
  RunOptions kill;
  kill.interruptAfter = kEvery + 1;
  run("out", kill);
  try {
    run("out");
    FAIL() << "a fresh run replaced an interrupted one";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
  }
  RunOptions overwrite;
  overwrite.overwrite = true;
  const RunSummary r = run("out", overwrite);
  EXPECT_FALSE(r.removedStale.empty());
  expectSameOutputs("out", "out");
  // Stale frames of a longer earlier run are removed by a shorter rerun.
  std::ofstream(scenePath_) << sceneText(60, kEvery);
  const RunSummary shorter = run("out");
  EXPECT_FALSE(shorter.removedStale.empty());
  EXPECT_FALSE(fs::exists(dir_ / "out" / "frames" / "f_000004.vtk"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "frames" / "f_000002.vtk"));
}

}  // namespace
}  // namespace mesochain::mdem

namespace mesochain::mdem {
namespace {

// Stages: relax (with local damping named for that stage only) then pull, in one scene.
std::string stagedScene(long relaxSteps, long pullSteps) {
  std::string text = sceneText(0, 20);
  text.replace(text.find("effects = [\"bonds\", \"vdw_contact\", \"contact_damping\", \"local_damping\"]"),
               std::string("effects = [\"bonds\", \"vdw_contact\", \"contact_damping\", \"local_damping\"]").size(),
               "effects = [\"bonds\", \"vdw_contact\", \"contact_damping\"]");
  text.replace(text.find("steps = 0\n"), 10, "");
  text.replace(text.find("energies_csv = \"energies.csv\"\nenergies_every = 20\nplot_png = \"energies.png\"\n"),
               std::string("energies_csv = \"energies.csv\"\nenergies_every = 20\nplot_png = \"energies.png\"\n").size(), "");
  const std::size_t tensile = text.find("[tensile]");
  text = text.substr(0, tensile);
  text += fmt::format(R"([[stages]]
name = "relax"
steps = {}
add_effects = ["local_damping"]
energies_every = 20
plot_png = "relax.png"
[[stages]]
name = "pull"
kind = "tensile"
steps = {}
energies_every = 20
[stages.tensile]
grip_width_nm = 3.0
strain_rate_per_ns = 0.5
ramp_ns = 0.01
final_strain = 0.5
)",
                      relaxSteps, pullSteps);
  return text;
}

TEST_F(Restart, StagesResumeBitForBitAcrossTheStageBoundary) {
  std::ofstream(scenePath_) << stagedScene(90, 110);
  const RunSummary reference = run("reference");
  ASSERT_EQ(reference.stages.size(), 2u);
  EXPECT_EQ(reference.stages[0].name, "relax");
  EXPECT_EQ(reference.stages[0].steps, 90);
  EXPECT_TRUE(reference.stages[1].tensile);
  EXPECT_TRUE(fs::exists(dir_ / "reference" / "relax-energies.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "reference" / "pull-tensile.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "reference" / "relax.png"));
  // The pull's strain counts from the grips' places at its start: 0 in its first row.
  std::ifstream csv(dir_ / "reference" / "pull-tensile.csv");
  std::string header, row;
  std::getline(csv, header), std::getline(csv, row);
  EXPECT_EQ(row.substr(row.find(',') + 1, 2), "0,") << row;
  // The pull's properties JSON (tensile_properties.hpp) holds the summary's peak.
  {
    std::ifstream json(dir_ / "reference" / "pull-tensile.json");
    ASSERT_TRUE(json.good());
    const nlohmann::json j = nlohmann::json::parse(json);
    EXPECT_EQ(j["ultimate"]["stress_MPa"].get<double>(), reference.stages[1].peakStress);
    EXPECT_EQ(j["final"]["strain"].get<double>(), reference.stages[1].finalStrain);
    EXPECT_EQ(reference.stages[1].tensileJson, (dir_ / "reference" / "pull-tensile.json").string());
  }
  // Interrupted inside the relax, just after the boundary's checkpoint, and inside the pull.
  expectStagedResumesMatch(reference, {35L, 90L, 95L, 150L});
}

TEST_F(Restart, MultipleTimeStepRunsResumeBitForBitBetweenBoundaries) {
  // vdW contacts every 2 steps; the pull stage starts its outer cycle at step 91, so its
  // checkpoints (100, 140) and the kills (35, 95, 150) fall between boundary states: the held
  // outer forces and the outer cycle come back from the checkpoint.
  std::string text = stagedScene(91, 110);
  text.replace(text.find("time_step_fraction = 0.7\n"), 25, "time_step_fraction = 0.7\nouter_step_ratio = 2\n");
  std::ofstream(scenePath_) << text;
  const RunSummary reference = run("reference");
  ASSERT_EQ(reference.outerStepRatio, 2);
  expectStagedResumesMatch(reference, {35L, 95L, 150L});
}

// duration_ns instead of steps: a stage runs the fewest steps whose time reaches its duration,
// at the stage's own time step (a whole number of steps within rounding is that number), and a
// run given by durations is the run given by those steps, also when it is killed and resumed.
TEST_F(Restart, StagesGivenAsDurationsRunTheStepsOfTheirTimeAndResumeBitForBit) {
  std::ofstream(scenePath_) << stagedScene(90, 110);
  const RunSummary bySteps = run("steps");
  ASSERT_EQ(bySteps.stages.size(), 2u);
  ASSERT_EQ(bySteps.stages[1].steps, 110);  // not ended by final_strain
  const double relaxStep = bySteps.timeStep, pullTime = bySteps.stages[1].time;
  std::string text = stagedScene(90, 110);
  text.replace(text.find("steps = 90\n"), 11, fmt::format("duration_ns = {:.17g}\n", 89.6 * relaxStep));
  text.replace(text.find("steps = 110\n"), 12, fmt::format("duration_ns = {:.17g}\n", pullTime));
  std::ofstream(scenePath_) << text;
  const RunSummary reference = run("reference");
  ASSERT_EQ(reference.stages.size(), 2u);
  EXPECT_EQ(reference.stages[0].steps, 90);
  EXPECT_EQ(reference.stages[1].steps, 110);
  EXPECT_EQ(reference.stages[0].time, bySteps.stages[0].time);
  EXPECT_GE(reference.stages[0].time, 89.6 * relaxStep);
  EXPECT_EQ(reference.finalEnergies.total(), bySteps.finalEnergies.total());
  for (const char* f : {"relax-energies.csv", "pull-energies.csv", "pull-tensile.csv", "trajectory.xyz"})
    EXPECT_EQ(slurp(dir_ / "steps" / f), slurp(dir_ / "reference" / f)) << f;
  expectStagedResumesMatch(reference, {35L, 95L});
}

TEST_F(Restart, StageErrorsNameTheKey) {
  auto expectError = [&](const std::string& text, const char* key) {
    std::ofstream(scenePath_) << text;
    try {
      loadScene(scenePath_);
      ADD_FAILURE() << "accepted, expected an error at " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  const std::string good = stagedScene(10, 10);
  std::string t = good;
  t.replace(t.find("kind = \"tensile\""), 16, "kind = \"squeeze\"");
  expectError(t, "stages[1].kind");
  t = good;
  t.replace(t.find("kind = \"tensile\""), 16, "kind = \"compression\"");
  expectError(t, "stages[1].tensile");  // a tensile table in a compression stage
  t = good;
  t.replace(t.find("name = \"pull\""), 13, "name = \"relax\"");
  expectError(t, "stages[1].name");
  t = good;
  t.replace(t.find("[stages.tensile]"), 16, "[unused]");
  expectError(t, "stages");
  expectError(good + "[tensile]\ngrip_width_nm = 3.0\nstrain_rate_per_ns = 0.5\n", "tensile");
  t = good;
  t.replace(t.find("add_effects = [\"local_damping\"]"), 31, "add_effects = [\"local_damping\", \"vdw_contact\"]");
  expectError(t, "stages[0].add_effects");
  t = good;
  t.replace(t.find("time_step_fraction = 0.7\n"), 25, "time_step_fraction = 0.7\nsteps = 5\n");
  expectError(t, "run.steps");
  t = good;
  t.replace(t.find("steps = 10\n"), 11, "steps = 10\nduration_ns = 0.01\n");
  expectError(t, "stages[0].duration_ns");  // both
  t = good;
  t.replace(t.find("steps = 10\n"), 11, "");
  expectError(t, "stages[0].steps");  // neither
  t = good;
  t.replace(t.find("steps = 10\n"), 11, "duration_ns = -1.0\n");
  expectError(t, "stages[0].duration_ns");
}

}  // namespace
}  // namespace mesochain::mdem

namespace mesochain::mdem {
namespace {

// dem --profile: every effect of the run has its phases, and the timed phases add up to no more
// than the run's wall time.
TEST_F(Restart, ProfileNamesEveryEffectsPhases) {
  RunOptions o;
  o.profile = true;
  const RunSummary r = run("profiled", o);
  double sum = 0.0;
  std::string phases;
  for (const auto& [phase, seconds] : r.profile.seconds) {
    EXPECT_GE(seconds, 0.0) << phase;
    sum += seconds;
    phases += phase + "; ";
  }
  for (const char* e : {"bonds", "vdw_contact", "contact_damping", "local_damping"})
    EXPECT_NE(phases.find(std::string("gather ") + e), std::string::npos) << phases;
  EXPECT_NE(phases.find("items vdw_contact"), std::string::npos) << phases;
  EXPECT_NE(phases.find("prepare vdw_contact"), std::string::npos) << phases;
  EXPECT_NE(phases.find("outputs"), std::string::npos) << phases;
  EXPECT_GT(r.wallSeconds, 0.0);
  EXPECT_LE(sum, 1.01 * r.wallSeconds) << phases;
  // Without --profile nothing is timed.
  EXPECT_TRUE(run("plain").profile.seconds.empty());
}

}  // namespace
}  // namespace mesochain::mdem

namespace mesochain::mdem {
namespace {

// Relax, then two fast compress-recover cycles (plates, compression.hpp) in one scene.
std::string compressionScene() {
  std::string text = stagedScene(60, 0);
  text = text.substr(0, text.find("[[stages]]\nname = \"pull\""));
  text += R"([[stages]]
name = "squeeze"
kind = "compression"
steps = 400
energies_every = 10
[stages.compression]
cycles = 2
max_strain = 0.5
strain_rate_per_ns = 400.0
hold_ns = 0.0002
plot_png = "squeeze.png"
)";
  return text;
}

TEST_F(Restart, CompressionResumesBitForBitMidCycle) {
  std::ofstream(scenePath_) << compressionScene();
  std::vector<std::string> status;  // the progress note (StatusLinesTellTheTimeStrainAndStress)
  RunOptions withStatus;
  withStatus.status = [&](const std::string& line) { status.push_back(line); };
  const RunSummary reference = runScene(loadScene(scenePath_), (dir_ / "reference").string(), [](double) {}, withStatus);
  ASSERT_FALSE(status.empty());
  EXPECT_EQ(status.back().rfind("squeeze: t = ", 0), 0u) << status.back();
  EXPECT_NE(status.back().find(", cycle 2 of 2, strain "), std::string::npos) << status.back();
  ASSERT_EQ(reference.stages.size(), 2u);
  const StageSummary& squeeze = reference.stages[1];
  EXPECT_TRUE(squeeze.compression);
  EXPECT_TRUE(squeeze.cyclesDone);
  ASSERT_EQ(squeeze.cycles.size(), 2u);
  EXPECT_LT(squeeze.steps, 400);  // ended by the protocol, not by the step count
  EXPECT_GT(squeeze.peakPressure, 0.0);
  // The plates reach 50 % and squeeze the film: at the sample of the largest strain its thickness
  // (centre span + 2R) is well below the initial one (the plates are fast here, 400/ns, so the
  // film does not follow them closely; a slow compression is in docs/scene-file.md).
  {
    std::ifstream csv(dir_ / "reference" / "squeeze-compression.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line.rfind("time_ns,cycle,phase,strain,plate_gap_nm,film_thickness_nm,", 0), 0u) << line;
    double largestStrain = 0.0, thicknessThen = 0.0, initial = 0.0;
    int rows = 0;
    while (std::getline(csv, line)) {
      std::vector<double> f;
      for (std::size_t a = 0, b; a <= line.size(); a = b + 1) {
        b = line.find(',', a);
        if (b == std::string::npos) b = line.size();
        const std::string field = line.substr(a, b - a);
        f.push_back(f.size() == 2 ? 0.0 : std::stod(field));  // (the phase)
      }
      ASSERT_GE(f.size(), 6u);
      if (rows++ == 0) initial = f[5];
      if (f[3] > largestStrain) largestStrain = f[3], thicknessThen = f[5];
    }
    EXPECT_GT(rows, 10);
    EXPECT_GT(largestStrain, 0.4);
    EXPECT_LT(thicknessThen, 0.75 * initial);
  }
  // Interrupted in the first cycle's closing, its opening and the second cycle (the relax and
  // the stage boundary: StagesResumeBitForBitAcrossTheStageBoundary).
  expectStagedResumesMatch(reference, {75L, 130L, 175L},
                           {"relax-energies.csv", "squeeze-energies.csv", "squeeze-compression.csv",
                            "squeeze-cycles.csv", "trajectory.xyz"},
                           [&](const RunSummary& r, long at) {
                             ASSERT_EQ(r.stages.back().cycles.size(), 2u) << at;
                             EXPECT_EQ(r.stages.back().cycles[1].density, squeeze.cycles[1].density) << at;
                           });
}

TEST_F(Restart, CompressionErrorsNameTheKey) {
  auto expectError = [&](const std::string& text, const char* key) {
    std::ofstream(scenePath_) << text;
    try {
      loadScene(scenePath_);
      ADD_FAILURE() << "accepted, expected an error at " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  const std::string good = compressionScene();
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expectError(with("max_strain = 0.5", "max_strain = 1.2"), "stages[1].compression.max_strain");
  expectError(with("strain_rate_per_ns = 400.0", "strain_rate_per_ns = 400.0\nplate_speed_nm_per_ns = 3.0"),
              "stages[1].compression.strain_rate_per_ns");
  expectError(with("strain_rate_per_ns = 400.0", ""), "stages[1].compression.strain_rate_per_ns");
  expectError(with("cycles = 2", "cycles = 0"), "stages[1].compression.cycles");
  expectError(with("cycles = 2", "cycles = 2\nspeed = 1"), "speed");
  expectError(with("[stages.compression]", "[stages.tensile]"), "stages[1]");
  // A compression stage's table on a relax stage.
  expectError(with("kind = \"compression\"", "kind = \"relax\""), "stages[1].compression");
}

}  // namespace
}  // namespace mesochain::mdem
