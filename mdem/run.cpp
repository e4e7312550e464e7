#include "mdem/run.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/output.hpp"
#include "mdem/tensile.hpp"
#include "mdem/time_series_plot.hpp"

namespace mesochain::mdem {

RunSummary runScene(const Scene& scene, const std::string& outputDirectory,
                    const std::function<void(double)>& progress) {
  Simulation sim(scene);
  const OutputSpec& o = scene.output;
  const std::filesystem::path dir(outputDirectory);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(scene.source, "key output.directory", dir.string(), "a directory that can be created");
  auto prepare = [&](const std::string& name) {
    const std::filesystem::path p = dir / name;
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
    return p.string();
  };

  std::unique_ptr<EnergyCsvWriter> csv;
  if (!o.energiesCsv.empty()) csv = std::make_unique<EnergyCsvWriter>(prepare(o.energiesCsv), sim.energies(), o.probes);
  std::ofstream xyz;
  if (!o.xyz.empty()) {
    xyz.open(prepare(o.xyz));
    if (!xyz) throw InputError(scene.source, "key output.xyz", o.xyz, "a writable file");
  }
  // The plot samples every energies_every steps, coarser when that would exceed ~4000 samples.
  std::unique_ptr<TimeSeriesPlot> plot;
  if (!o.plotPng.empty()) plot = std::make_unique<TimeSeriesPlot>(o.probes);
  const long plotEvery = std::max(o.energiesEvery, scene.run.steps / 4000);
  std::unique_ptr<TensileRecorder> tensile;
  if (scene.tensile.enabled) tensile = std::make_unique<TensileRecorder>(scene, prepare(scene.tensile.csv));
  const std::string vtkPrefix = o.vtkPrefix.empty() ? "" : prepare(o.vtkPrefix);
  long frame = 0;
  auto record = [&](bool force) {
    const long k = sim.stepCount();
    if (csv && (force || k % o.energiesEvery == 0)) csv->write(k, sim.time(), sim.energies(), sim.bodies());
    if (plot && (force || k % plotEvery == 0)) plot->record(sim.time(), sim.energies(), sim.bodies());
    if (tensile && (force || k % o.energiesEvery == 0)) tensile->record(sim);
    if (force || k % o.framesEvery == 0) {
      if (xyz) writeXyzFrame(xyz, sim.bodies(), scene.elementTypes, sim.time(), k);
      if (!vtkPrefix.empty())
        writeVtkFrame(fmt::format("{}_{:06d}.vtk", vtkPrefix, frame), sim.bodies(), sim.bonds(), sim.time());
      ++frame;
    }
  };

  RunSummary r;
  r.timeStep = sim.timeStep();
  r.criticalTimeStep = sim.stability().criticalTimeStep;
  for (const LedgerEntry& e : sim.energies().entries()) r.dissipatedTracked = r.dissipatedTracked || e.kind == EnergyKind::Dissipated;
  record(true);
  const long every = std::max(1L, scene.run.steps / 200);
  const bool frames = xyz.is_open() || !vtkPrefix.empty();
  const bool stopCheck = scene.run.stopKineticEnergy > 0.0;
  auto nextMultiple = [](long k, long n) { return (k / n + 1) * n; };
  while (sim.stepCount() < scene.run.steps) {
    // Advance to the next step that records, checks or reports, in one run (one OpenMP region).
    const long k0 = sim.stepCount();
    long next = scene.run.steps;
    if (csv || tensile) next = std::min(next, nextMultiple(k0, o.energiesEvery));
    if (frames) next = std::min(next, nextMultiple(k0, o.framesEvery));
    if (stopCheck) next = std::min(next, nextMultiple(k0, scene.run.checkEvery));
    if (progress) next = std::min(next, nextMultiple(k0, every));
    sim.run(next - k0);
    const long k = sim.stepCount();
    const bool last = k == scene.run.steps;
    if (scene.run.stopKineticEnergy > 0.0 && k >= scene.run.minimumSteps &&
        k % scene.run.checkEvery == 0) {
      if (sim.energies().kinetic() < scene.run.stopKineticEnergy) {
        r.stoppedByCriterion = true;
        record(true);
        break;
      }
    }
    record(last);
    if (progress && (k % every == 0 || last)) progress(static_cast<double>(k) / scene.run.steps);
  }
  if (plot) plot->write(prepare(o.plotPng));
  if (tensile) {
    if (!scene.tensile.png.empty()) tensile->writePlot(prepare(scene.tensile.png));
    const TensileSample& last = tensile->samples().back();
    r.tensile = true, r.finalStrain = last.strain, r.finalStress = last.stress;
    for (const TensileSample& t : tensile->samples()) r.peakStress = std::max(r.peakStress, t.stress);
    r.initialStress = tensile->samples().front().stress;
  }
  r.steps = sim.stepCount();
  r.time = sim.time();
  r.finalEnergies = sim.energies();
  return r;
}

}  // namespace mesochain::mdem
