#include "app/chain_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/chain_file.hpp"
#include "app/chain_report.hpp"
#include "beam/beam_run.hpp"
#include "beam/fit_plot.hpp"
#include "beam/mdem_export.hpp"
#include "beam/scan_table.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "common/progress_bar.hpp"
#include "common/units.hpp"
#include "mdem/cantilever_check.hpp"
#include "mdem/scene_file.hpp"
#include "input/cell_calculator.hpp"
#include "objective/drivers/scan.hpp"
#include "input/scan_file.hpp"
#include "input/scan_output.hpp"
#include "objective/drivers/scan_reference.hpp"
#include "workflows/knobs.hpp"

namespace mesochain::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The run of one chain: the file, the state of its stages (chain-state.json: per stage the hash
// of its inputs, done, the seconds over all runs), the report being built and the budget of
// new relaxations (--stop-after).
struct ChainRun {
  ChainFile c;
  fs::path statePath;
  json state = json::object();
  json report;
  int budget = -1;
  int exitCode = 0;  // 3 not converged, 4 stopped
  // The settings the reference was computed with (cell, calculator, relaxation, the tables'
  // contents): part of every scan stage's inputs, so that other tables rerun the scans too.
  std::string referenceIdentity;

  void saveState() const { writeFileAtomically(statePath.string(), state.dump(2) + "\n"); }
  void log(const json& stage) {
    std::cout << fmt::format("chain: {:<10} {} ({:.1f} s)\n", stage["stage"].get<std::string>(),
                             stage["status"].get<std::string>(), stage["seconds"].get<double>());
    report["stages"].push_back(stage);
  }
};

// reference: the first scan stage's scan file without `reference` (reference.scan.toml, read by
// the scan reader for the cell, calculator and relaxation), its point 0 relaxed once with the
// T0 search (relaxScanReference) into reference.json. Skipped when reference.json was computed
// with the same settings. Returns false when stopped.
bool referenceStage(ChainRun& r) {
  const auto& [first, keys] = r.c.scans.front();
  const fs::path scanFile = r.c.dir / "reference.scan.toml";
  const fs::path refPath = r.c.dir / "reference.json";
  writeFileAtomically(scanFile.string(), scanFileText(r.c, *first, keys, "reference", false));
  const objective::ScanInput in = objective::readScanFile(scanFile.string(), r.c.dir.string());
  const dftb::CalculatorSettings calc = objective::calculatorSettings(in.cell);
  const auto identity = objective::referenceIdentity(in.cell.cell, calc, in.settings);
  json out = {{"stage", "reference"}, {"outputs", refPath.string()}};
  r.referenceIdentity = json(identity).dump();
  json& rec = r.state["reference"];
  objective::ScanReference ref;
  bool have = false;
  if (fs::exists(refPath)) {
    try {
      ref = objective::readScanReference(refPath.string(), in.cell.cell);
      have = objective::settingChanges(ref.identity, identity, "reference").empty();
    } catch (const InputError&) {
      have = false;  // another cell's reference: relaxed again
    }
  }
  if (have) {
    out["status"] = "skipped (done, inputs unchanged)";
  } else {
    if (r.budget == 0) return false;
    const auto t0 = std::chrono::steady_clock::now();
    objective::ScanSettings s = in.settings;
    s.progressBar = false;  // its plan's other points are not computed here: a bar of its own
    ProgressBar bar("chain reference", 1);
    s.relax.progress = [&bar](int evaluation, double f, double maxForce) {
      bar.update(0, fmt::format("evaluation {}  F = {:.10f} Ha  max|force| = {:.2e} Ha/Bohr", evaluation, f, maxForce));
    };
    ref = objective::relaxScanReference(in.cell.cell, objective::loadParameters(in.cell), calc, s);
    bar.finish();
    objective::writeScanReference(refPath.string(), ref);
    rec = {{"seconds", secondsSince(t0)}};
    r.saveState();
    if (r.budget > 0) --r.budget;
    out["status"] = "ran";
    if (!ref.point.converged) r.exitCode = 3;
  }
  out["seconds"] = rec.is_object() ? rec.value("seconds", 0.0) : 0.0;  // the state may be gone
  const objective::ScanPoint& p = ref.point;
  r.report["reference"] = {{"T0_bohr", p.cell.symmetry.translation()},
                           {"T0_nm", p.cell.symmetry.translation() * units::si::kBohrInNm},
                           {"twist0_rad", p.cell.symmetry.twist()},
                           {"rotation_order", p.cell.symmetry.rotationOrder()},
                           {"atoms_per_cell", p.cell.atomCount()},
                           {"energy_hartree_per_cell", p.energy},
                           {"converged", p.converged},
                           {"max_force_hartree_per_bohr", p.maxForce},
                           {"file", refPath.string()}};
  r.log(out);
  return true;
}

// A scan stage: STAGE.scan.toml run as `mesochain scan --resume` from the shared reference.
// Returns false when stopped or not converged (exitCode set).
bool scanStage(ChainRun& r, const ScanStage& stage, const toml::value& keys, const std::string& cellText,
               beam::BeamInputs& bin) {
  const std::string text = scanFileText(r.c, stage, keys, stage.name, true);
  const std::string hash = chainHash(text + cellText + r.referenceIdentity);
  const fs::path scanFile = r.c.dir / (std::string(stage.name) + ".scan.toml");
  const fs::path curve = r.c.dir / (std::string(stage.name) + ".json");
  json& rec = r.state[stage.name];
  json out = {{"stage", stage.name}, {"scan_file", scanFile.string()}, {"curve", curve.string()}};
  if (rec.is_object() && rec.value("input_hash", "") == hash && rec.value("done", false) && fs::exists(curve)) {
    out["status"] = "skipped (done, inputs unchanged)";
    out["seconds"] = rec.value("seconds", 0.0);
  } else {
    if (!(rec.is_object() && rec.value("input_hash", "") == hash)) {
      fs::remove(r.c.dir / (std::string(stage.name) + ".checkpoint.json"));  // other inputs: start afresh
      rec = {{"input_hash", hash}, {"done", false}, {"seconds", 0.0}};
      r.saveState();  // before the scan: a run killed inside it resumes from its checkpoint
    }
    writeFileAtomically(scanFile.string(), text);
    // The scan's [output] paths are relative to the chain's folder (as scan -o DIR).
    objective::ScanInput in = objective::readScanFile(scanFile.string(), r.c.dir.string());
    in.settings.resume = true;
    in.settings.stopAfter = r.budget;
    const auto t0 = std::chrono::steady_clock::now();
    const objective::ScanResult res = objective::runScan(in.cell.cell, objective::loadParameters(in.cell),
                                                         objective::calculatorSettings(in.cell), in.settings);
    rec["seconds"] = rec.value("seconds", 0.0) + secondsSince(t0);
    out["seconds"] = rec["seconds"];
    out["points_computed"] = res.computed;
    out["points_restored"] = res.reused;
    if (r.budget >= 0) r.budget = std::max(0, r.budget - res.computed);
    if (!res.complete) {
      r.saveState();
      std::cout << fmt::format("chain: stage {} stopped after {} new point(s); rerun to resume\n", stage.name,
                               res.computed);
      r.exitCode = 4;
      return false;
    }
    objective::writeScanCurve(res, in.jsonPath, in.csvPath);
    fs::create_directories(fs::path(in.structurePrefix).parent_path());
    objective::writeScanStructures(res, in.structurePrefix);
    for (const auto& p : res.points)
      if (!p.converged) {
        r.saveState();
        std::cerr << fmt::format("chain: stage {}: a point did not converge within the step limit\n", stage.name);
        r.exitCode = 3;
        return false;
      }
    rec["done"] = true;
    out["status"] = res.reused > 0 ? "resumed" : "ran";
    r.saveState();
  }
  r.log(out);
  bin.curves.push_back(beam::readScanTable(curve.string()));
  return true;
}

// The fit plot of one curve into FOLDER/fit-LABEL.png, listed in the report's "plots" (paths
// relative to the chain's folder, shown by chain.md).
void writeFitPlot(ChainRun& r, const beam::FittedCurve& fc, const std::string& folder) {
  std::string name = "fit-" + fc.label + ".png";
  std::replace(name.begin(), name.end(), ' ', '-');
  fs::create_directories(r.c.dir / folder);
  beam::writeFitPlot(fc, (r.c.dir / folder / name).string());
  r.report["plots"].push_back({{"title", fc.label + " fit"}, {"file", folder + "/" + name}});
}

// beam: the curves -> beam.json, model.toml, cantilever.toml and the fit plots (rerun every
// time: well under a second).
beam::BeamRun beamStage(ChainRun& r, beam::BeamInputs bin) {
  bool hard = false;
  for (const auto& [stage, keys] : r.c.scans) hard = hard || std::string(stage->name) == "bend_hard";
  bin.cellsPerBrick = r.c.cellsPerBrick;
  bin.section = !r.c.section.empty() ? r.c.section : hard ? "rectangle" : "circle";
  bin.source = r.c.file.string();
  const auto t0 = std::chrono::steady_clock::now();
  beam::BeamRun run = beam::runBeam(bin);
  const fs::path beamDir = r.c.dir / "beam";
  fs::create_directories(beamDir);
  beam::MdemExportOptions ex;
  const std::string model = beam::mdemModelToml(run.brick, ex, "mDEM model written by `mesochain chain`");
  const std::string scene = beam::cantileverSceneToml(run.brick, ex);
  requireFiniteJson(run.report, (beamDir / "beam.json").string());
  writeFileAtomically((beamDir / ex.modelFile).string(), model);
  writeFileAtomically((beamDir / "cantilever.toml").string(), scene);
  for (const beam::FittedCurve& fc : run.curves) writeFitPlot(r, fc, "beam");
  writeFileAtomically((beamDir / "beam.json").string(), run.report.dump(2) + "\n");
  r.log({{"stage", "beam"}, {"status", "ran"}, {"seconds", secondsSince(t0)},
         {"outputs", (beamDir / "beam.json").string()}});
  r.report["constants"] = run.report["constants"];
  r.report["beam"] = run.report["beam"];
  r.report["brick"] = run.report["brick"];
  if (run.report.contains("warnings")) r.report["warnings"] = run.report["warnings"];
  return run;
}

// beam = false: each curve fitted alone (the fitter of `mesochain beam`, U(0) free where there is
// no straight point) into report["constants"], no beam, bricks or cantilever.
void curveFits(ChainRun& r, const beam::BeamInputs& bin) {
  for (const beam::ScanCurve& curve : bin.curves) {
    const beam::CurveConstant q = beam::curveConstant(curve);
    const beam::FittedCurve fc = beam::fitScanCurve(curve, q.name, q.key, bin.tolerance, bin.linearTerm, false);
    writeFitPlot(r, fc, "fits");
    r.report["constants"][curve.label()] = {{"quantity", q.name}, {"unit", q.unit}, {"value", fc.fit.stiffness},
                                           {"uncertainty", fc.fit.uncertainty}, {"source", curve.source}};
    for (const std::string& w : fc.warnings) r.report["warnings"].push_back(curve.label() + ": " + w);
  }
}

// cantilever: beam/cantilever.toml run by the mdem engine to its static state, its tip against
// beam theory of the fitted constants (E I = D_s / T0, G J = K T0; mdem/cantilever_check.hpp).
// Skipped when the scene, the model, the constants and the tolerance are those of the stored
// result.
void cantileverStage(ChainRun& r) {
  const json& k = r.report["constants"];
  const fs::path scenePath = r.c.dir / "beam" / "cantilever.toml";
  if (!k.contains("D_soft_hartree_bohr2") || !k["D_soft_hartree_bohr2"].is_object()) {
    r.log({{"stage", "cantilever"}, {"status", "not run (no soft bending constant)"}, {"seconds", 0.0}});
    return;
  }
  const double t0 = k["T0_bohr"].get<double>();
  const double toPnNm2 = units::si::kHartreeInZeptojoule * units::si::kBohrInNm;  // Hartree Bohr -> pN nm^2
  mdem::CantileverTheory theory;
  theory.bendingStiffness = k["D_soft_hartree_bohr2"]["value"].get<double>() / t0 * toPnNm2;
  if (k.contains("K_hartree_per_rad2") && k["K_hartree_per_rad2"].is_object())
    theory.torsionalStiffness = k["K_hartree_per_rad2"]["value"].get<double>() * t0 * toPnNm2;
  theory.tolerance = r.c.cantileverTolerance;
  theory.massPerLength = r.report["brick"]["mass_ag"].get<double>() / r.report["brick"]["length_nm"].get<double>();
  const std::string hash = chainHash(readText(scenePath) + readText(r.c.dir / "beam" / "model.toml") +
                                     fmt::format("{:.17g} {:.17g} {:.17g} {:.17g}", theory.bendingStiffness,
                                                 theory.torsionalStiffness, theory.tolerance,
                                                 theory.massPerLength));
  json& rec = r.state["cantilever"];
  json out = {{"stage", "cantilever"}, {"scene", scenePath.string()}};
  if (rec.is_object() && rec.value("input_hash", "") == hash && rec.contains("result")) {
    out["status"] = "skipped (done, inputs unchanged)";
  } else {
    const auto start = std::chrono::steady_clock::now();
    const mdem::CantileverCheck c = mdem::checkCantilever(mdem::loadScene(scenePath.string()), theory);
    json res = {{"length_nm", c.length},
                {"bending_moment_pN_nm", c.bendingMoment},
                {"twisting_moment_pN_nm", c.twistingMoment},
                {"bending_stiffness_pN_nm2", theory.bendingStiffness},
                {"torsional_stiffness_pN_nm2", theory.torsionalStiffness},
                {"steps", c.steps},
                {"relaxed", c.relaxed},
                {"residual_moment_pN_nm", c.residualMoment},
                {"tolerance", c.tolerance},
                {"passed", c.passed},
                {"first_bending_frequency_GHz", c.frequency},
                {"first_bending_frequency_beam_theory_GHz", c.frequencyTheory},
                {"quantities", json::array()}};
    for (const mdem::CantileverQuantity& q : c.quantities)
      res["quantities"].push_back({{"name", q.name}, {"unit", q.unit}, {"measured", q.measured},
                                   {"beam_theory", q.theory}, {"relative_difference", q.relativeDifference()}});
    rec = {{"input_hash", hash}, {"seconds", secondsSince(start)}, {"result", res}};
    r.saveState();
    out["status"] = "ran";
  }
  out["seconds"] = rec["seconds"];
  r.report["cantilever"] = rec["result"];
  r.log(out);
  if (!rec["result"]["passed"].get<bool>())
    std::cerr << "chain: warning: the mDEM cantilever differs from beam theory by more than the tolerance "
                 "(chain.md)\n";
}


// knobs ([knobs]): the accuracy-against-time table of each listed scan stage (workflows/knobs.hpp,
// as `mesochain bench knobs STAGE.scan.toml`) into knobs/STAGE.json and .csv. A stage's table is
// skipped when its settings and its curve are unchanged; a killed knobs stage reruns the tables
// not yet written.
void knobsStage(ChainRun& r) {
  const ChainKnobs& k = r.c.knobs;
  const fs::path dir = r.c.dir / "knobs";
  fs::create_directories(dir);
  json& rec = r.state["knobs"];
  if (!rec.is_object()) rec = {{"seconds", 0.0}, {"tables", json::object()}};
  json tables = json::array();
  int ran = 0;
  for (const std::string& stage : k.stages) {
    workflows::KnobsRequest q;
    q.scanFile = (r.c.dir / (stage + ".scan.toml")).string();
    q.scanOutputDir = r.c.dir.string();
    // A bend scan of rings made from a straight cell (reference rotation order 1) takes
    // `sampling` (the straight cell's kappa points and the rings' samples together); `kpoints`
    // alone would change only its straight point and mix a sampling mismatch into the curve
    // (docs/benchmarks.md, bench knobs step 2). `angular` applies to bends only, `sampling` to
    // bends of a straight cell only. A knob not applied is said in the report.
    const bool bend = stage.rfind("bend", 0) == 0;
    const bool rings = bend && r.report["reference"]["rotation_order"].get<int>() == 1;
    json notApplied = json::array();
    if (rings && !k.sampling.empty()) {
      if (!k.kpoints.empty())
        notApplied.push_back("kpoints (sampling varies the straight cell's kappa points and the rings' samples together)");
    } else {
      q.kpoints = k.kpoints;
    }
    if (bend) q.angular = k.angular;
    else if (!k.angular.empty()) notApplied.push_back("angular (bend stages only)");
    if (rings) q.sampling = k.sampling;
    else if (!k.sampling.empty()) notApplied.push_back("sampling (bend stages of a straight cell only)");
    q.dispersion = k.dispersion;
    q.temperature = k.temperature;
    q.where = {r.c.file.string(), "knobs."};
    json settings = {q.kpoints, q.angular, q.sampling, q.dispersion, q.temperature};
    const std::string hash = chainHash(settings.dump() + readText(r.c.dir / (stage + ".json")));
    const fs::path out = dir / (stage + ".json"), png = dir / (stage + ".png");
    json& t = rec["tables"][stage];
    // A table whose plot should exist but does not (deleted, or written by an older version) is
    // computed again.
    const bool plotMissing = t.is_object() && t.value("plot", true) && !fs::exists(png);
    if (!(t.is_object() && t.value("input_hash", "") == hash && fs::exists(out) && !plotMissing)) {
      const auto start = std::chrono::steady_clock::now();
      const workflows::KnobsTable table = workflows::runKnobs(q);
      writeFileAtomically(out.string(), workflows::knobsJson(table).dump(2) + "\n");
      writeFileAtomically((dir / (stage + ".csv")).string(), workflows::knobsCsv(table));
      fs::remove(png);  // a table without differences has no plot
      const bool plotted = workflows::writeKnobsPlot(table, png.string());
      rec["seconds"] = rec.value("seconds", 0.0) + secondsSince(start);
      t = {{"input_hash", hash}, {"plot", plotted}};
      r.saveState();
      ++ran;
    }
    json j = json::parse(readText(out));
    j["stage"] = stage;
    if (!notApplied.empty()) j["knobs_not_applied"] = notApplied;
    if (fs::exists(png))
      r.report["plots"].push_back({{"title", stage + " knobs: error against time"}, {"file", "knobs/" + stage + ".png"}});
    tables.push_back(j);
  }
  r.report["knobs"] = tables;
  r.log({{"stage", "knobs"}, {"status", ran > 0 ? "ran" : "skipped (done, inputs unchanged)"},
         {"seconds", rec["seconds"]}, {"outputs", dir.string()}});
}

}  // namespace

