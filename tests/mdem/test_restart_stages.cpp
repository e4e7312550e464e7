// Restart across stages (run.hpp, [[stages]]): relax then pull, multiple time stepping, stages
// given as durations and compression cycles resume bit for bit from a checkpoint at any step;
// stage errors name their key; --profile names every effect's phases. The fixture:
// restart_fixture.hpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/plot/png_io.hpp"
#include "mdem/tensile.hpp"
#include "restart_fixture.hpp"

namespace mesochain::mdem {
namespace {

using namespace restart_testing;

// Stages: relax (with local damping named for that stage only) then pull, in one scene.
std::string stagedScene(long relaxSteps, long pullSteps) {
  std::string text = sceneText(0, 20);
  text.replace(text.find("effects = [\"bonds\", \"vdw_contact\", \"contact_damping\", \"local_damping\"]"),
               std::string("effects = [\"bonds\", \"vdw_contact\", \"contact_damping\", \"local_damping\"]").size(),
               "effects = [\"bonds\", \"vdw_contact\", \"contact_damping\"]");
  text.replace(text.find("steps = 0\n"), 10, "");
  text.replace(text.find("energies_csv = \"energies.csv\"\nenergies_every = 20\nplot_png = \"energies.png\"\n"),
               std::string("energies_csv = \"energies.csv\"\nenergies_every = 20\nplot_png = \"energies.png\"\n").size(), "");
  // The relax stage's local damping charges its work (a column of relax-energies.csv, resumed
  // bit for bit from the checkpoints like the rest).
  text.replace(text.find("alpha = 0.3\n"), 12, "alpha = 0.3\ntrack_work = true\n");
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
  {
    std::ifstream relax(dir_ / "reference" / "relax-energies.csv");
    std::string header;
    std::getline(relax, header);
    EXPECT_NE(header.find("local_damping_dissipated_zJ"), std::string::npos) << header;
  }
  // One PNG per stage without asking: the pull's energies and its tensile plot by default names.
  EXPECT_TRUE(fs::exists(dir_ / "reference" / "pull-energies.png"));
  EXPECT_TRUE(fs::exists(dir_ / "reference" / "pull-tensile.png"));
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
    // Its bundle-size distributions, found from the positions with a cell list, hold the bundles
    // of the CSV's first and last rows, found with the contact neighbour list.
    std::ifstream rows(dir_ / "reference" / "pull-tensile.csv");
    std::vector<std::vector<std::string>> table;
    for (std::string line; std::getline(rows, line);) {
      ASSERT_TRUE(csvParseRecord(line, table.emplace_back())) << line;
    }
    ASSERT_GE(table.size(), 3u);
    const auto column = [&](const std::string& name) {
      const auto it = std::find(table[0].begin(), table[0].end(), name);
      EXPECT_NE(it, table[0].end()) << name;
      return static_cast<std::size_t>(it - table[0].begin());
    };
    const nlohmann::json& b = j["bundle_size_distribution"];
    EXPECT_EQ(b["aligned_angle_deg"].get<double>(), 10.0);
    for (const auto& [when, row] : {std::pair{"stage_start", table[1]}, std::pair{"stage_end", table.back()}}) {
      EXPECT_EQ(b[when]["bundles"].get<int>(), std::stoi(row[column("bundles")])) << when;
      EXPECT_EQ(b[when]["largest_elements"].get<int>(), std::stoi(row[column("largest_bundle_elements")])) << when;
      int bundles = 0;
      for (const auto& c : b[when]["classes"]) bundles += c["bundles"].get<int>();
      EXPECT_EQ(bundles, b[when]["bundles"].get<int>()) << when;
    }
    EXPECT_GT(b["stage_end"]["bundles"].get<int>(), 0);
  }
  // Interrupted inside the relax, just after the boundary's checkpoint, and inside the pull.
  expectStagedResumesMatch(reference, {35L, 90L, 95L, 150L});
}

// A relax stage then a tensile stage in one scene equals two scenes joined by a final state: the
// relax alone writing [output] final_state, the pull alone starting from it ([run] start_from),
// bit for bit; the second scene also resumes from a kill. What is not a final state of this
// film is a clear error naming the file.
TEST_F(Restart, RelaxThenPullEqualsTwoScenesJoinedByTheFinalState) {
  const std::string staged = stagedScene(90, 110);
  std::ofstream(scenePath_) << staged;
  const RunSummary reference = run("staged");
  ASSERT_EQ(reference.stages.size(), 2u);
  const std::size_t second = staged.rfind("[[stages]]");
  const std::size_t first = staged.find("[[stages]]");
  auto write = [&](const std::string& name, std::string text) {
    std::ofstream((dir_ / name).string()) << text;
    return (dir_ / name).string();
  };
  std::string relax = staged.substr(0, second);
  relax.replace(relax.find("[output]\n"), 9, "[output]\nfinal_state = \"relaxed.mdem\"\n");
  const std::string relaxScene = write("relax.toml", relax);
  std::string pull = staged.substr(0, first) + staged.substr(second);
  pull.replace(pull.find("[run]\n"), 6, "[run]\nstart_from = \"relax/relaxed.mdem\"\n");
  const std::string damping = "[local_damping]\nalpha = 0.3\ntrack_work = true\n";
  pull.replace(pull.find(damping), damping.size(), "");  // named by the relax stage only
  const std::string pullScene = write("pull.toml", pull);

  const RunSummary relaxed = runScene(loadScene(relaxScene), (dir_ / "relax").string(), nullptr);
  ASSERT_TRUE(fs::exists(dir_ / "relax" / "relaxed.mdem"));
  EXPECT_FALSE(fs::exists(dir_ / "relax" / "checkpoint.mdem"));  // the run is complete
  EXPECT_EQ(relaxed.steps, 90);
  const RunSummary pulled = runScene(loadScene(pullScene), (dir_ / "pull").string(), nullptr);
  EXPECT_EQ(pulled.startStep, 90);
  EXPECT_EQ(pulled.steps, reference.steps);
  EXPECT_EQ(pulled.time, reference.time);
  for (const char* f : {"pull-energies.csv", "pull-tensile.csv", "pull-tensile.json"})
    EXPECT_EQ(slurp(dir_ / "pull" / f), slurp(dir_ / "staged" / f)) << f;
  EXPECT_EQ(pulled.finalEnergies.total(), reference.finalEnergies.total());
  EXPECT_EQ(pulled.stages.back().peakStress, reference.stages.back().peakStress);

  // The second scene killed inside its pull and resumed: the same outputs.
  RunOptions kill;
  kill.interruptAfter = 150;
  ASSERT_TRUE(runScene(loadScene(pullScene), (dir_ / "pull-killed").string(), nullptr, kill).interrupted);
  RunOptions resume;
  resume.resume = true;
  const RunSummary resumed = runScene(loadScene(pullScene), (dir_ / "pull-killed").string(), nullptr, resume);
  EXPECT_EQ(resumed.startStep, 90);
  for (const char* f : {"pull-energies.csv", "pull-tensile.csv", "pull-tensile.json"})
    EXPECT_EQ(slurp(dir_ / "pull-killed" / f), slurp(dir_ / "staged" / f)) << f;

  // A scene without [[stages]] ([run] steps, [tensile]) chooses its grips where it starts: its
  // strain starts at 0 in the relaxed film (loadScene's grips, on the film as generated, would not).
  std::string single = sceneText(40, 0);
  single.replace(single.find("[run]\n"), 6, "[run]\nstart_from = \"relax/relaxed.mdem\"\n");
  const RunSummary direct = runScene(loadScene(write("single.toml", single)), (dir_ / "single").string(), nullptr);
  EXPECT_EQ(direct.steps, 130);
  std::ifstream csv(dir_ / "single" / "tensile.csv");
  std::string header, row;
  std::getline(csv, header), std::getline(csv, row);
  EXPECT_EQ(row.substr(0, row.find(',', row.find(',') + 1) + 1), fmt::format("{:.10g},0,", reference.stages[0].time)) << row;

  // A scene continuing from its own final state in its own folder (relax once more): the fresh
  // run reads the file before it clears its outputs.
  std::string again = relax;
  again.replace(again.find("[run]\n"), 6, "[run]\nstart_from = \"relax/relaxed.mdem\"\n");
  const RunSummary twice = runScene(loadScene(write("again.toml", again)), (dir_ / "relax").string(), nullptr);
  EXPECT_EQ(twice.startStep, 90);
  EXPECT_EQ(twice.steps, 180);
  EXPECT_TRUE(fs::exists(dir_ / "relax" / "relaxed.mdem"));

  // Not a final state: a run's checkpoint (of the killed relax), and the final state of another film.
  kill.interruptAfter = 40;
  ASSERT_TRUE(runScene(loadScene(relaxScene), (dir_ / "relax-killed").string(), nullptr, kill).interrupted);
  std::string otherFilm = relax;
  otherFilm.replace(otherFilm.find("seed = 3"), 8, "seed = 4");
  runScene(loadScene(write("other.toml", otherFilm)), (dir_ / "other").string(), nullptr);
  for (const auto& [from, says] : {std::pair<std::string, std::string>{"relax-killed/checkpoint.mdem", "not the final state"},
                                   {"other/relaxed.mdem", "another film"}}) {
    std::string text = pull;
    text.replace(text.find("relax/relaxed.mdem"), 18, from);
    const Scene s = loadScene(write("bad.toml", text));
    try {
      runScene(s, (dir_ / "bad").string(), nullptr);
      ADD_FAILURE() << from << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(from), std::string::npos) << e.what();
    }
  }
  // A start_from file that does not exist is an error of the scene file naming the key.
  std::string missing = pull;
  missing.replace(missing.find("relax/relaxed.mdem"), 18, "relax/none.mdem");
  expectSceneError(missing, "run.start_from");
}

