// Restart (checkpoint.hpp, run.hpp): a run interrupted at random steps and resumed from its last
// checkpoint ends in exactly the state of the uninterrupted run, on 1 and 2 threads, with every
// output file (energies and tensile CSVs, XYZ trajectory, VTK frames) byte-identical to the
// uninterrupted run's; a stop request writes a checkpoint and resumes the same way; a checkpoint's
// state is the run's; corrupt, truncated or foreign checkpoints are clear errors; a fresh run
// into a folder with an interrupted run is refused. Stages, profiles and compression cycles:
// test_restart_stages.cpp.
#include <algorithm>
#include <atomic>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/build_info.hpp"
#include "common/errors.hpp"
#include "mdem/checkpoint.hpp"
#include "restart_fixture.hpp"

namespace mesochain::mdem {
namespace {

using namespace restart_testing;

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
  // and the plot of the samples up to the stop (RunningStagesDrawTheirPlotsWithTheCheckpoints).
  EXPECT_TRUE(fs::exists(dir_ / "stopped" / "energies.png"));
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

TEST_F(Restart, CheckpointRecordsTheBuildThatWroteIt) {
  RunOptions kill;
  kill.interruptAfter = kEvery + 5;
  run("out", kill);
  const fs::path ck = dir_ / "out" / "checkpoint.mdem";
  ASSERT_TRUE(fs::exists(ck));
  const Scene scene = loadScene(scenePath_);
  EXPECT_EQ(CheckpointFile(ck.string(), scene).writtenBy(), buildCommit());
  EXPECT_EQ(resumedBuildNote(buildCommit()), "");
  // The same checkpoint as another build wrote it: the commit replaced (same length), the
  // checksum made again. It still resumes, reports that build, and the note names both.
  std::string bytes = slurp(ck);
  const std::string commit = buildCommit();
  const std::size_t at = bytes.find(commit);
  ASSERT_NE(at, std::string::npos);
  const std::string other(commit.size(), 'f');
  bytes.replace(at, commit.size(), other);
  const std::uint64_t sum = fnv1a(bytes.data(), bytes.size() - 8);
  std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << bytes;
  std::string reported;
  RunOptions resume;
  resume.resume = true;
  resume.resumedFrom = [&](const std::string& c) { reported = c; };
  const RunSummary r = run("out", resume);
  EXPECT_EQ(reported, other);
  EXPECT_EQ(r.resumedFromCommit, other);
  const std::string note = resumedBuildNote(other);
  EXPECT_NE(note.find(other), std::string::npos) << note;
  EXPECT_NE(note.find(commit), std::string::npos) << note;
  EXPECT_NE(note.find("bit for bit only on the build that wrote"), std::string::npos) << note;
  // And it continued the same run: the outputs are those of an uninterrupted run.
  run("whole");
  expectSameOutputs("out", "whole");
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

// A fresh rerun into the folder of a finished run removes that run's outputs before its first
// step, and says so through RunOptions::removed: killed early, it leaves no plot or JSON of the
// earlier run that would pass for its own result.
TEST_F(Restart, FreshRerunRemovesTheEarlierRunsOutputsFirst) {
  run("out");
  for (const char* f : {"energies.png", "tensile.csv", "energies.csv", "trajectory.xyz", "frames/f.pvd"})
    ASSERT_TRUE(fs::exists(dir_ / "out" / f)) << f;
  std::ofstream(dir_ / "out" / "notes.txt") << "the user's";
  std::vector<std::string> told;
  int calls = 0;
  RunOptions kill;
  kill.interruptAfter = 10;
  kill.removed = [&](const std::vector<std::string>& files) { told = files, ++calls; };
  const RunSummary r = run("out", kill);
  ASSERT_TRUE(r.interrupted);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(told, r.removedStale);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "energies.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "frames" / "f_000004.vtk"));
  for (const char* f : {"energies.png", "tensile.csv", "energies.csv", "trajectory.xyz"})
    EXPECT_NE(std::find(told.begin(), told.end(), (dir_ / "out" / f).string()), told.end()) << f;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "notes.txt"));  // not an output of this scene
  EXPECT_EQ(outputNames(loadScene(scenePath_)),
            (std::vector<std::string>{"trajectory.xyz", "frames/f.pvd", "energies.csv", "energies.png", "tensile.csv",
                                      "tensile.json"}));
}

// A kill inside an atomic write leaves the temporary file (NAME.tmp.PID) beside the finished
// one; the next run into the folder, resumed or fresh, removes it and says so.
TEST_F(Restart, TemporaryFilesOfAKilledWriteAreRemovedByTheNextRun) {
  RunOptions kill;
  kill.interruptAfter = kEvery + 1;
  run("out", kill);
  const fs::path leftovers[] = {dir_ / "out" / "checkpoint.mdem.tmp.4242", dir_ / "out" / "frames" / "f.pvd.tmp.17"};
  for (const fs::path& p : leftovers) std::ofstream(p) << "half";
  std::ofstream(dir_ / "out" / "notes.tmp.txt") << "the user's";  // not a temporary file's name
  RunOptions resume;
  resume.resume = true;
  const RunSummary r = run("out", resume);
  for (const fs::path& p : leftovers) {
    EXPECT_FALSE(fs::exists(p)) << p;
    EXPECT_NE(std::find(r.removedStale.begin(), r.removedStale.end(), p.string()), r.removedStale.end()) << p;
  }
  EXPECT_TRUE(fs::exists(dir_ / "out" / "notes.tmp.txt"));
  EXPECT_EQ(r.steps, kSteps);
}

}  // namespace
}  // namespace mesochain::mdem
