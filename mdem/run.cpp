#include "mdem/run.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/append_file.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/output.hpp"
#include "mdem/tensile.hpp"
#include "mdem/time_series_plot.hpp"

namespace mesochain::mdem {

namespace fs = std::filesystem;

namespace {

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

// The run loop's own checkpoint section.
struct LoopState {
  std::int64_t energiesBytes = -1, tensileBytes = -1, xyzBytes = -1;
  std::int64_t frame = 0;
};

}  // namespace

RunSummary runScene(const Scene& scene, const std::string& outputDirectory,
                    const std::function<void(double)>& progress, const RunOptions& options) {
  Simulation sim(scene);
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
  RunSummary r;

  // Resume, or start afresh in a folder without an interrupted run (or with --overwrite).
  LoopState loop;
  std::unique_ptr<TimeSeriesPlot> plot;
  if (!o.plotPng.empty()) plot = std::make_unique<TimeSeriesPlot>(o.probes);
  std::vector<char> tensileState;
  const bool hasCheckpoint = fs::exists(checkpointPath);
  if (options.resume) {
    if (!hasCheckpoint)
      throw InputError(checkpointPath, "", "no checkpoint (the run finished, or never wrote one)",
                       "the checkpoint of an interrupted run of this scene to resume");
    readCheckpoint(checkpointPath, scene, sim, [&](BinaryReader& in) {
      loop.energiesBytes = in.read<std::int64_t>(), loop.tensileBytes = in.read<std::int64_t>();
      loop.xyzBytes = in.read<std::int64_t>(), loop.frame = in.read<std::int64_t>();
      if (in.read<char>() != (plot ? 1 : 0)) in.fail("a plot section that does not match the scene's [output]");
      if (plot) plot->loadState(in);
      const std::vector<unsigned char> t = in.readVector<unsigned char>("tensile section");
      tensileState.assign(t.begin(), t.end());
    });
    r.resumedFromStep = sim.stepCount();
  } else {
    if (hasCheckpoint && !options.overwrite)
      throw InputError(checkpointPath, "",
                       "the checkpoint of an interrupted run in the output folder " + dir.string(),
                       "--resume to continue it, --overwrite to start afresh and replace its outputs, or another "
                       "output folder (-o)");
    if (hasCheckpoint) fs::remove(checkpointPath, ec), r.removedStale.push_back(checkpointPath);
  }
  // Frames of an earlier (longer) run, or written after the checkpoint, would mix with this run's.
  if (!vtkPrefix.empty())
    for (const auto& [index, path] : vtkFrames(vtkPrefix))
      if (index >= loop.frame) fs::remove(path, ec), r.removedStale.push_back(path.string());

  std::unique_ptr<EnergyCsvWriter> csv;
  if (!o.energiesCsv.empty())
    csv = std::make_unique<EnergyCsvWriter>(prepare(o.energiesCsv), sim.energies(), o.probes, loop.energiesBytes);
  std::unique_ptr<AppendFile> xyz;
  if (!o.xyz.empty()) xyz = std::make_unique<AppendFile>(prepare(o.xyz), loop.xyzBytes);
  // The plot samples every energies_every steps, coarser when that would exceed ~4000 samples.
  const long plotEvery = std::max(o.energiesEvery, scene.run.steps / 4000);
  std::unique_ptr<TensileRecorder> tensile;
  if (scene.tensile.enabled) {
    tensile = std::make_unique<TensileRecorder>(scene, prepare(scene.tensile.csv), loop.tensileBytes);
    if (options.resume) {
      BinaryReader in(reinterpret_cast<const unsigned char*>(tensileState.data()), tensileState.size(), checkpointPath);
      tensile->loadState(in);
    }
  }
  long frame = loop.frame;
  auto record = [&](bool force) {
    const long k = sim.stepCount();
    if (csv && (force || k % o.energiesEvery == 0)) csv->write(k, sim.time(), sim.energies(), sim.bodies());
    if (plot && (force || k % plotEvery == 0)) plot->record(sim.time(), sim.energies(), sim.bodies());
    if (tensile && (force || k % o.energiesEvery == 0)) tensile->record(sim);
    if (force || k % o.framesEvery == 0) {
      if (xyz) {
        std::ostringstream text;
        writeXyzFrame(text, sim.bodies(), scene.elementTypes, sim.time(), k);
        xyz->write(text.str());
      }
      if (!vtkPrefix.empty())
        writeVtkFrame(fmt::format("{}_{:06d}.vtk", vtkPrefix, frame), sim.bodies(), sim.bonds(), sim.time());
      ++frame;
    }
  };
  using Clock = std::chrono::steady_clock;
  auto lastCheckpoint = Clock::now();
  auto checkpoint = [&] {
    writeCheckpoint(checkpointPath, scene, sim, [&](BinaryWriter& out) {
      out.write<std::int64_t>(csv ? csv->bytes() : -1);
      out.write<std::int64_t>(tensile ? tensile->csvBytes() : -1);
      out.write<std::int64_t>(xyz ? xyz->bytes() : -1);
      out.write<std::int64_t>(frame);
      out.write<char>(plot ? 1 : 0);
      if (plot) plot->saveState(out);
      BinaryWriter t;
      if (tensile) tensile->saveState(t);
      out.writeVector(t.bytes());
    });
    lastCheckpoint = Clock::now();
    ++r.checkpoints;
  };

  r.timeStep = sim.timeStep();
  r.criticalTimeStep = sim.stability().criticalTimeStep;
  const EnergyLedger initial = sim.energies();
  for (const LedgerEntry& e : initial.entries()) r.dissipatedTracked = r.dissipatedTracked || e.kind == EnergyKind::Dissipated;
  if (!options.resume) record(true);
  const long every = std::max(1L, scene.run.steps / 200);
  const bool frames = xyz || !vtkPrefix.empty();
  const bool stopCheck = scene.run.stopKineticEnergy > 0.0;
  const bool byMinutes = o.checkpointMinutes > 0.0;
  auto nextMultiple = [](long k, long n) { return (k / n + 1) * n; };
  while (sim.stepCount() < scene.run.steps) {
    // Advance to the next step that records, checks, checkpoints or reports, in one run (one
    // OpenMP region); the split does not change the arithmetic (stepper.hpp).
    const long k0 = sim.stepCount();
    long next = scene.run.steps;
    if (csv || tensile || plot) next = std::min(next, nextMultiple(k0, o.energiesEvery));
    if (frames) next = std::min(next, nextMultiple(k0, o.framesEvery));
    if (stopCheck) next = std::min(next, nextMultiple(k0, scene.run.checkEvery));
    if (progress) next = std::min(next, nextMultiple(k0, every));
    if (o.checkpointEvery > 0) next = std::min(next, nextMultiple(k0, o.checkpointEvery));
    if (byMinutes) next = std::min(next, k0 + 1000);  // look at the clock at least every 1000 steps
    if (options.interruptAfter >= 0) next = std::min(next, std::max(k0 + 1, options.interruptAfter));
    sim.run(next - k0);
    const long k = sim.stepCount();
    if (options.interruptAfter >= 0 && k >= options.interruptAfter) {
      r.interrupted = true;
      break;
    }
    const bool last = k == scene.run.steps;
    if (stopCheck && k >= scene.run.minimumSteps && k % scene.run.checkEvery == 0 &&
        sim.energies().kinetic() < scene.run.stopKineticEnergy) {
      r.stoppedByCriterion = true;
      record(true);
      break;
    }
    record(last);
    const bool due = (o.checkpointEvery > 0 && k % o.checkpointEvery == 0) ||
                     (byMinutes && Clock::now() - lastCheckpoint > std::chrono::duration<double>(60.0 * o.checkpointMinutes));
    if (due && !last) checkpoint();
    if (progress && (k % every == 0 || last)) progress(static_cast<double>(k) / scene.run.steps);
  }
  r.steps = sim.stepCount();
  r.time = sim.time();
  r.finalEnergies = sim.energies();
  if (r.interrupted) return r;
  if (plot) plot->write(prepare(o.plotPng));
  if (tensile) {
    if (!scene.tensile.png.empty()) tensile->writePlot(prepare(scene.tensile.png));
    const TensileSample& lastSample = tensile->samples().back();
    r.tensile = true, r.finalStrain = lastSample.strain, r.finalStress = lastSample.stress;
    for (const TensileSample& t : tensile->samples()) r.peakStress = std::max(r.peakStress, t.stress);
    r.initialStress = tensile->samples().front().stress;
  }
  fs::remove(checkpointPath, ec);  // the run is complete: nothing to resume
  return r;
}

}  // namespace mesochain::mdem
