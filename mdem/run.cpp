#include "mdem/run.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/append_file.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/output.hpp"
#include "mdem/stage_run.hpp"

namespace mesochain::mdem {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
// The shortest wall time between two sets of a running stage's plots (StageRun::writeRunningPlots).
constexpr int kRunningPlotSeconds = 60;

// VTK frames PREFIX_NNNNNN.vtk of `prefix` (a path), with their frame numbers.
std::vector<std::pair<long, fs::path>> vtkFrames(const std::string& prefix) {
  std::vector<std::pair<long, fs::path>> out;
  const fs::path p(prefix);
  const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return out;
  const std::regex frame(std::regex_replace(p.filename().string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                         R"(_(\d{6,})\.vtk)");
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, frame)) out.emplace_back(std::stol(m[1].str()), e.path());
  }
  return out;
}

}  // namespace

void continueEffectStates(Simulation& sim, const EffectStates& states, const std::string& source) {
  for (const EffectPtr& e : sim.effects())
    for (const auto& [name, bytes] : states)
      if (name == e->name()) {
        BinaryReader in(bytes.data(), bytes.size(), source);
        e->loadState(in);
      }
  sim.refreshForces();
}
EffectStates savedEffectStates(const Simulation& sim) {
  EffectStates states;
  for (const EffectPtr& e : sim.effects()) {
    BinaryWriter out;
    e->saveState(out);
    states.emplace_back(e->name(), out.bytes());
  }
  return states;
}

CheckpointState readCheckpointState(const Scene& scene, const std::string& checkpointPath) {
  const CheckpointFile file(checkpointPath, scene);
  const std::vector<StageSpec> stages = stagesOf(scene);
  const StageStart start = readStageStart(file, scene, stages.size());
  Simulation sim(stageScene(scene, stages[start.index], start.index, start.bodies, start.time, scene.stages.empty()),
                 start.time, start.step);
  file.restore(sim);
  CheckpointState out;
  out.stage = start.index;
  out.bodies = sim.state().bodies;
  out.time = sim.time(), out.step = sim.stepCount();
  return out;
}

