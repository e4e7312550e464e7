#include "app/chain_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <toml.hpp>

#include "beam/beam_run.hpp"
#include "beam/fit_plot.hpp"
#include "beam/mdem_export.hpp"
#include "beam/scan_table.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "common/toml_file.hpp"
#include "objective/core/cell_file.hpp"
#include "objective/drivers/cell_calculator.hpp"
#include "objective/drivers/scan.hpp"
#include "objective/drivers/scan_file.hpp"
#include "objective/drivers/scan_output.hpp"

namespace mesochain::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct ScanStage {
  const char* name;       // the chain file's table and the stage name
  const char* kind;       // scan kind
  const char* direction;  // bend direction, "" otherwise
};
constexpr ScanStage kScanStages[] = {{"stretch", "stretch", ""},
                                     {"twist", "twist", ""},
                                     {"bend_soft", "bend", "soft"},
                                     {"bend_hard", "bend", "hard"}};

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// FNV-1a, 64 bit (Fowler, Noll & Vo), of a stage's inputs.
std::string hashOf(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return fmt::format("{:016x}", h);
}

// A TOML string literal (basic string, escaped).
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

struct Chain {
  fs::path file, dir;
  std::string cellPath;  // absolute
  double forceTolerance = 1e-4;
  int cellsPerBrick = 0;
  std::string section;  // "" = automatic
  std::vector<std::pair<const ScanStage*, toml::value>> scans;
};

