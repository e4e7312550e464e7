#pragma once
// The stages of a run (mdem/run.hpp, docs/scene-file.md "stages"): the stage list of a scene, the
// scene each stage runs, where a checkpoint's stage began, and one stage's run with its time
// series, plots and summary (StageRun). runScene drives them; nothing else needs them.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mdem/binary_io.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/compression.hpp"
#include "mdem/output.hpp"
#include "mdem/run.hpp"
#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"
#include "mdem/tensile.hpp"
#include "mdem/time_series_plot.hpp"

namespace mesochain::mdem {

// The stages of a scene: its [[stages]], or one made of [run], [output] and [tensile].
std::vector<StageSpec> stagesOf(const Scene& s);

// The steps a stage is expected to run at time step h, for the progress display: its steps (or
// its duration's; 0 while h is unknown), fewer where its end is known in advance: a tensile stage
// ends at its final strain (the grips' prescribed motion, tensileTimeToStrain), a compression
// stage with its last cycle (its rate known: given, or set from the plates at the stage's start).
// A stage that stops on its kinetic energy counts its maximum.
long expectedStageSteps(const StageSpec& st, double h);

// The scene a stage runs: the scene file's, starting from `bodies` at `time`, with the stage's
// extra effects and, for a tensile stage, its grips chosen from those positions (a scene without
// [[stages]] has its grips from loadScene, unless it starts from another run's final state).
Scene stageScene(const Scene& base, const StageSpec& stage, std::int64_t index, const Bodies& bodies, double time,
                 bool implicit);

// Where a checkpoint's stage began (its prelude, StageRun::savePrelude): the stage's index, the
// time, step and bodies it started from.
struct StageStart {
  std::int64_t index = 0;
  double time = 0.0;
  long step = 0;
  Bodies bodies;
};
StageStart readStageStart(const CheckpointFile& file, const Scene& scene, std::size_t stageCount);

// One stage's run: its simulation and outputs (the energies CSV and plot, the tensile or
// compression recorder), their checkpoint sections, and the stage's summary at its end.
class StageRun {
 public:
  StageRun(const Scene& base, const StageSpec& spec, Scene scene, const std::filesystem::path& dir, std::int64_t stageIndex,
           double startTime, long startStep, const Bodies& startBodies)
      : base_(base), spec_(spec), scene_(std::move(scene)), dir_(dir), index_(stageIndex), startBodies_(startBodies),
        sim_(scene_, startTime, startStep) {}

  Simulation& sim() { return sim_; }
  const Scene& scene() const { return scene_; }
  const StageSpec& spec() const { return spec_; }

  // The path of an output in the run's folder, its folders made.
  std::string prepare(const std::string& name) const;
  // Opens the stage's outputs (new, or cut back to `resume`'s lengths).
  void open(BinaryReader* resume);
  // A checkpoint's sections: the outputs' lengths and the recorders' states (its tail), and
  // where the stage began (its prelude, read back by readStageStart).
  void saveOutputs(BinaryWriter& out) const;
  void savePrelude(BinaryWriter& out) const;
  double startTime() const { return startTime_; }
  long startStep() const { return startStep_; }
  void setStart(double t, long k) { startTime_ = t, startStep_ = k; }
  // The stage's time series at the current step (every `every` steps, or always when forced).
  void record(bool force);
  // One line on where the stage is, for progress displays: "pull: t = 9.143 ns, strain 0.2834,
  // stress 4.238 MPa" (the last recorded tensile or compression sample), "relax: t = 2.5 ns".
  std::string status() const;
  // The stage's PNGs of the samples so far, marked as a run still going (written with the
  // checkpoints: a run of hours shows its curves before it ends; finish() replaces them).
  void writeRunningPlots() const;
  bool recordsEvery() const { return csv_ || tensile_ || plot_ || compression_; }
  bool reachedFinalStrain() const { return reachedStrain_; }
  bool cyclesDone() const { return compression_ && compression_->done(); }
  // The stage's end: its final plots, the tensile properties JSON and bundle sizes, the film
  // report of a relax or compression stage, into `out`.
  void finish(StageSummary& out);

 private:
  const Scene& base_;
  StageSpec spec_;
  Scene scene_;
  std::filesystem::path dir_;
  std::int64_t index_;
  Bodies startBodies_;
  double startTime_ = 0.0;
  long startStep_ = 0;
  Simulation sim_;
  std::unique_ptr<EnergyCsvWriter> csv_;
  std::unique_ptr<TimeSeriesPlot> plot_;
  std::unique_ptr<TensileRecorder> tensile_;
  std::unique_ptr<CompressionRecorder> compression_;
  long plotEvery_ = 1;
  bool reachedStrain_ = false;
};

}  // namespace mesochain::mdem