int runChain(const ChainOptions& o) {
  ChainRun r;
  r.c = readChainFile(o.file);
  if (o.check) return checkChain(r.c);
  fs::create_directories(r.c.dir);
  if (r.c.inlineCell) {
    // The run's copy of the inline cell; never over a file it did not write.
    const std::string old = fs::exists(r.c.cellPath) ? readText(r.c.cellPath) : std::string();
    if (!old.empty() && old.rfind("# the [cell] of ", 0) != 0)
      throw InputError(r.c.file.string(), "table [cell]", r.c.cellPath + " exists and was not written by a chain",
                       "an output folder without a file of that name (the run writes the inline cell there)");
    writeFileAtomically(r.c.cellPath, inlineCellText(r.c));
  }
  r.statePath = r.c.dir / "chain-state.json";
  if (fs::exists(r.statePath)) {
    r.state = json::parse(readText(r.statePath), nullptr, false);
    if (r.state.is_discarded() || !r.state.is_object())
      throw InputError(r.statePath.string(), "the chain state", "not a JSON object",
                       "the file a chain writes (delete it to rerun every stage)");
  }
  // The cell's content in the stages' input hash (an inline cell in canonical form).
  const std::string cellText = r.c.inlineCell ? inlineCellIdentity(r.c) : readText(r.c.cellPath);
  if (cellText.empty()) throw InputError(r.c.file.string(), "key cell", r.c.cellPath, "a readable cell file");
  r.report["format"] = 1;
  r.report["chain_file"] = r.c.file.string();
  r.report["stages"] = json::array();
  r.report["plots"] = json::array();
  r.budget = o.stopAfter;
  if (!referenceStage(r)) {
    std::cout << "chain: stopped before the reference; rerun to continue\n";
    return 4;
  }
  if (r.exitCode == 3) {
    std::cerr << "chain: the reference did not converge within the step limit\n";
    return 3;
  }
  beam::BeamInputs bin;
  for (const auto& [stage, keys] : r.c.scans)
    if (!scanStage(r, *stage, keys, cellText, bin)) return r.exitCode;
  std::optional<beam::BeamRun> run;
  if (r.c.beam) {
    run = beamStage(r, std::move(bin));
    cantileverStage(r);
  } else {
    curveFits(r, bin);
  }
  if (r.c.knobs.given) knobsStage(r);
  requireFiniteJson(r.report, (r.c.dir / "chain.json").string());
  writeFileAtomically((r.c.dir / "chain.json").string(), r.report.dump(2) + "\n");
  writeFileAtomically((r.c.dir / "chain.md").string(), chainMarkdown(r.c, r.report, run ? &*run : nullptr));
  for (const auto& [key, v] : r.report["constants"].items())
    if (v.is_object())
      std::cout << fmt::format("{:<22} {:.8g} +- {:.2g}\n", key, v["value"].get<double>(), v["uncertainty"].get<double>());
  std::cout << "wrote " << (r.c.dir / "chain.json").string() << ", " << (r.c.dir / "chain.md").string() << "\n";
  return 0;
}

}  // namespace mesochain::app