// A relax stage that stops once the kinetic energy is below a threshold ([[stages]]
// stop_kinetic_energy_zJ, check_every, minimum_steps) stops at the first check, at or after its
// minimum steps, where the energy of the same run without the criterion (its relax-energies.csv,
// a row every 20 steps) is below the threshold; the pull then starts there, and a run killed
// just before or after that stop resumes to the same outputs.
TEST_F(Restart, RelaxStopsAtTheKineticEnergyAndResumesAcrossTheStop) {
  std::ofstream(scenePath_) << stagedScene(1000, 60);
  run("fixed");
  std::ifstream csv(dir_ / "fixed" / "relax-energies.csv");
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line.rfind("step,time_ns,kinetic_translational_zJ,kinetic_rotational_zJ,", 0), 0u) << line;
  std::vector<std::pair<long, double>> kinetic;  // step, total kinetic energy (zJ)
  while (std::getline(csv, line)) {
    std::istringstream row(line);
    std::string step, time, translational, rotational;
    std::getline(row, step, ','), std::getline(row, time, ','), std::getline(row, translational, ','),
        std::getline(row, rotational, ',');
    kinetic.emplace_back(std::stol(step), std::stod(translational) + std::stod(rotational));
  }
  ASSERT_GE(kinetic.size(), 15u);
  // The film zips (its kinetic energy rises to a first peak near step 360, then varies): from
  // step 400 on, a threshold just above the energy at step 720 is first undercut at some check
  // at or before 720.
  const long minimum = 400;
  double threshold = 0.0;
  for (const auto& [step, e] : kinetic)
    if (step == 720) threshold = e * (1.0 + 1e-6);
  ASSERT_GT(threshold, 0.0);
  long expected = -1;
  for (const auto& [step, e] : kinetic)
    if (step >= minimum && e < threshold) {
      expected = step;
      break;
    }
  ASSERT_GT(expected, 0);
  std::printf("the relax stops at step %ld (threshold %.6g zJ)\n", expected, threshold);
  EXPECT_GT(expected, minimum);  // the threshold, not the minimum, decides
  std::string text = stagedScene(1000, 60);
  text.replace(text.find("steps = 1000\n"), 13,
               fmt::format("steps = 1000\nstop_kinetic_energy_zJ = {:.17g}\ncheck_every = 20\nminimum_steps = {}\n",
                           threshold, minimum));
  std::ofstream(scenePath_) << text;
  const RunSummary reference = run("reference");
  ASSERT_EQ(reference.stages.size(), 2u);
  EXPECT_TRUE(reference.stages[0].stoppedByCriterion);
  EXPECT_EQ(reference.stages[0].steps, expected);
  EXPECT_EQ(reference.stages[1].steps, 60);
  EXPECT_EQ(reference.steps, expected + 60);
  expectStagedResumesMatch(reference, {expected - 7, expected, expected + 5});
}

