// `mesochain dem SCENE.toml`: runs a mesoscopic distinct element scene (docs/scene-file.md).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>

#include <unistd.h>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <omp.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "common/errors.hpp"
#include "common/progress_bar.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/contacts/film_statistics.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::app {

namespace {
// Set by SIGINT / SIGTERM: the run stops at its next step boundary with a checkpoint (a second
// signal ends the process at once, the default action restored by the first).
std::atomic<bool> stopRequested{false};
extern "C" void requestStop(int signal) {
  stopRequested.store(true);
  std::signal(signal, SIG_DFL);
  static const char note[] =
      "\nmesochain: stopping at the next step boundary (within 1000 steps) with a checkpoint; interrupt again to quit "
      "at once\n";
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, note, sizeof note - 1);  // async-signal-safe
}

// The share of the run's wall time in each phase (--profile).
void printProfile(const mdem::RunSummary& r, std::size_t elements) {
  const long stepped = r.steps - std::max(r.startStep, r.resumedFromStep);
  std::cout << fmt::format("profile ({:.4g} s of stepping and outputs, {:.4g} element-steps/s; first thread's share):\n",
                           r.wallSeconds, r.wallSeconds > 0 ? static_cast<double>(elements) * stepped / r.wallSeconds : 0.0);
  double timed = 0.0;
  for (const auto& [phase, sec] : r.profile.seconds) timed += sec;
  const auto share = [&r](double sec) { return r.wallSeconds > 0 ? 100.0 * sec / r.wallSeconds : 0.0; };
  for (const auto& [phase, sec] : r.profile.seconds)
    std::cout << fmt::format("  {:<52s} {:9.4g} s  {:5.1f} %\n", phase, sec, share(sec));
  std::cout << fmt::format("  {:<52s} {:9.4g} s  {:5.1f} %\n", "other (serial loop, progress)", r.wallSeconds - timed,
                           share(r.wallSeconds - timed));
}

// LAMMPS's "Performance" line, per stage this invocation advanced (a resumed run reports the
// steps since its resume).
void printPerformance(const mdem::RunSummary& r) {
  for (const mdem::StagePerformance& p : r.performance)
    std::cout << fmt::format("performance{}: {} steps in {:.4g} s of wall time, {:.4g} element-steps/s, {:.4g} ns/day "
                             "({} elements, step {:.4g} ns, OpenMP threads {})\n",
                             p.name.empty() ? "" : " of stage " + p.name, p.steps, p.wallSeconds, p.elementStepsPerSecond(),
                             p.nsPerDay(), p.elements, p.timeStep, omp_get_max_threads());
}

struct DemOptions {
  std::string scene;
  std::string outputDir;
  bool resume = false;
  bool overwrite = false;
  bool profile = false;
};
}  // namespace