Chain readChain(const std::string& path) {
  const toml::value root = parseTomlFile(path, "chain file");
  Chain c;
  c.file = fs::absolute(path);
  c.dir = c.file.parent_path() / "chain-out";
  const std::string where = path;
  auto line = [](const toml::value& v) { return fmt::format("(line {})", v.location().line()); };
  bool format = false, cell = false;
  for (const auto& [key, v] : root.as_table()) {
    const std::string at = fmt::format("key {} {}", key, line(v));
    if (key == "format") {
      if (!v.is_integer() || v.as_integer() != 1) throw InputError(where, at, toml::format(v), "format = 1");
      format = true;
    } else if (key == "cell") {
      if (!v.is_string()) throw InputError(where, at, "not a string", "the path of a cell file (docs/cell-file.md)");
      c.cellPath = fs::absolute(c.file.parent_path() / v.as_string().str).string();
      cell = true;
    } else if (key == "output") {
      if (!v.is_string() || v.as_string().str.empty()) throw InputError(where, at, "not a path", "a folder for the stages");
      c.dir = c.file.parent_path() / v.as_string().str;
    } else if (key == "force_tolerance") {
      const double x = v.is_floating() ? v.as_floating() : v.is_integer() ? static_cast<double>(v.as_integer()) : -1.0;
      if (!(x > 0.0) || !std::isfinite(x)) throw InputError(where, at, toml::format(v), "a force tolerance > 0 (Ha/Bohr)");
      c.forceTolerance = x;
    } else if (key == "cells_per_brick") {
      if (!v.is_integer() || v.as_integer() < 1 || v.as_integer() > beam::kMaxCellsPerBrick)
        throw InputError(where, at, toml::format(v), "an integer >= 1 (cells per brick)");
      c.cellsPerBrick = static_cast<int>(v.as_integer());
    } else if (key == "section") {
      const std::string sec = v.is_string() ? v.as_string().str : "";
      if (sec != "rectangle" && sec != "circle" && sec != "annulus")
        throw InputError(where, at, toml::format(v), "\"rectangle\", \"circle\" or \"annulus\"");
      c.section = sec;
    } else {
      bool stage = false;
      for (const ScanStage& s : kScanStages)
        if (key == s.name) {
          if (!v.is_table()) throw InputError(where, at, "not a table", fmt::format("a table [{}] of scan keys", s.name));
          c.scans.emplace_back(&s, v);
          stage = true;
        }
      if (!stage)
        throw InputError(where, at, "an unknown key",
                         "format, cell, output, force_tolerance, cells_per_brick, section, [stretch], [twist], "
                         "[bend_soft], [bend_hard]");
    }
  }
  if (!format) throw InputError(where, "key format", "nothing", "format = 1");
  if (!cell) throw InputError(where, "key cell", "nothing", "cell = \"FILE.toml\" (the filament)");
  if (c.cellsPerBrick == 0) throw InputError(where, "key cells_per_brick", "nothing", "cells_per_brick = N");
  if (c.scans.empty()) throw InputError(where, "stages", "no scan table", "at least [stretch] (and [twist], [bend_soft])");
  std::stable_sort(c.scans.begin(), c.scans.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return c;
}

// The scan file of a stage: the chain's table keys verbatim, the cell, the kind, the relaxation
// and the outputs in the chain's folder.
std::string scanFileText(const Chain& c, const ScanStage& s, const toml::value& keys) {
  std::string t = fmt::format("# written by `mesochain chain {}`; docs/scan-file.md\nformat = 1\ncell = {}\nkind = \"{}\"\n",
                              c.file.filename().string(), quoted(c.cellPath), s.kind);
  if (*s.direction) t += fmt::format("direction = \"{}\"\n", s.direction);
  std::string dimensions;
  for (const auto& [k, v] : keys.as_table()) {
    if (k == "dimensions" && v.is_table()) {  // [STAGE.dimensions] -> the scan's [dimensions]
      for (const auto& [dk, dv] : v.as_table()) dimensions += dk + " = " + toml::format(dv) + "\n";
      continue;
    }
    if (k == "direction" || k == "kind" || k == "cell" || v.is_table())
      throw InputError(c.file.string(), fmt::format("key {}.{} (line {})", s.name, k, v.location().line()),
                       "a key the chain sets itself", "the scan's deformation keys (strains, rotation_orders, ...)");
    t += k + " = " + toml::format(v) + "\n";
  }
  if (!dimensions.empty()) t += "[dimensions]\n" + dimensions;
  t += fmt::format("[relax]\nforce_tolerance = {:.17g}\n[output]\njson = \"{}.json\"\ncsv = \"{}.csv\"\n"
                   "checkpoint = \"{}.checkpoint.json\"\n",
                   c.forceTolerance, s.name, s.name, s.name);
  return t;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int runChain(const ChainOptions& o) {
  const Chain c = readChain(o.file);
  fs::create_directories(c.dir);
  const fs::path statePath = c.dir / "chain-state.json";
  json state = json::object();
  if (fs::exists(statePath)) {
    state = json::parse(readText(statePath), nullptr, false);
    if (state.is_discarded() || !state.is_object())
      throw InputError(statePath.string(), "the chain state", "not a JSON object",
                       "the file a chain writes (delete it to rerun every stage)");
  }
  const std::string cellText = readText(c.cellPath);
  if (cellText.empty()) throw InputError(c.file.string(), "key cell", c.cellPath, "a readable cell file");
  json report;
  report["format"] = 1;
  report["chain_file"] = c.file.string();
  report["stages"] = json::array();
  int budget = o.stopAfter;
  beam::BeamInputs bin;
  std::string beamHashInput;
  for (const auto& [stage, keys] : c.scans) {
    const std::string text = scanFileText(c, *stage, keys);
    const std::string hash = hashOf(text + cellText);
    const fs::path scanFile = c.dir / (std::string(stage->name) + ".scan.toml");
    const fs::path curve = c.dir / (std::string(stage->name) + ".json");
    json& rec = state[stage->name];
    json out = {{"stage", stage->name}, {"scan_file", scanFile.string()}, {"curve", curve.string()}};
    if (rec.is_object() && rec.value("input_hash", "") == hash && rec.value("done", false) && fs::exists(curve)) {
      out["status"] = "skipped (done, inputs unchanged)";
      out["seconds"] = rec.value("seconds", 0.0);
    } else {
      if (!(rec.is_object() && rec.value("input_hash", "") == hash)) {
        fs::remove(c.dir / (std::string(stage->name) + ".checkpoint.json"));  // other inputs: start afresh
        rec = {{"input_hash", hash}, {"done", false}, {"seconds", 0.0}};
      }
      writeFileAtomically(scanFile.string(), text);
      // The scan's [output] paths are relative to the chain's folder (as scan -o DIR).
      objective::ScanInput in = objective::readScanFile(scanFile.string(), c.dir.string());
      in.settings.resume = true;
      in.settings.stopAfter = budget;
      in.settings.progressBar = false;
      const auto t0 = std::chrono::steady_clock::now();
      const objective::ScanResult r = objective::runScan(in.cell.cell, objective::loadParameters(in.cell),
                                                         objective::calculatorSettings(in.cell), in.settings);
      rec["seconds"] = rec.value("seconds", 0.0) + secondsSince(t0);
      out["seconds"] = rec["seconds"];
      out["points_computed"] = r.computed;
      out["points_restored"] = r.reused;
      if (budget >= 0) budget = std::max(0, budget - r.computed);
      if (!r.complete) {
        writeFileAtomically(statePath.string(), state.dump(2) + "\n");
        std::cout << fmt::format("chain: stage {} stopped after {} new point(s); rerun to resume\n", stage->name,
                                 r.computed);
        return 4;
      }
      objective::writeScanCurve(r, in.jsonPath, in.csvPath);
      for (const auto& p : r.points)
        if (!p.converged) {
          writeFileAtomically(statePath.string(), state.dump(2) + "\n");
          std::cerr << fmt::format("chain: stage {}: a point did not converge within the step limit\n", stage->name);
          return 3;
        }
      rec["done"] = true;
      out["status"] = r.reused > 0 ? "resumed" : "ran";
      writeFileAtomically(statePath.string(), state.dump(2) + "\n");
    }
    std::cout << fmt::format("chain: {:<10} {} ({:.1f} s)\n", stage->name, out["status"].get<std::string>(),
                             out["seconds"].get<double>());
    report["stages"].push_back(out);
    bin.curves.push_back(beam::readScanTable(curve.string()));
    beamHashInput += readText(curve);
  }

  // beam: the curves -> beam.json, model.toml, cantilever.toml and the fit plots.
  bool hard = false;
  for (const auto& [stage, keys] : c.scans) hard = hard || std::string(stage->name) == "bend_hard";
  bin.cellsPerBrick = c.cellsPerBrick;
  bin.section = !c.section.empty() ? c.section : hard ? "rectangle" : "circle";
  bin.source = c.file.string();
  const auto t0 = std::chrono::steady_clock::now();
  beam::BeamRun run = beam::runBeam(bin);
  const fs::path beamDir = c.dir / "beam";
  fs::create_directories(beamDir);
  beam::MdemExportOptions ex;
  const std::string model = beam::mdemModelToml(run.brick, ex, "mDEM model written by `mesochain chain`");
  const std::string scene = beam::cantileverSceneToml(run.brick, ex);
  requireFiniteJson(run.report, (beamDir / "beam.json").string());
  writeFileAtomically((beamDir / ex.modelFile).string(), model);
  writeFileAtomically((beamDir / "cantilever.toml").string(), scene);
  for (const beam::FittedCurve& fc : run.curves) {
    std::string name = "fit-" + fc.label + ".png";
    std::replace(name.begin(), name.end(), ' ', '-');
    beam::writeFitPlot(fc, (beamDir / name).string());
  }
  writeFileAtomically((beamDir / "beam.json").string(), run.report.dump(2) + "\n");
  report["stages"].push_back({{"stage", "beam"}, {"status", "ran"}, {"seconds", secondsSince(t0)},
                              {"outputs", (beamDir / "beam.json").string()}});
  report["constants"] = run.report["constants"];
  report["beam"] = run.report["beam"];
  report["brick"] = run.report["brick"];
  if (run.report.contains("warnings")) report["warnings"] = run.report["warnings"];
  requireFiniteJson(report, (c.dir / "chain.json").string());
  writeFileAtomically((c.dir / "chain.json").string(), report.dump(2) + "\n");

  std::string md = fmt::format("# Chain report: {}\n\nFilament: `{}`; force tolerance {:g} Ha/Bohr; {} cells per brick.\n\n"
                               "| stage | status | seconds |\n|---|---|---|\n",
                               c.file.filename().string(), c.cellPath, c.forceTolerance, c.cellsPerBrick);
  for (const json& s : report["stages"])
    md += fmt::format("| {} | {} | {:.1f} |\n", s["stage"].get<std::string>(), s["status"].get<std::string>(),
                      s["seconds"].get<double>());
  md += "\n| constant | value | uncertainty | source |\n|---|---|---|---|\n";
  for (const auto& [key, v] : report["constants"].items())
    if (v.is_object())
      md += fmt::format("| {} | {:.8g} | {:.2g} | {} |\n", key, v["value"].get<double>(), v["uncertainty"].get<double>(),
                        v["source"].get<std::string>());
  md += fmt::format("\nBeam ({}, {} closure): Y = {:.6g} GPa, G = {:.6g} GPa. Brick: L = {:.6g} nm, mass {:.6g} ag. "
                    "Files: `beam/beam.json`, `beam/{}`, `beam/cantilever.toml` (run it with `mesochain dem`).\n",
                    run.beam.shape, run.beam.closure, report["beam"]["young_modulus_GPa"].get<double>(),
                    report["beam"]["shear_modulus_GPa"].get<double>(), report["brick"]["length_nm"].get<double>(),
                    report["brick"]["mass_ag"].get<double>(), ex.modelFile);
  if (report.contains("warnings"))
    for (const auto& w : report["warnings"]) md += "\nWarning: " + w.get<std::string>() + "\n";
  writeFileAtomically((c.dir / "chain.md").string(), md);
  for (const auto& [key, v] : report["constants"].items())
    if (v.is_object())
      std::cout << fmt::format("{:<22} {:.8g} +- {:.2g}\n", key, v["value"].get<double>(), v["uncertainty"].get<double>());
  std::cout << "wrote " << (c.dir / "chain.json").string() << ", " << (c.dir / "chain.md").string() << "\n";
  return 0;
}

}  // namespace mesochain::app
