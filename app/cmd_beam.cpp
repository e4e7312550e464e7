// `mesochain beam TABLES... [CONSTANTS.toml]`: fits scan tables (or takes the four constants),
// idealises a beam, discretises it into bricks and writes beam.json, an mDEM model file and a
// cantilever scene (docs/beam.md).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/cmd_beam_bend.hpp"
#include "app/commands.hpp"
#include "beam/beam_run.hpp"
#include "beam/fit_plot.hpp"
#include "beam/mdem_export.hpp"
#include "beam/plate_run.hpp"
#include "common/units.hpp"
#include "common/build_info.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "common/plot/png_io.hpp"
#include "common/units.hpp"

namespace mesochain::app {

namespace {
namespace fs = std::filesystem;

struct BeamOptions {
  std::vector<std::string> inputs;
  int cellsPerBrick = 0;
  std::string closure = "four_constants";
  std::string section = "rectangle";
  double wallAngstrom = 3.4;
  std::optional<double> thicknessAngstrom;
  std::string linearTerm = "auto";
  double tolerance = 0.02;
  bool measuredCurvature = false;
  std::string bendOffset = "anchored";
  std::optional<double> bendReference;
  std::optional<double> c, k, ds, dh, t0;
  std::optional<int> atoms;
  std::string outputDir = "beam-out";
  int bricks = 11;
};

struct PlateOptions {
  std::string file;
  std::string outputDir = "plate-out";
  double tolerance = 0.02;
  bool measuredCurvature = false;
};

void writeFile(const fs::path& p, const std::string& text) { writeFileAtomically(p.string(), text); }

// `mesochain beam plate FILE.toml`: N-layer rigidities against the bonded plate and sliding layers.
int runPlateCommand(const PlateOptions& o) {
  beam::PlateInputs in;
  beam::readPlateFile(o.file, in);
  in.tolerance = o.tolerance;
  in.measuredCurvature = o.measuredCurvature;
  prepareOutputFolder(o.outputDir, "<command line>", "option --output-dir");
  beam::PlateRun run = beam::runPlate(in);
  requireFiniteJson(run.report, (fs::path(o.outputDir) / "plate.json").string());
  fs::create_directories(o.outputDir);
  const fs::path dir(o.outputDir);
  std::vector<std::string> fits;
  for (std::size_t i = 0; i < run.stacks.size(); ++i) {
    const auto& s = run.stacks[i];
    if (!s.curve) continue;
    const std::string path = (dir / fmt::format("fit-{}-layers.png", s.layers)).string();
    beam::writeFitPlot(*s.curve, path);
    run.report["stacks"][i]["plot"] = path;
    fits.push_back(path);
  }
  const std::string png = (dir / "plate.png").string();
  plot::writePng(png, beam::renderPlatePlot(run));
  run.report["files"] = {{"plot", png}, {"fit_plots", fits}};
  run.report["program"] = buildInfoJson();
  writeFile(dir / "plate.json", run.report.dump(2) + "\n");
  std::cout << fmt::format("D1 = {:.6g} eV ({})\n", run.singleLayer * units::kHartreeInEv,
                           run.report["inputs"]["single_layer_rigidity_source"].get<std::string>());
  std::cout << "  N   D (eV)             bonded (eV)   sliding (eV)  D/bonded  bonded fraction\n";
  for (const auto& j : run.report["stacks"])
    std::cout << fmt::format("{:3d}   {:<18} {:<13.6g} {:<13.6g} {:<9.5f} {}\n", j["layers"].get<int>(),
                             beam::formatWithUncertainty(j["rigidity_eV"].get<double>(), j["uncertainty_eV"].get<double>()),
                             j["bonded_eV"].get<double>(), j["sliding_eV"].get<double>(),
                             j["ratio_to_bonded"].get<double>(),
                             j["bonded_fraction"].is_null() ? std::string("-")
                                                            : fmt::format("{:.4f}", j["bonded_fraction"].get<double>()));
  std::cout << "wrote " << (dir / "plate.json").string() << ", " << png;
  for (const std::string& p : fits) std::cout << ", " << p;
  std::cout << "\n";
  return 0;
}
}  // namespace

Command makeBeamCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<BeamOptions>();
  auto plateSub = std::make_shared<CLI::App*>(nullptr);
  auto plate = std::make_shared<PlateOptions>();
  auto bendCurve = std::make_shared<SubcommandHooks>();
  Command c;
  c.attach = [sub, opt, plateSub, plate, bendCurve](CLI::App& app) {
    CLI::App* s = app.add_subcommand(
        "beam", "fit scan tables (or take C, K, D_s, D_h) to a beam and bricks; write beam.json and mDEM files");
    *sub = s;
    s->add_option("inputs", opt->inputs,
                  "scan tables (.json, .csv), folders of them, and/or a constants file (.toml)");
    s->add_option("-n,--cells-per-brick", opt->cellsPerBrick, "cells per brick (L = n T0)")
        ->check(integerIn(1, beam::kMaxCellsPerBrick));
    s->add_option("--closure", opt->closure, "four_constants or measured_thickness")
        ->check(CLI::IsMember({"four_constants", "measured_thickness"}));
    s->add_option("--section", opt->section, "rectangle, circle or annulus")
        ->check(CLI::IsMember({"rectangle", "circle", "annulus"}));
    s->add_option("--wall-thickness-angstrom", opt->wallAngstrom, "annulus wall")
        ->check(finiteNumber(false));
    s->add_option("--thickness-angstrom", opt->thicknessAngstrom, "measured thickness h (overrides the scans')")
        ->check(finiteNumber(false));
    s->add_option("--linear-term", opt->linearTerm, "auto (stretch, twist: on; bend: off), on, off")
        ->check(CLI::IsMember({"auto", "on", "off"}));
    s->add_option("--tolerance", opt->tolerance, "relative tolerance of the quadratic regime")
        ->check(finiteNumber(false, 1.0));
    s->add_flag("--measured-curvature", opt->measuredCurvature, "fit bends against the measured curvature");
    s->add_option("--bend-offset", opt->bendOffset,
                  "U(0) of the bend fits: anchored (default: the straight reference) or free")
        ->check(CLI::IsMember({"anchored", "free"}));
    s->add_option("--bend-reference-hartree", opt->bendReference,
                  "straight reference energy per cell, for bend tables of rings alone")
        ->check(anyFiniteNumber());
    s->add_option("--C-hartree", opt->c, "stretching C per cell (U = C eps^2 / 2)")->check(finiteNumber(false));
    s->add_option("--K-hartree-per-rad2", opt->k, "twisting K per cell (U = K gamma^2 / 2)")
        ->check(finiteNumber(false));
    s->add_option("--D-soft-hartree-bohr2", opt->ds, "soft bending D_s per cell (U = D (1/R)^2 / 2)")
        ->check(finiteNumber(false));
    s->add_option("--D-hard-hartree-bohr2", opt->dh, "hard bending D_h per cell")->check(finiteNumber(false));
    s->add_option("--T0-bohr", opt->t0, "cell length T0")->check(finiteNumber(false));
    s->add_option("--atoms-per-cell", opt->atoms, "carbon atoms per cell (mass)")
        ->check(integerIn(1, beam::kMaxAtomsPerCell));
    s->add_option("-o,--output-dir", opt->outputDir, "folder for beam.json, model.toml, cantilever.toml")
        ->check(nonEmptyPath());
    s->add_option("--bricks", opt->bricks, "bricks in the cantilever scene")
        ->check(integerIn(2, 1000000));
    CLI::App* p = s->add_subcommand(
        "plate", "N-layer bending rigidities (bend scans or given) against the bonded plate and sliding layers");
    *plateSub = p;
    p->add_option("file", plate->file, "plate file (.toml, docs/beam.md)")->required();
    p->add_option("-o,--output-dir", plate->outputDir, "folder for plate.json, plate.png and fit plots")
        ->check(nonEmptyPath());
    p->add_option("--tolerance", plate->tolerance, "relative tolerance of the quadratic regime")
        ->check(finiteNumber(false, 1.0));
    p->add_flag("--measured-curvature", plate->measuredCurvature, "fit bends against the measured curvature");
    *bendCurve = attachBendCurveCommand(*s);
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt, plateSub, plate, bendCurve] {
    if (*plateSub && (*plateSub)->parsed()) return runPlateCommand(*plate);
    if (bendCurve->selected && bendCurve->selected()) return bendCurve->run();
    beam::BeamInputs in;
    std::vector<std::string> skipped;
    for (const std::string& p : opt->inputs) {
      if (fs::is_directory(p)) {
        const std::vector<std::string> files = beam::scanFilesIn(p);
        for (const std::string& f : files) {
          // scan writes each curve as JSON and CSV (the same numbers): the JSON is read.
          if (fs::path(f).extension() == ".csv" &&
              std::find(files.begin(), files.end(), fs::path(f).replace_extension(".json").string()) != files.end())
            continue;
          try {
            in.curves.push_back(beam::readScanTable(f));
          } catch (const InputError& e) {
            skipped.push_back(e.what());  // a folder may hold other JSON (checkpoints, results)
          }
        }
      } else if (fs::path(p).extension() == ".toml") {
        beam::readConstantsFile(p, in);
      } else {
        in.curves.push_back(beam::readScanTable(p));
      }
    }
    for (const std::string& s : skipped) std::cerr << "beam: skipped " << s << "\n";
    const std::string cl = "<command line>";
    auto given = [&](std::optional<beam::GivenConstant>& slot, const std::optional<double>& v, const char* flag) {
      if (!v) return;
      if (slot) throw InputError(cl, flag, "a value also given in " + slot->source, "one source per constant");
      slot = beam::GivenConstant{*v, 0.0, cl};
    };
    given(in.stretch, opt->c, "--C-hartree");
    given(in.twist, opt->k, "--K-hartree-per-rad2");
    given(in.bendSoft, opt->ds, "--D-soft-hartree-bohr2");
    given(in.bendHard, opt->dh, "--D-hard-hartree-bohr2");
    if (opt->t0) in.cellLength = *opt->t0;
    if (opt->atoms) in.atomsPerCell = *opt->atoms;
    if (opt->cellsPerBrick > 0) in.cellsPerBrick = opt->cellsPerBrick;
    if (opt->thicknessAngstrom) in.thickness = *opt->thicknessAngstrom * units::kAngstromInBohr;
    in.closure = opt->closure;
    in.section = opt->section;
    in.wall = opt->wallAngstrom * units::kAngstromInBohr;
    in.linearTerm = opt->linearTerm;
    in.tolerance = opt->tolerance;
    in.measuredCurvature = opt->measuredCurvature;
    in.bendAnchor.offset = opt->bendOffset;
    in.bendAnchor.referenceEnergy = opt->bendReference;
    if (opt->bricks < 2) throw InputError(cl, "--bricks", std::to_string(opt->bricks), "at least 2");

    prepareOutputFolder(opt->outputDir, cl, "option --output-dir");
    beam::BeamRun run = beam::runBeam(in);
    if (run.report.contains("warnings"))
      for (const auto& w : run.report["warnings"]) std::cerr << "warning: " << w.get<std::string>() << "\n";
    fs::create_directories(opt->outputDir);
    const fs::path dir(opt->outputDir);
    beam::MdemExportOptions ex;
    ex.elements = opt->bricks;
    const std::string header = fmt::format(
        "mDEM model written by `mesochain beam` ({} closure, {} section): Y = {:.6g} GPa, G = {:.6g} GPa,\n"
        "T0 = {:.6g} Bohr, {} cells per brick. Parameters with units: beam.json.",
        run.beam.closure, run.beam.shape, run.beam.young * units::si::kHartreePerBohr3InMPa * 1e-3,
        run.beam.shear * units::si::kHartreePerBohr3InMPa * 1e-3, run.beam.cellLength, run.brick.cellsPerBrick);
    // Every number checked before any file is written (an overflow such as C_eV = 1e308 ends
    // here, naming the entry, with no output that looks valid).
    const std::string model = beam::mdemModelToml(run.brick, ex, header);
    const std::string scene = beam::cantileverSceneToml(run.brick, ex);
    requireFiniteJson(run.report, (dir / "beam.json").string());
    requireFiniteToml(model, (dir / ex.modelFile).string());
    requireFiniteToml(scene, (dir / "cantilever.toml").string());
    writeFile(dir / ex.modelFile, model);
    writeFile(dir / "cantilever.toml", scene);
    run.report["files"] = {{"model", (dir / ex.modelFile).string()}, {"scene", (dir / "cantilever.toml").string()}};
    // One PNG per fitted curve: fit-stretch.png, fit-twist.png, fit-bend-soft.png, fit-bend-hard.png.
    std::vector<std::string> plots;
    for (const beam::FittedCurve& fc : run.curves) {
      std::string name = "fit-" + fc.label + ".png";
      std::replace(name.begin(), name.end(), ' ', '-');
      const std::string path = (dir / name).string();
      beam::writeFitPlot(fc, path);
      run.report["constants"][fc.reportKey]["plot"] = path;
      plots.push_back(path);
    }
    run.report["files"]["plots"] = plots;
    if (!skipped.empty()) run.report["skipped_files"] = skipped;
    run.report["program"] = buildInfoJson();
    writeFile(dir / "beam.json", run.report.dump(2) + "\n");

    const auto& k = run.report["constants"];
    for (const char* key : {"C_hartree", "K_hartree_per_rad2", "D_soft_hartree_bohr2", "D_hard_hartree_bohr2"})
      if (k.contains(key))
        std::cout << fmt::format("{:<22} {:.8g} +- {:.2g}  ({})\n", key, k[key]["value"].get<double>(),
                                 k[key]["uncertainty"].get<double>(), k[key]["source"].get<std::string>());
    const auto& b = run.report["beam"];
    std::cout << fmt::format("beam ({}, {} closure): Y = {:.6g} GPa, G = {:.6g} GPa", run.beam.shape,
                             run.beam.closure, b["young_modulus_GPa"].get<double>(), b["shear_modulus_GPa"].get<double>());
    if (run.beam.shape == "rectangle")
      std::cout << fmt::format(", h = {:.6g} nm, w = {:.6g} nm", b["thickness_nm"].get<double>(), b["width_nm"].get<double>());
    else
      std::cout << fmt::format(", r = {:.6g} nm", b["radius_nm"].get<double>());
    std::cout << "\n";
    for (const beam::Beam& a : run.alternatives)
      std::cout << fmt::format("alternative ({} closure): h = {:.6g} nm, relative residual of D_s {:+.3g}\n", a.closure,
                               a.thickness * units::si::kBohrInNm, a.residuals.bendSoft);
    const auto& br = run.report["brick"];
    std::cout << fmt::format("brick: L = {:.6g} nm, mass = {:.6g} ag, k_n = {:.6g} MPa/nm, k_s = {:.6g} MPa/nm\n",
                             br["length_nm"].get<double>(), br["mass_ag"].get<double>(),
                             br["k_n_MPa_per_nm"].get<double>(), br["k_s_MPa_per_nm"].get<double>());
    std::cout << "wrote " << (dir / "beam.json").string() << ", " << (dir / ex.modelFile).string() << ", "
              << (dir / "cantilever.toml").string();
    for (const std::string& p : plots) std::cout << ", " << p;
    std::cout << "\n";
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
