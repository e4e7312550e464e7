#pragma once
// Runs a loaded scene with its outputs: the loop the `mesochain dem` command drives, with
// checkpoints and resume (checkpoint.hpp, docs/scene-file.md "Restart").
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mdem/compression.hpp"
#include "mdem/contacts/film_statistics.hpp"
#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"
#include "mdem/tensile.hpp"
#include "mdem/tensile_properties.hpp"

namespace mesochain::mdem {

struct RunOptions {
  // Continue the interrupted run whose checkpoint is in the output folder: outputs are cut back
  // to the checkpoint and appended to; the result is bit for bit that of an uninterrupted run.
  bool resume = false;
  // Start afresh although the output folder holds an interrupted run's checkpoint (it and that
  // run's outputs are replaced). Without it such a folder is refused.
  bool overwrite = false;
  // Tests: stop as if killed once this many steps are done (no final outputs, the checkpoint
  // left as it was).
  long interruptAfter = -1;
  // When set (e.g. by a SIGINT / SIGTERM handler), the run stops at the next step boundary it
  // visits (within 1000 steps), writes its checkpoint and returns with stoppedOnRequest: a
  // --resume continues bit for bit. Nothing computed since the last checkpoint is lost.
  const std::atomic<bool>* stopRequested = nullptr;
  // Time the phases of the steps and the outputs (RunSummary::profile).
  bool profile = false;
  // Called once when a run resumes, with the fraction of its steps the checkpoint had done
  // (the `progress` callback's measure), so that a progress display counts them as done but
  // not as timed: its ETA then extrapolates the steps run since the resume.
  std::function<void(double)> resumedAt;
  // Called once when a run resumes, with the commit of the build that wrote the checkpoint
  // (CheckpointFile::writtenBy: "" for format 2), so that a different build can be told.
  std::function<void(const std::string&)> resumedFrom;
  // Called before each `progress` report with one line on where the run is (the stage, its
  // time, and the last tensile or compression sample), for the progress display's note.
  std::function<void(const std::string&)> status;
  // Called once, before the first step, with the files of an earlier run the run has removed
  // (RunSummary::removedStale), so that the message comes before hours of stepping.
  std::function<void(const std::vector<std::string>&)> removed;
};

struct StageSummary {
  std::string name;              // "" for a scene without [[stages]]
  long steps = 0;
  double time = 0.0;             // ns, of the stage
  bool stoppedByCriterion = false;
  bool reachedFinalStrain = false;
  EnergyLedger finalEnergies;
  bool tensile = false;
  double initialStress = 0.0, finalStrain = 0.0, finalStress = 0.0, peakStress = 0.0;  // MPa
  double crossSection = 0.0, gaugeLength = 0.0;  // nm^2, nm
  ElasticFit elastic;            // the slope below 3 % strain (tensile.hpp)
  TensileProperties properties;  // yield, ultimate, failure, toughness (tensile_properties.hpp)
  std::string tensileCsv, tensileJson;
  // Compression stages (compression.hpp): the cycles completed, the largest plate pressure (MPa),
  // the plates' stiffness (pN/nm^2), their gap at zero strain (nm) and area (nm^2).
  bool compression = false, cyclesDone = false;
  std::vector<CycleRecord> cycles;
  double peakPressure = 0.0, plateStiffness = 0.0, initialPlateGap = 0.0, plateArea = 0.0;
  std::string compressionCsv;
  // Relax and compression stages of a [network] film with [[stages]]: the film report of the
  // final state, also written to NAME-film.json.
  std::optional<FilmStatistics> film;
  std::string filmJson;
};

// What one invocation spent on one stage (LAMMPS's "Performance" line): the steps it advanced,
// the wall time of their stepping and outputs, the stage's time step and element count.
struct StagePerformance {
  std::string name;  // "" for a scene without [[stages]]
  long steps = 0;
  double wallSeconds = 0.0;
  double timeStep = 0.0;  // ns
  long elements = 0;
  double elementStepsPerSecond() const { return wallSeconds > 0.0 ? static_cast<double>(elements) * steps / wallSeconds : 0.0; }
  double nsPerDay() const { return wallSeconds > 0.0 ? 86400.0 * steps * timeStep / wallSeconds : 0.0; }
};

struct RunSummary {
  long steps = 0;
  double time = 0.0;             // ns
  bool stoppedByCriterion = false;
  bool interrupted = false;      // RunOptions::interruptAfter reached, or stopped on request
  bool stoppedOnRequest = false; // RunOptions::stopRequested: the checkpoint was written
  long resumedFromStep = -1;     // >= 0: resumed from a checkpoint at this step
  long startStep = 0;            // [run] start_from: the step of the final state it started from
  // Resumed: the commit of the build that wrote the checkpoint ("" for a format-2 checkpoint).
  std::string resumedFromCommit;
  long checkpoints = 0;          // written by this invocation
  std::vector<std::string> removedStale;  // outputs of an earlier run removed before starting
  EnergyLedger finalEnergies;
  std::vector<StageSummary> stages;  // those completed by this invocation
  std::vector<StagePerformance> performance;  // every stage this invocation advanced, the last one also when interrupted
  PhaseTimes profile;                // with RunOptions::profile: seconds per phase, "outputs" included
  double wallSeconds = 0.0;          // of the stepping and outputs
  double timeStep = 0.0;
  double criticalTimeStep = 0.0;
  // Multiple time stepping: outer step / time step (1: none), the outer group, its critical step.
  int outerStepRatio = 1;
  std::vector<std::string> outerEffects;
  double outerCriticalTimeStep = 0.0;
  std::string outerLimitedBy;
  bool dissipatedTracked = false;  // the scene has an effect that dissipates (dashpots)
  bool tensile = false;            // [tensile]: strain and engineering stress (MPa)
  double initialStress = 0.0, finalStrain = 0.0, finalStress = 0.0, peakStress = 0.0;
};

// The state a run's checkpoint holds: every element at the checkpoint's step, the stage it was
// in. For tools that start from a run's state elsewhere (mesochain-bench network --state-from-run:
// the relaxed film of a long run as a benchmark case). `scene` is the run's scene file (the
// checkpoint's fingerprint is checked against it); the stage's simulation is rebuilt as a resumed
// run rebuilds it and restored from the file. InputError naming the file otherwise.
struct CheckpointState {
  Bodies bodies;
  double time = 0.0;  // ns
  long step = 0;
  std::int64_t stage = 0;
};
CheckpointState readCheckpointState(const Scene& scene, const std::string& checkpointPath);

// Each effect's evolving state by name (Effect::saveState bytes), as a checkpoint holds them.
using EffectStates = std::vector<std::pair<std::string, std::vector<unsigned char>>>;
EffectStates savedEffectStates(const Simulation& sim);
// A stage's start from the state another simulation ended in (the stage before, or another
// run's final state): each effect of `sim` continues the state saved under its name (tracked
// twist branches, dissipated work, neighbour lists), the others start afresh; then the forces of
// the start are evaluated anew (Simulation::refreshForces). `source` names the states in errors.
void continueEffectStates(Simulation& sim, const EffectStates& states, const std::string& source);

// The files a run of `scene` writes into its output folder (relative names; the checkpoint and
// the numbered VTK frames aside): a fresh run removes those an earlier run left there.
std::vector<std::string> outputNames(const Scene& scene);

// Throws the InputError a run into `outputDirectory` with `options` meets before it writes
// anything: --resume without a checkpoint there, or a fresh run (without --overwrite) into a
// folder that holds an interrupted run's checkpoint. For callers that write into the folder
// before runScene (mesochain dem's film.json).
void checkRunFolder(const Scene& scene, const std::string& outputDirectory, const RunOptions& options);

// Progress callback receives the fraction of the maximum step count done.
RunSummary runScene(const Scene& scene, const std::string& outputDirectory,
                    const std::function<void(double)>& progress, const RunOptions& options = {});

}  // namespace mesochain::mdem