std::vector<std::string> outputNames(const Scene& scene) {
  const OutputSpec& o = scene.output;
  std::vector<std::string> names;
  const auto add = [&names](const std::string& n) {
    if (!n.empty() && std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  };
  add(o.xyz), add(o.finalState);
  if (!o.vtkPrefix.empty()) add(o.vtkPrefix + ".pvd");
  for (const StageSpec& st : stagesOf(scene)) {
    add(st.energiesCsv), add(st.plotPng);
    if (st.tensileStage) add(st.tensile.csv), add(st.tensile.json), add(st.tensile.png);
    if (st.compression.enabled) add(st.compression.csv), add(st.compression.cyclesCsv), add(st.compression.png);
    if (!st.tensileStage && !scene.filmSize.isZero() && !scene.stages.empty()) add(st.name + "-film.json");
  }
  return names;
}

void checkRunFolder(const Scene& scene, const std::string& outputDirectory, const RunOptions& options) {
  const fs::path checkpoint = fs::path(outputDirectory) / scene.output.checkpoint;
  std::error_code ec;
  const bool hasCheckpoint = fs::exists(checkpoint, ec);
  if (options.resume && !hasCheckpoint)
    throw InputError(checkpoint.string(), "", "no checkpoint (the run finished, or never wrote one)",
                     "the checkpoint of an interrupted run of this scene to resume");
  if (!options.resume && hasCheckpoint && !options.overwrite)
    throw InputError(checkpoint.string(), "",
                     "the checkpoint of an interrupted run in the output folder " + outputDirectory,
                     "--resume to continue it, --overwrite to start afresh and replace its outputs, or another "
                     "output folder (-o)");
}

RunSummary runScene(const Scene& scene, const std::string& outputDirectory,
                    const std::function<void(double)>& progress, const RunOptions& options) {
  const OutputSpec& o = scene.output;
  const fs::path dir(outputDirectory);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(scene.source, "key output.directory", dir.string(), "a directory that can be created");
  auto prepare = [&](const std::string& name) {
    const fs::path p = dir / name;
    if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
    return p.string();
  };
  const std::string checkpointPath = prepare(o.checkpoint);
  const std::string vtkPrefix = o.vtkPrefix.empty() ? "" : prepare(o.vtkPrefix);
  std::vector<StageSpec> stages = stagesOf(scene);
  const bool implicit = scene.stages.empty();
  // The steps of the run for the progress fraction, counted again at each stage's start: the
  // steps the earlier stages took, and those the stage and the later ones are expected to take
  // (expectedStageSteps) at the stage's own time step (each stage's simulation sets its own; the
  // later stages' are not known yet).
  auto expectedTotal = [&stages](std::size_t current, const StageSpec& currentSpec, double h, long done) {
    long n = done + expectedStageSteps(currentSpec, h);
    for (std::size_t i = current + 1; i < stages.size(); ++i) n += expectedStageSteps(stages[i], h);
    return std::max(1L, n);
  };
  long totalSteps = expectedTotal(0, stages.front(), 0.0, 0);
  RunSummary r;

  // Resume, or start afresh in a folder without an interrupted run (or with --overwrite).
  checkRunFolder(scene, outputDirectory, options);
  // [run] start_from: the first stage starts where another run ended (a resumed run has it in
  // its checkpoint). Read before the fresh run clears its folder, which may hold that file (a
  // scene continuing from its own final state). The steps it had done count toward neither the
  // progress nor this run's.
  std::optional<FinalState> startState;
  if (!options.resume && !scene.run.startFrom.empty()) startState = readFinalState(scene.run.startFrom, scene);
  std::unique_ptr<CheckpointFile> resumed;
  if (options.resume) {
    resumed = std::make_unique<CheckpointFile>(checkpointPath, scene);
  } else {
    // A fresh run replaces what a run of this scene writes, the interrupted run's checkpoint
    // (--overwrite) included: nothing an earlier run left may pass for this run's result.
    for (const std::string& name : outputNames(scene)) {
      const fs::path p = dir / name;
      if (fs::is_regular_file(p, ec)) fs::remove(p, ec), r.removedStale.push_back(p.string());
    }
    if (fs::exists(checkpointPath, ec)) fs::remove(checkpointPath, ec), r.removedStale.push_back(checkpointPath);
  }
  // A kill during an atomic write leaves its temporary file (NAME.tmp.PID, common/atomic_file.cpp)
  // beside the finished file it would have replaced: the next run into the folder removes it.
  static const std::regex temporary(R"(.+\.tmp\.[0-9]+)");
  std::vector<fs::path> leftovers;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->is_regular_file(ec) && std::regex_match(it->path().filename().string(), temporary)) leftovers.push_back(it->path());
  for (const fs::path& p : leftovers) fs::remove(p, ec), r.removedStale.push_back(p.string());

  // Where to start: stage 0 at the scene's state, or the checkpoint's stage.
  std::int64_t stageIndex = 0;
  double stageTime = 0.0;
  long stageStep = 0;
  Bodies stageBodies = scene.bodies;
  std::int64_t xyzBytes = -1, frame = 0;
  if (resumed) {
    StageStart start = readStageStart(*resumed, scene, stages.size());
    stageIndex = start.index, stageTime = start.time, stageStep = start.step, stageBodies = std::move(start.bodies);
  } else if (startState) {
    stageTime = startState->time, stageStep = startState->step, stageBodies = startState->bodies;
  }
  // The step the run started at (the progress fraction counts from it): a resumed run that started
  // from a final state reads that file's step again; if it is gone or changed, the progress
  // display counts from 0 (only the display: the run's state is all in the checkpoint).
  long baseStep = startState ? startState->step : 0;
  if (resumed && !scene.run.startFrom.empty()) try {
      baseStep = readFinalState(scene.run.startFrom, scene).step;
    } catch (const InputError&) {
    }
  r.startStep = baseStep;
  BinaryReader tail = resumed ? resumed->tail() : BinaryReader(nullptr, 0, checkpointPath);
  if (resumed) xyzBytes = tail.read<std::int64_t>(), frame = tail.read<std::int64_t>();
  // Frames of an earlier (longer) run, or written after the checkpoint, would mix with this run's.
  if (!vtkPrefix.empty())
    for (const auto& [index, path] : vtkFrames(vtkPrefix))
      if (index >= frame) fs::remove(path, ec), r.removedStale.push_back(path.string());
  // A tensile stage's properties JSON from an earlier run would look like this run's result.
  for (std::size_t k = static_cast<std::size_t>(stageIndex); k < stages.size(); ++k)
    if (stages[k].tensileStage && !stages[k].tensile.json.empty()) {
      const fs::path json = dir / stages[k].tensile.json;
      if (fs::exists(json, ec)) fs::remove(json, ec), r.removedStale.push_back(json.string());
    }
  if (options.removed && !r.removedStale.empty()) options.removed(r.removedStale);
  std::unique_ptr<AppendFile> xyz;
  if (!o.xyz.empty()) xyz = std::make_unique<AppendFile>(prepare(o.xyz), xyzBytes);
  std::unique_ptr<VtkSeries> series;
  if (!vtkPrefix.empty()) series = std::make_unique<VtkSeries>(vtkPrefix, frame);
  const bool frames = xyz || !vtkPrefix.empty();
  auto writeFrame = [&](const Simulation& sim, const Scene& s) {
    if (xyz) {
      std::ostringstream text;
      writeXyzFrame(text, sim.bodies(), s.elementTypes, sim.time(), sim.stepCount());
      xyz->write(text.str());
    }
    if (!vtkPrefix.empty()) {
      VtkFields fields;
      fields.elementEnergy.assign(sim.bodies().size(), 0.0);
      for (const EffectPtr& e : sim.effects()) {
        e->addElementEnergies(sim.state(), fields.elementEnergy);
        if (e->bondList()) fields.bondLoads = e->bondLoads(sim.state());
      }
      for (int i = 0; i < sim.bodies().size(); ++i) {
        const ElementType& t = s.elementTypes[sim.bodies().type[i]];
        fields.halfExtents.push_back(t.halfExtents());
        fields.shape.push_back(t.shape == Shape::Cylinder ? 1 : 0);
      }
      const std::string framePath = fmt::format("{}_{:06d}.vtk", vtkPrefix, frame);
      writeVtkFrame(framePath, sim.bodies(), sim.bonds(), sim.time(), fields);
      series->add(framePath, sim.time());
    }
    ++frame;
  };

  auto lastCheckpoint = Clock::now();
  const bool byMinutes = o.checkpointMinutes > 0.0;
  auto nextMultiple = [](long k, long n) { return (k / n + 1) * n; };
  long every = std::max(1L, totalSteps / 200);
  std::unique_ptr<StageRun> previous;
  for (; stageIndex < static_cast<std::int64_t>(stages.size()); ++stageIndex) {
    StageSpec& spec = stages[stageIndex];
    auto run = std::make_unique<StageRun>(scene, spec, stageScene(scene, spec, stageIndex, stageBodies, stageTime, implicit), dir,
                                          stageIndex, stageTime, stageStep, stageBodies);
    run->setStart(stageTime, stageStep);
    Simulation& sim = run->sim();
    // A duration becomes steps at the stage's own time step, set from the state the stage starts
    // in, so a resumed run resolves it to the same count.
    if (spec.steps == 0 && spec.durationNs > 0.0) spec.steps = stepsForDuration(spec.durationNs, sim.timeStep());
    {
      StageSpec known = spec;  // with the compression rate its plates set (plate_speed_nm_per_ns)
      if (known.compressionStage) known.compression = run->scene().compression;
      totalSteps = expectedTotal(stageIndex, known, sim.timeStep(), stageStep - baseStep);
      every = std::max(1L, totalSteps / 200);
    }
    if (options.profile) sim.setProfile(&r.profile);
    const bool resumingHere = resumed && !previous;
    if (resumingHere) {
      resumed->restore(sim);
      r.resumedFromStep = sim.stepCount();
      r.resumedFromCommit = resumed->writtenBy();
      if (options.resumedFrom) options.resumedFrom(r.resumedFromCommit);
      if (options.resumedAt) options.resumedAt(std::min(1.0, static_cast<double>(sim.stepCount() - baseStep) / totalSteps));
      run->open(&tail);
    } else {
      if (previous)
        continueEffectStates(sim, savedEffectStates(previous->sim()), "<stage transition>");
      else if (startState)
        continueEffectStates(sim, startState->effects, scene.run.startFrom);
      run->open(nullptr);
    }
    if (r.timeStep == 0.0) {
      r.timeStep = sim.timeStep(), r.criticalTimeStep = sim.stability().criticalTimeStep;
      r.outerStepRatio = sim.outerStepRatio(), r.outerEffects = sim.outerEffectNames();
      r.outerCriticalTimeStep = sim.outerStability().criticalTimeStep;
      r.outerLimitedBy = sim.outerStability().limitedBy;
    }
    if (!resumingHere) {
      run->record(true);
      if (frames && stageIndex == 0) writeFrame(sim, run->scene());
    }
    std::optional<Clock::time_point> lastRunningPlots;  // this stage's
    auto checkpoint = [&] {
      writeCheckpoint(
          checkpointPath, scene, sim, [&](BinaryWriter& out) { run->savePrelude(out); },
          [&](BinaryWriter& out) {
            out.write<std::int64_t>(xyz ? xyz->bytes() : -1);
            out.write<std::int64_t>(frame);
            run->saveOutputs(out);
          });
      lastCheckpoint = Clock::now();
      ++r.checkpoints;
      // The plots of the samples so far, at most once a minute (a checkpoint every few steps
      // would spend its time drawing).
      if (!lastRunningPlots || lastCheckpoint - *lastRunningPlots > std::chrono::seconds(kRunningPlotSeconds)) {
        run->writeRunningPlots();
        lastRunningPlots = Clock::now();
      }
    };
    StageSummary summary;
    summary.name = spec.name;
    StagePerformance performance{spec.name, 0, 0.0, sim.timeStep(), static_cast<long>(sim.bodies().size())};
    const long firstStepHere = sim.stepCount();
    const long end = stageStep + spec.steps;
    const bool stopCheck = spec.stopKineticEnergy > 0.0;
    while (sim.stepCount() < end) {
      // Advance to the next step that records, checks, checkpoints or reports, in one run (one
      // OpenMP region); the split does not change the arithmetic (stepper.hpp).
      const long k0 = sim.stepCount(), local = k0 - stageStep;
      long next = end;
      if (run->recordsEvery()) next = std::min(next, stageStep + nextMultiple(local, spec.energiesEvery));
      if (frames) next = std::min(next, nextMultiple(k0, o.framesEvery));
      if (stopCheck) next = std::min(next, stageStep + nextMultiple(local, spec.checkEvery));
      if (progress) next = std::min(next, nextMultiple(k0, every));
      if (o.checkpointEvery > 0) next = std::min(next, nextMultiple(k0, o.checkpointEvery));
      if (byMinutes) next = std::min(next, k0 + 1000);  // look at the clock at least every 1000 steps
      if (options.interruptAfter >= 0) next = std::min(next, std::max(k0 + 1, options.interruptAfter));
      if (options.stopRequested) next = std::min(next, k0 + 1000);  // look at the request at least every 1000 steps
      const auto stepping = Clock::now();
      sim.run(next - k0);
      const auto outputs = Clock::now();
      const double steppingSeconds = std::chrono::duration<double>(outputs - stepping).count();
      r.wallSeconds += steppingSeconds, performance.wallSeconds += steppingSeconds;
      const long k = sim.stepCount();
      performance.steps = k - firstStepHere;
      if (options.interruptAfter >= 0 && k >= options.interruptAfter) {
        r.interrupted = true;
        break;
      }
      const bool last = k == end;
      bool stop = false;
      if (stopCheck && k - stageStep >= spec.minimumSteps && (k - stageStep) % spec.checkEvery == 0 &&
          sim.kineticEnergy() < spec.stopKineticEnergy) {
        summary.stoppedByCriterion = true;
        stop = true;
      }
      run->record(last || stop);
      if (run->reachedFinalStrain()) stop = true, summary.reachedFinalStrain = true;
      if (run->cyclesDone()) stop = true, summary.cyclesDone = true;
      if (frames && (k % o.framesEvery == 0 || last || stop)) writeFrame(sim, run->scene());
      const bool due = (o.checkpointEvery > 0 && k % o.checkpointEvery == 0) ||
                       (byMinutes && Clock::now() - lastCheckpoint > std::chrono::duration<double>(60.0 * o.checkpointMinutes));
      if (due && !last && !stop) checkpoint();  // (a finished stage moves on at once)
      if (!last && !stop && options.stopRequested && options.stopRequested->load()) {
        // This step's outputs are written; the checkpoint holds the state they continue from.
        if (!due) checkpoint();
        run->writeRunningPlots();  // the curves up to this step, whenever the last ones were drawn
        r.interrupted = r.stoppedOnRequest = true;
        break;
      }
      if (progress && (k % every == 0 || last || stop)) {
        if (options.status) options.status(run->status());
        progress(std::min(1.0, static_cast<double>(k - baseStep) / totalSteps));
      }
      const double outputSeconds = std::chrono::duration<double>(Clock::now() - outputs).count();
      r.wallSeconds += outputSeconds, performance.wallSeconds += outputSeconds;
      if (options.profile) r.profile["outputs (energies, samples, frames, checkpoints)"] += outputSeconds;
      if (stop) break;
    }
    summary.steps = sim.stepCount() - stageStep;
    summary.time = sim.time() - stageTime;
    summary.finalEnergies = sim.energies();
    if (performance.steps > 0) r.performance.push_back(performance);
    if (r.interrupted) {
      r.steps = sim.stepCount(), r.time = sim.time(), r.finalEnergies = summary.finalEnergies;
      return r;
    }
    run->finish(summary);
    r.stages.push_back(summary);
    stageTime = sim.time(), stageStep = sim.stepCount(), stageBodies = sim.bodies();
    previous = std::move(run);
  }
  const Simulation& sim = previous->sim();
  r.steps = sim.stepCount();
  r.time = sim.time();
  r.finalEnergies = sim.energies();
  for (const LedgerEntry& e : r.finalEnergies.entries()) r.dissipatedTracked = r.dissipatedTracked || e.kind == EnergyKind::Dissipated;
  const StageSummary& last = r.stages.back();
  r.stoppedByCriterion = last.stoppedByCriterion;
  for (const StageSummary& st : r.stages)
    if (st.tensile) {
      r.tensile = true, r.finalStrain = st.finalStrain, r.finalStress = st.finalStress;
      r.peakStress = st.peakStress, r.initialStress = st.initialStress;
    }
  if (!o.finalState.empty()) writeFinalState(prepare(o.finalState), scene, sim);
  fs::remove(checkpointPath, ec);  // the run is complete: nothing to resume
  return r;
}

}  // namespace mesochain::mdem
