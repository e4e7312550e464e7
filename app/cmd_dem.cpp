// `mesochain dem SCENE.toml`: runs a mesoscopic distinct element scene (docs/scene-file.md).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands.hpp"
#include "mdem/contacts/film_statistics.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::app {

namespace {
struct DemOptions {
  std::string scene;
  std::string outputDir;
  bool quiet = false;
};

void drawProgress(double fraction) {
  constexpr int kWidth = 40;
  const int filled = static_cast<int>(fraction * kWidth + 0.5);
  std::string bar(filled, '#');
  bar.resize(kWidth, ' ');
  std::fprintf(stderr, "\r[%s] %5.1f%%", bar.c_str(), 100.0 * fraction);
  std::fflush(stderr);
}
}  // namespace

Command makeDemCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<DemOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& app) {
    *sub = app.add_subcommand("dem", "run a mesoscopic distinct element (mDEM) scene");
    (*sub)->add_option("scene", opt->scene, "scene file (TOML, format = 1)")->required();
    (*sub)->add_option("-o,--output-dir", opt->outputDir,
                       "folder for the outputs (default: output.directory of the scene)");
    (*sub)->add_flag("-q,--quiet", opt->quiet, "no progress bar");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    const mdem::Scene scene = mdem::loadScene(opt->scene);
    const std::string dir = opt->outputDir.empty() ? scene.output.directory : opt->outputDir;
    // A generated film ([network]): its report, printed now and written as film.json after the run.
    std::optional<mdem::FilmStatistics> film;
    if (!scene.filmSize.isZero()) {
      mdem::FilmStatisticsOptions fo;
      fo.excludeWithin = scene.contacts.excludeWithin;
      film = mdem::filmStatistics(scene, fo);
      std::cout << mdem::formatFilmStatistics(*film);
    }
    std::function<void(double)> progress;
    if (!opt->quiet) progress = drawProgress;
    const mdem::RunSummary r = mdem::runScene(scene, dir, progress);
    if (!opt->quiet) std::fprintf(stderr, "\n");
    if (film) mdem::writeFilmStatisticsJson(*film, (std::filesystem::path(dir) / "film.json").string());
    const mdem::Energies& e = r.finalEnergies;
    std::cout << fmt::format(
        "mdem: {} elements, {} steps of {:.6g} ns (critical {:.6g} ns), t = {:.6g} ns{}\n",
        scene.bodies.size(), r.steps, r.timeStep, r.criticalTimeStep, r.time,
        r.stoppedByCriterion ? ", stopped: kinetic energy below threshold" : "");
    std::cout << fmt::format(
        "energies (zJ): kinetic {:.8g} + {:.8g} (rot), stretching {:.8g}, shearing {:.8g}, "
        "twisting {:.8g}, bending {:.8g}, van der Waals {:.8g}, total {:.8g}{}; outputs in {}\n",
        e.kineticTranslational, e.kineticRotational, e.bonds.stretching, e.bonds.shearing,
        e.bonds.twisting, e.bonds.bending, e.vdw, e.total(),
        r.dissipatedTracked ? fmt::format(" (dissipated by dashpots {:.8g})", e.contactDissipated) : "", dir);
    if (r.tensile)
      std::cout << fmt::format("tensile: strain {:.6g}, stress {:.6g} MPa (peak {:.6g} MPa, at zero strain {:.6g} MPa), "
                               "cross-section {:.6g} nm^2, gauge length {:.6g} nm; {}\n",
                               r.finalStrain, r.finalStress, r.peakStress, r.initialStress, scene.tensile.crossSection,
                               scene.tensile.gaugeLength, (std::filesystem::path(dir) / scene.tensile.csv).string());
    if (!scene.output.plotPng.empty())
      std::cout << "plot: " << (std::filesystem::path(dir) / scene.output.plotPng).string() << "\n";
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