Command makeDemCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<DemOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& app) {
    *sub = app.add_subcommand("dem", "run a mesoscopic distinct element (mDEM) scene");
    (*sub)->add_option("scene", opt->scene, "scene file (TOML, format = 1)")->required();
    (*sub)->add_option("-o,--output-dir", opt->outputDir,
                       "folder for the outputs (default: output.directory of the scene)")
        ->check(nonEmptyPath());
    (*sub)->add_flag("--resume", opt->resume,
                     "continue the interrupted run from the checkpoint in the output folder (bit for bit)");
    (*sub)->add_flag("--profile", opt->profile,
                     "print the share of the run's wall time in each phase (each effect's items and gathers, integration, outputs)");
    (*sub)->add_flag("--overwrite", opt->overwrite,
                     "start afresh although the output folder holds an interrupted run's checkpoint");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    const mdem::Scene scene = mdem::loadScene(opt->scene);
    const std::string dir = opt->outputDir.empty() ? scene.output.directory : opt->outputDir;
    // Made and checked before the run, not found unwritable at the first output.
    prepareOutputFolder(dir, opt->outputDir.empty() ? opt->scene : "<command line>",
                        opt->outputDir.empty() ? "key output.directory" : "option --output-dir");
    if (opt->resume && opt->overwrite)
      throw InputError("<command line>", "options --resume and --overwrite", "both", "at most one of them");
    mdem::RunOptions options;
    options.resume = opt->resume, options.overwrite = opt->overwrite, options.profile = opt->profile;
    // Refused (an interrupted run there, or nothing to resume) before anything is written.
    mdem::checkRunFolder(scene, dir, options);
    // A generated film ([network]): its report, printed and written as film.json before the run.
    std::optional<mdem::FilmStatistics> film;
    if (!scene.filmSize.isZero()) {
      mdem::FilmStatisticsOptions fo;
      fo.excludeWithin = scene.contacts.excludeWithin;
      film = mdem::filmStatistics(scene, fo);
      std::cout << mdem::formatFilmStatistics(*film);
      mdem::writeFilmStatisticsJson(*film, (std::filesystem::path(dir) / "film.json").string());
    }
    // Progress in percent of the steps; off a terminal a plain line per tenth of the run.
    // Its note: where the run is (stage, time, the last strain and stress of a tensile stage).
    ProgressBar bar("dem (% of steps)", 100, 10);
    std::string status;
    const std::function<void(double)> progress = [&bar, &status](double fraction) {
      bar.update(static_cast<int>(std::lround(fraction * 100)), status);
    };
    // The steps done before a resume are not timed here: the ETA extrapolates those run since.
    options.resumedAt = [&bar](double fraction) { bar.skip(static_cast<int>(std::lround(fraction * 100))); };
    options.status = [&status](const std::string& line) { status = line; };
    options.removed = [&dir](const std::vector<std::string>& files) {
      std::cout << fmt::format("removed {} output file(s) of an earlier run in {} (e.g. {})\n", files.size(), dir,
                               files.front())
                << std::flush;
    };
    options.resumedFrom = [](const std::string& commit) {
      if (const std::string note = mdem::resumedBuildNote(commit); !note.empty()) std::cerr << note << "\n";
    };
    options.stopRequested = &stopRequested;
    stopRequested.store(false);
    const auto previousInt = std::signal(SIGINT, requestStop);
    const auto previousTerm = std::signal(SIGTERM, requestStop);
    const mdem::RunSummary r = mdem::runScene(scene, dir, progress, options);
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    bar.finish();
    if (r.stoppedOnRequest) {
      std::cout << fmt::format("stopped on request at step {} (t = {:.6g} ns); the checkpoint {} holds the run: "
                               "the same command with --resume (`mesochain dem {} -o {} --resume`, and any --set "
                               "given) continues it bit for bit\n",
                               r.steps, r.time, (std::filesystem::path(dir) / scene.output.checkpoint).string(),
                               opt->scene, dir);
      printPerformance(r);
      if (opt->profile) printProfile(r, scene.bodies.size());
      return kStoppedAsAsked;
    }
    if (!scene.run.startFrom.empty() && r.resumedFromStep < 0)
      std::cout << fmt::format("started from the final state {} (step {})\n", scene.run.startFrom, r.startStep);
    if (r.resumedFromStep >= 0)
      std::cout << fmt::format("resumed from the checkpoint at step {}{}\n", r.resumedFromStep,
                               mdem::resumedBuildNote(r.resumedFromCommit).empty()
                                   ? ""
                                   : " (written by " + mdem::writingBuild(r.resumedFromCommit) + ")");
    const mdem::EnergyLedger& e = r.finalEnergies;
    std::cout << fmt::format(
        "mdem: {} elements, {} steps of {:.6g} ns (critical {:.6g} ns), t = {:.6g} ns{}\n",
        scene.bodies.size(), r.steps - r.startStep, r.timeStep, r.criticalTimeStep, r.time,
        r.stoppedByCriterion ? ", stopped: kinetic energy below threshold" : "");
    if (r.outerStepRatio > 1)
      std::cout << fmt::format("multiple time stepping: {} every {} steps (outer step {:.6g} ns, critical {:.6g} ns, "
                               "limited by the {})\n",
                               fmt::join(r.outerEffects, ", "), r.outerStepRatio, r.outerStepRatio * r.timeStep,
                               r.outerCriticalTimeStep, r.outerLimitedBy);
    std::string stored, dissipated;
    for (const mdem::LedgerEntry& x : e.entries()) {
      std::string& to = x.kind == mdem::EnergyKind::Dissipated ? dissipated : stored;
      to += fmt::format("{}{} {:.8g}", to.empty() ? "" : ", ", x.name == "vdw" ? "van der Waals" : x.name, x.value);
    }
    std::cout << fmt::format("energies (zJ): {}, total {:.8g}{}; outputs in {}\n", stored, e.total(),
                             dissipated.empty() ? "" : " (dissipated: " + dissipated + ")", dir);
    for (const mdem::StageSummary& st : r.stages) {
      if (!st.name.empty())
        std::cout << fmt::format("stage {}: {} steps, {:.6g} ns{}{}\n", st.name, st.steps, st.time,
                                 st.stoppedByCriterion ? ", stopped: kinetic energy below threshold" : "",
                                 st.reachedFinalStrain ? ", final strain reached" : "");
      if (st.tensile)
        std::cout << fmt::format("tensile: strain {:.6g}, stress {:.6g} MPa (peak {:.6g} MPa, at zero strain {:.6g} MPa), "
                                 "cross-section {:.6g} nm^2, gauge length {:.6g} nm; {}\n",
                                 st.finalStrain, st.finalStress, st.peakStress, st.initialStress, st.crossSection,
                                 st.gaugeLength, st.tensileCsv);
      if (st.compression) {
        std::cout << fmt::format("compression: {} cycle(s) completed{}, plate gap at zero strain {:.6g} nm, plate stiffness "
                                 "{:.6g} pN/nm^2, plate area {:.6g} nm^2, peak pressure {:.6g} MPa; {}\n",
                                 st.cycles.size(), st.cyclesDone ? "" : " (the stage's steps ran out first)",
                                 st.initialPlateGap, st.plateStiffness, st.plateArea, st.peakPressure, st.compressionCsv);
        for (const mdem::CycleRecord& c : st.cycles)
          std::cout << fmt::format("  cycle {}: thickness {:.6g} nm (smallest {:.6g} nm), density {:.6g} g/cm^3, peak pressure "
                                   "{:.6g} MPa\n",
                                   c.cycle, c.thickness, c.smallestThickness, c.density, c.peakPressure);
      }
      if (st.film) std::cout << "film at the end of stage " << st.name << " (" << st.filmJson << "):\n" << mdem::formatFilmStatistics(*st.film);
      if (st.tensile && st.elastic.fitted)
        std::cout << fmt::format("elastic slope (Young's modulus of the specimen) {:.6g} MPa over strain {:.4g} - {:.4g} "
                                 "({} samples, R^2 {:.4f})\n",
                                 st.elastic.slope, st.elastic.from, st.elastic.to, st.elastic.samples, st.elastic.r2);
      else if (st.tensile)
        std::cout << fmt::format("no elastic slope: {} samples below strain {:.3g}{}; a slope needs at least {} spanning half "
                                 "of 0 - {:.3g}\n",
                                 st.elastic.samples, mdem::kElasticStrain,
                                 st.elastic.samples > 0 ? fmt::format(" (strain {:.4g} - {:.4g})", st.elastic.from, st.elastic.to) : "",
                                 mdem::kElasticMinimumSamples, mdem::kElasticStrain);
      if (st.tensile) {
        const mdem::TensileProperties& p = st.properties;
        const auto strainOr = [](double v, const char* none) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : std::string(none); };
        std::cout << fmt::format("ultimate strength {:.6g} MPa at strain {:.4g}; {}; failure strain (stress below {:.0f} % of the "
                                 "ultimate) {}; toughness {:.6g} MJ/m^3 to the last sample{}; {}\n",
                                 p.ultimateStress, p.ultimateStrain,
                                 std::isfinite(p.yieldStrain)
                                     ? fmt::format("{:.1f} % offset yield {:.6g} MPa at strain {:.4g}", 100 * mdem::kYieldOffset,
                                                   p.yieldStress, p.yieldStrain)
                                     : fmt::format("no {:.1f} % offset yield", 100 * mdem::kYieldOffset),
                                 100 * mdem::kFailureFraction, strainOr(p.failureStrain, "not reached"), p.toughness,
                                 std::isfinite(p.toughnessToFailure) ? fmt::format(", {:.6g} to failure", p.toughnessToFailure) : "",
                                 st.tensileJson);
      }
    }
    printPerformance(r);
    if (opt->profile) printProfile(r, scene.bodies.size());
    if (!scene.output.plotPng.empty())
      std::cout << "plot: " << (std::filesystem::path(dir) / scene.output.plotPng).string() << "\n";
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
