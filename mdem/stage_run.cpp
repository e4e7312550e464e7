#include "mdem/stage_run.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "mdem/contacts/bundle_sizes.hpp"
#include "mdem/contacts/film_statistics.hpp"
#include "mdem/tensile_properties.hpp"

namespace mesochain::mdem {

namespace fs = std::filesystem;

std::vector<StageSpec> stagesOf(const Scene& s) {
  if (!s.stages.empty()) return s.stages;
  StageSpec st;
  st.steps = s.run.steps, st.durationNs = s.run.durationNs, st.stopKineticEnergy = s.run.stopKineticEnergy;
  st.checkEvery = s.run.checkEvery, st.minimumSteps = s.run.minimumSteps;
  st.energiesCsv = s.output.energiesCsv, st.energiesEvery = s.output.energiesEvery, st.plotPng = s.output.plotPng;
  st.tensileStage = s.tensile.enabled;
  st.tensile = s.tensile;  // grips already chosen by loadScene
  return {st};
}

long expectedStageSteps(const StageSpec& st, double h) {
  long n = st.steps > 0 || h <= 0.0 ? st.steps : stepsForDuration(st.durationNs, h);
  if (h <= 0.0) return n;
  double end = -1.0;  // ns from the stage's start
  if (st.tensileStage && st.tensile.finalStrain > 0.0 && st.tensile.strainRate > 0.0)
    end = tensileTimeToStrain(st.tensile, st.tensile.finalStrain);
  if (st.compressionStage && st.compression.strainRate > 0.0) end = st.compression.cycles * cycleDuration(st.compression);
  if (end >= 0.0) n = n > 0 ? std::min(n, stepsForDuration(end, h)) : stepsForDuration(end, h);
  return n;
}

Scene stageScene(const Scene& base, const StageSpec& stage, std::int64_t index, const Bodies& bodies, double time,
                 bool implicit) {
  Scene s = base;
  s.bodies = bodies;
  s.effects.insert(s.effects.end(), stage.addEffects.begin(), stage.addEffects.end());
  if (stage.massScale > 0.0) s.run.massScale = stage.massScale;
  if (implicit && !base.run.startFrom.empty() && s.tensile.enabled) {
    // loadScene gripped the film as built: its grips (the only constraints of grip elements)
    // give way to those of the state the run starts from.
    const auto gripped = [&](const FixedDofs& f) {
      return std::count(s.tensile.leftGrip.begin(), s.tensile.leftGrip.end(), f.element) +
                 std::count(s.tensile.rightGrip.begin(), s.tensile.rightGrip.end(), f.element) > 0;
    };
    s.boundary.fixed.erase(std::remove_if(s.boundary.fixed.begin(), s.boundary.fixed.end(), gripped), s.boundary.fixed.end());
    s.tensile.startTime = time;
    setUpTensile(s);
  } else if (!implicit) {
    s.tensile = stage.tensile;
    if (s.tensile.enabled) {
      s.tensile.startTime = time;
      setUpTensile(s);
    }
    s.compression = stage.compression;
    setUpCompression(s, time, fmt::format("key stages[{}].compression", index));
  }
  return s;
}

StageStart readStageStart(const CheckpointFile& file, const Scene& scene, std::size_t stageCount) {
  BinaryReader pre = file.prelude();
  StageStart s;
  s.index = pre.read<std::int64_t>(), s.time = pre.read<double>(), s.step = pre.read<std::int64_t>();
  if (s.index < 0 || s.index >= static_cast<std::int64_t>(stageCount)) pre.fail("a stage the scene does not have");
  s.bodies = scene.bodies;
  readBodiesFrom(pre, s.bodies);
  return s;
}

std::string StageRun::prepare(const std::string& name) const {
  const fs::path p = dir_ / name;
  std::error_code ec;
  if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
  return p.string();
}

void StageRun::open(BinaryReader* resume) {
  std::int64_t energies = -1, tensile = -1;
  if (resume) energies = resume->read<std::int64_t>(), tensile = resume->read<std::int64_t>();
  if (!spec_.plotPng.empty()) plot_ = std::make_unique<TimeSeriesPlot>(base_.output.probes);
  if (resume) {
    if (resume->read<char>() != (plot_ ? 1 : 0)) resume->fail("a plot section that does not match the stage's plot_png");
    if (plot_) plot_->loadState(*resume);
  }
  if (!spec_.energiesCsv.empty())
    csv_ = std::make_unique<EnergyCsvWriter>(prepare(spec_.energiesCsv), sim_.energies(), base_.output.probes, energies);
  plotEvery_ = std::max(spec_.energiesEvery, spec_.steps / 4000);
  if (scene_.tensile.enabled) {
    tensile_ = std::make_unique<TensileRecorder>(scene_, prepare(scene_.tensile.csv), tensile);
    if (resume) tensile_->loadState(*resume);
  }
  if (scene_.compression.enabled) {
    std::int64_t rows = -1, cycles = -1;
    if (resume) rows = resume->read<std::int64_t>(), cycles = resume->read<std::int64_t>();
    const CompressionSpec& c = scene_.compression;
    compression_ = std::make_unique<CompressionRecorder>(scene_, c.csv.empty() ? "" : prepare(c.csv),
                                                         c.cyclesCsv.empty() ? "" : prepare(c.cyclesCsv), rows, cycles);
    if (resume) compression_->loadState(*resume);
  }
}

void StageRun::saveOutputs(BinaryWriter& out) const {
  out.write<std::int64_t>(csv_ ? csv_->bytes() : -1);
  out.write<std::int64_t>(tensile_ ? tensile_->csvBytes() : -1);
  out.write<char>(plot_ ? 1 : 0);
  if (plot_) plot_->saveState(out);
  if (tensile_) tensile_->saveState(out);
  if (compression_) {
    out.write<std::int64_t>(compression_->csvBytes()), out.write<std::int64_t>(compression_->cyclesBytes());
    compression_->saveState(out);
  }
}

void StageRun::savePrelude(BinaryWriter& out) const {
  out.write(index_);
  out.write(startTime());
  out.write<std::int64_t>(startStep());
  writeBodiesTo(out, startBodies_);
}

void StageRun::record(bool force) {
  const long k = sim_.stepCount() - startStep_;
  const bool series = force || k % spec_.energiesEvery == 0, plotted = plot_ && (force || k % plotEvery_ == 0);
  if (!(series && (csv_ || tensile_ || compression_)) && !plotted) return;
  const EnergyLedger e = sim_.energies();  // once for every output of this step
  if (csv_ && series) csv_->write(sim_.stepCount(), sim_.time(), e, sim_.bodies());
  if (plotted) plot_->record(sim_.time(), e, sim_.bodies());
  if (tensile_ && series) {
    const TensileSample& t = tensile_->record(sim_, e);
    reachedStrain_ = scene_.tensile.finalStrain > 0.0 && t.strain >= scene_.tensile.finalStrain;
  }
  if (compression_ && series) compression_->record(sim_, e);
}

std::string StageRun::status() const {
  std::string line = fmt::format("{}t = {:.4g} ns", spec_.name.empty() ? "" : spec_.name + ": ", sim_.time());
  if (tensile_ && !tensile_->samples().empty()) {
    const TensileSample& t = tensile_->samples().back();
    line += fmt::format(", strain {:.4g}, stress {:.4g} MPa", t.strain, t.stress);
  }
  if (compression_ && !compression_->samples().empty()) {
    const CompressionSample& c = compression_->samples().back();
    line += fmt::format(", cycle {} of {}, strain {:.4g}, pressure {:.4g} MPa", std::min(c.cycle + 1, scene_.compression.cycles),
                        scene_.compression.cycles, c.strain, c.pressure);
  }
  return line;
}

void StageRun::writeRunningPlots() const {
  const std::string note = fmt::format("running: t = {:.5g} ns, step {}", sim_.time(), sim_.stepCount());
  if (plot_ && plot_->samples() > 0) plot_->write(prepare(spec_.plotPng), note);
  if (tensile_ && !tensile_->samples().empty() && !scene_.tensile.png.empty())
    tensile_->writePlot(prepare(scene_.tensile.png), nullptr, note);
  if (compression_ && !compression_->samples().empty() && !scene_.compression.png.empty())
    compression_->writePlot(prepare(scene_.compression.png), note);
}

void StageRun::finish(StageSummary& out) {
  if (plot_) plot_->write(prepare(spec_.plotPng));
  if (tensile_) {
    // Bundle sizes at the stage's start and end, from the positions (bundle_sizes.hpp), with the
    // contact criteria of the samples.
    TensileBundles bundles;
    bundles.contactGap = scene_.tensile.contactGap, bundles.alignedAngle = scene_.tensile.alignedAngle;
    const bool contacts = sim_.contactNeighbourhood() != nullptr;
    if (contacts) {
      Scene at = scene_;
      at.bodies = startBodies_;
      bundles.start = sceneBundleSizes(at, bundles.contactGap, bundles.alignedAngle, scene_.contacts.excludeWithin);
      at.bodies = sim_.bodies();
      bundles.end = sceneBundleSizes(at, bundles.contactGap, bundles.alignedAngle, scene_.contacts.excludeWithin);
    }
    bundles.startStrain = tensile_->samples().front().strain, bundles.endStrain = tensile_->samples().back().strain;
    if (!scene_.tensile.png.empty()) tensile_->writePlot(prepare(scene_.tensile.png), &bundles);
    const TensileSample& last = tensile_->samples().back();
    out.tensile = true, out.finalStrain = last.strain, out.finalStress = last.stress;
    for (const TensileSample& t : tensile_->samples()) out.peakStress = std::max(out.peakStress, t.stress);
    out.initialStress = tensile_->samples().front().stress;
    out.crossSection = scene_.tensile.crossSection, out.gaugeLength = scene_.tensile.gaugeLength;
    out.elastic = fitElasticSlope(tensile_->samples(), 0.0, kElasticStrain);
    out.properties = tensileProperties(tensile_->samples());
    out.tensileCsv = prepare(scene_.tensile.csv);
    out.tensileJson = prepare(scene_.tensile.json);
    writeTensilePropertiesJson(out.tensileJson, out.properties, scene_.tensile.crossSection, scene_.tensile.gaugeLength,
                               scene_.tensile.strainRate, contacts ? &bundles : nullptr);
  }
  if (compression_) {
    const CompressionSpec& c = scene_.compression;
    if (!c.png.empty()) compression_->writePlot(prepare(c.png));
    out.compression = true, out.cycles = compression_->cycles();
    out.plateStiffness = c.stiffness, out.initialPlateGap = c.top0 - c.bottom0, out.plateArea = c.area;
    out.compressionCsv = c.csv.empty() ? "" : prepare(c.csv);
    for (const CompressionSample& s : compression_->samples()) out.peakPressure = std::max(out.peakPressure, s.pressure);
  }
  // The film report of the state a relax or compression stage ends in (film_statistics.hpp).
  if (!spec_.tensileStage && !base_.filmSize.isZero() && !base_.stages.empty()) {
    Scene film = base_;
    film.bodies = sim_.bodies();
    FilmStatisticsOptions fo;
    fo.excludeWithin = base_.contacts.excludeWithin;
    out.film = filmStatistics(film, fo);
    out.filmJson = prepare(spec_.name + "-film.json");
    writeFilmStatisticsJson(*out.film, out.filmJson);
  }
}

}  // namespace mesochain::mdem