// The performance record (RunSummary::performance, `mesochain dem`'s "performance" lines): one
// entry per stage an invocation advanced, with the steps it advanced there, so that a resumed run
// reports the steps since its resume and a killed one the stage it was in.
TEST_F(Restart, PerformanceCountsTheStepsEachInvocationAdvancedPerStage) {
  std::ofstream(scenePath_) << stagedScene(90, 110);
  const RunSummary reference = run("reference");
  ASSERT_EQ(reference.performance.size(), 2u);
  EXPECT_EQ(reference.performance[0].name, "relax");
  EXPECT_EQ(reference.performance[0].steps, 90);
  EXPECT_EQ(reference.performance[1].name, "pull");
  EXPECT_EQ(reference.performance[1].steps, reference.stages[1].steps);
  for (const StagePerformance& p : reference.performance) {
    EXPECT_GT(p.wallSeconds, 0.0);
    EXPECT_GT(p.timeStep, 0.0);
    EXPECT_GT(p.elementStepsPerSecond(), 0.0);
    EXPECT_NEAR(p.nsPerDay(), 86400.0 * p.steps * p.timeStep / p.wallSeconds, 1e-9 * p.nsPerDay());
  }
  RunOptions kill;
  kill.interruptAfter = 150;  // inside the pull
  const RunSummary killed = run("out", kill);
  ASSERT_TRUE(killed.interrupted);
  ASSERT_EQ(killed.performance.size(), 2u);
  EXPECT_EQ(killed.performance[1].steps, 150 - 90);
  RunOptions resume;
  resume.resume = true;
  const RunSummary resumed = run("out", resume);
  ASSERT_EQ(resumed.performance.size(), 1u);
  EXPECT_EQ(resumed.performance[0].name, "pull");
  EXPECT_EQ(resumed.performance[0].steps, resumed.steps - resumed.resumedFromStep);
  EXPECT_EQ(resumed.performance[0].elements, reference.performance[1].elements);
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

// The progress fraction counts a tensile stage to its final strain, not to its maximum steps:
// the pull ends where the grips' prescribed motion reaches that strain (tensileTimeToStrain, past
// the ramp here: 0.004 > 0.5/ns x 0.01 ns / 2), so the display reaches 100 % when the run ends.
// Before, a pull capped at a million steps ended at 0.05 %.
TEST_F(Restart, ProgressCountsATensileStageToItsFinalStrain) {
  std::string text = stagedScene(90, 1000000);
  text.replace(text.find("final_strain = 0.5"), 18, "final_strain = 0.004");
  std::ofstream(scenePath_) << text;
  std::vector<double> fractions;
  const RunSummary r =
      runScene(loadScene(scenePath_), (dir_ / "out").string(), [&](double f) { fractions.push_back(f); }, {});
  ASSERT_EQ(r.stages.size(), 2u);
  ASSERT_TRUE(r.stages[1].reachedFinalStrain);
  ASSERT_EQ(r.performance.size(), 2u);
  // The measured strain (the grips' mean displacement, sampled every 20 steps) reaches 0.004 at
  // the closed form's step: the integrator moves the grips as tensileTimeToStrain says.
  const TensileSpec& t = loadScene(scenePath_).stages[1].tensile;  // 0.5/ns, ramp 0.01 ns
  const double duration = tensileTimeToStrain(t, 0.004);
  EXPECT_DOUBLE_EQ(duration, 0.004 / t.strainRate + 0.5 * t.ramp);
  const long predicted = stepsForDuration(duration, r.performance[1].timeStep);
  EXPECT_GT(predicted, 100);
  EXPECT_GE(r.stages[1].steps, predicted - 1);
  EXPECT_LE(r.stages[1].steps, predicted + 20);
  ASSERT_FALSE(fractions.empty());
  EXPECT_GT(fractions.back(), 0.97);
  EXPECT_LE(fractions.back(), 1.0);
  // Within the ramp: t^2 rate / (2 ramp).
  EXPECT_DOUBLE_EQ(tensileTimeToStrain(t, 0.001), std::sqrt(2.0 * t.ramp * 0.001 / t.strainRate));
}

// A stage's PNGs are drawn with the checkpoints while it runs (at most once a minute), so a run
// of hours shows its curves before it ends, titled as running; the stage's end replaces them.
TEST_F(Restart, RunningStagesDrawTheirPlotsWithTheCheckpoints) {
  std::ofstream(scenePath_) << stagedScene(90, 110);
  RunOptions kill;
  kill.interruptAfter = 150;  // inside the pull; checkpoints every 20 steps
  ASSERT_TRUE(run("out", kill).interrupted);
  const fs::path out = dir_ / "out";
  // The relax finished: its plot is final. The pull's two plots are those of its first
  // checkpoint (step 100): readable PNGs of ten steps of the pull.
  EXPECT_TRUE(fs::exists(out / "relax.png"));
  for (const char* f : {"pull-energies.png", "pull-tensile.png"}) {
    ASSERT_TRUE(fs::exists(out / f)) << f;
    EXPECT_GT(plot::readPng((out / f).string()).width(), 0) << f;
  }
  const std::string running = slurp(out / "pull-tensile.png");
  RunOptions resume;
  resume.resume = true;
  ASSERT_FALSE(run("out", resume).interrupted);
  // The finished pull's plot replaces it (all its samples, the bundle sizes' panel), and is that
  // of an uninterrupted run.
  EXPECT_NE(slurp(out / "pull-tensile.png"), running);
  ASSERT_FALSE(run("reference").interrupted);
  EXPECT_EQ(slurp(out / "pull-tensile.png"), slurp(dir_ / "reference" / "pull-tensile.png"));
  EXPECT_EQ(slurp(out / "pull-energies.png"), slurp(dir_ / "reference" / "pull-energies.png"));
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
  const auto expectError = [this](const std::string& text, const char* key) { expectSceneError(text, key); };
  const std::string good = stagedScene(10, 10);
  // The good scene with `from` (which it holds) replaced by `to`.
  const auto edited = [&good](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expectError(edited("kind = \"tensile\"", "kind = \"squeeze\""), "stages[1].kind");
  // A tensile table in a compression stage.
  expectError(edited("kind = \"tensile\"", "kind = \"compression\""), "stages[1].tensile");
  expectError(edited("name = \"pull\"", "name = \"relax\""), "stages[1].name");
  expectError(edited("[stages.tensile]", "[unused]"), "stages");
  expectError(good + "[tensile]\ngrip_width_nm = 3.0\nstrain_rate_per_ns = 0.5\n", "tensile");
  expectError(edited("add_effects = [\"local_damping\"]", "add_effects = [\"local_damping\", \"vdw_contact\"]"),
              "stages[0].add_effects");
  expectError(edited("time_step_fraction = 0.7\n", "time_step_fraction = 0.7\nsteps = 5\n"), "run.steps");
  expectError(edited("steps = 10\n", "steps = 10\nduration_ns = 0.01\n"), "stages[0].duration_ns");  // both
  expectError(edited("steps = 10\n", ""), "stages[0].steps");  // neither
  expectError(edited("steps = 10\n", "duration_ns = -1.0\n"), "stages[0].duration_ns");
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
  std::vector<double> fractions;
  const RunSummary reference =
      runScene(loadScene(scenePath_), (dir_ / "reference").string(), [&](double f) { fractions.push_back(f); }, withStatus);
  // The progress counts the squeeze to its last cycle, not to its 400 steps: about 100 % at the
  // end (the cycles end within a sample's 10 steps of their duration's steps).
  ASSERT_FALSE(fractions.empty());
  EXPECT_GT(fractions.back(), 0.97);
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
  const auto expectError = [this](const std::string& text, const char* key) { expectSceneError(text, key); };
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
