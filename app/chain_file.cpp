#include "app/chain_file.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "beam/beam_run.hpp"
#include "common/errors.hpp"
#include "common/setting_entries.hpp"
#include "common/toml_file.hpp"
#include "common/toml_table.hpp"
#include "input/cell_document.hpp"

namespace mesochain::app {

namespace {

namespace fs = std::filesystem;

constexpr ScanStage kScanStages[] = {{"stretch", "stretch", ""},
                                     {"twist", "twist", ""},
                                     {"bend_soft", "bend", "soft"},
                                     {"bend_hard", "bend", "hard"}};

// A TOML string literal (basic string, escaped: common/setting_entries.hpp).
std::string quoted(const std::string& s) { return tomlStringText(s); }

// A stage table: the deformation keys of its scan file, passed on verbatim (the scan reader
// checks them, naming the generated STAGE.scan.toml), except what the chain sets itself.
void checkStageKeys(const TomlTable& t) {
  const std::string deformation = "the scan's deformation keys (strains, rotation_orders, ...) and a table [" +
                                  t.name() + ".dimensions]";
  for (const std::string& key : t.keys()) {
    if (key == "direction" || key == "kind" || key == "cell" || key == "reference")
      t.fail(key, "a key the chain sets itself", deformation);
    if (key != "dimensions" && t.at(key).is_table()) t.fail(key, "a table", deformation);
  }
}

// [knobs]: lists of settings as `mesochain bench knobs` takes them (numbers or strings).
ChainKnobs readKnobs(const TomlTable& t, const ChainFile& c) {
  t.allowOnly({"stages", "kpoints", "angular", "sampling", "dispersion", "temperature"});
  auto list = [&](const char* key) {
    return t.has(key) ? t.numbersOrStrings(key, "an array of settings, numbers or strings as bench knobs takes them")
                      : std::vector<std::string>{};
  };
  ChainKnobs k;
  k.given = true;
  std::string stages;
  for (const auto& [stage, keys] : c.scans) {
    stages += (stages.empty() ? "" : ", ") + std::string(stage->name);
    k.stages.push_back(stage->name);
  }
  const std::vector<std::string> listed =
      t.has("stages") ? t.strings("stages", "an array of scan stages of this chain file: " + stages)
                      : std::vector<std::string>{};
  for (const std::string& s : listed)
    if (std::none_of(c.scans.begin(), c.scans.end(), [&](const auto& p) { return s == p.first->name; }))
      t.fail("stages", "\"" + s + "\"", "scan stages of this chain file: " + stages);
  if (!listed.empty()) k.stages = listed;  // none listed: every scan stage
  k.kpoints = list("kpoints");
  k.angular = list("angular");
  k.sampling = list("sampling");
  k.dispersion = list("dispersion");
  k.temperature = list("temperature");
  return k;
}

}  // namespace

ChainFile readChainFile(const std::string& path) {
  const toml::value root = parseTomlFile(path, "chain file");
  const TomlTable t(path, root, "");
  t.allowOnly({"format", "cell", "output", "force_tolerance", "cells_per_brick", "section", "beam", "[stretch]",
               "[twist]", "[bend_soft]", "[bend_hard]", "[cantilever]", "[knobs]"});
  ChainFile c;
  c.file = fs::absolute(path);
  c.dir = c.file.parent_path() / "chain-out";
  if (t.integer("format", "format = 1") != 1) t.fail("format", describe(t.at("format")), "format = 1");
  if (t.has("output")) {
    const char* folder = "a folder for the stages, relative to the chain file";
    const std::string output = t.string("output", folder);
    if (output.empty()) t.fail("output", "an empty string", folder);
    c.dir = (c.file.parent_path() / output).lexically_normal();
  }
  const char* cellExpected =
      "cell = \"FILE.toml\", the filament's cell file, or a table [cell] holding its sections (docs/cell-file.md)";
  if (t.has("cell") && t.at("cell").is_table()) {
    // Checked here as the cell reader checks a cell file (keys named cell.KEY, lines of this file).
    const objective::CellInput cell = objective::readCellDocument(t.at("cell"), c.file.string(), "cell");
    c.inlineCell = t.at("cell");
    c.cellPath = (c.dir / "chain-cell.toml").string();
    if (t.at("cell").contains("parameters") && t.at("cell").at("parameters").is_table())
      for (const auto& [key, v] : t.at("cell").at("parameters").as_table())
        if (cell.parameterFiles.count(key)) c.inlineCellTables[key] = cell.parameterFiles.at(key);
  } else {
    c.cellPath = fs::absolute(c.file.parent_path() / t.string("cell", cellExpected)).lexically_normal().string();
  }
  c.forceTolerance = t.positiveOr("force_tolerance", c.forceTolerance, "a force tolerance > 0 (Ha/Bohr)");
  c.beam = t.booleanOr("beam", c.beam);
  if (t.has("cells_per_brick") || c.beam) {
    if (!t.has("cells_per_brick")) t.missing("cells_per_brick", "cells_per_brick = N, cells per brick (or beam = false)");
    c.cellsPerBrick = static_cast<int>(t.integerIn("cells_per_brick", 1, beam::kMaxCellsPerBrick));
  }
  c.section = t.oneOfOr("section", {"rectangle", "circle", "annulus"}, "");
  if (const auto cantilever = t.table("cantilever")) {
    cantilever->allowOnly({"tolerance"});
    const char* relative = "a relative tolerance in (0, 1)";
    c.cantileverTolerance = cantilever->numberOr("tolerance", c.cantileverTolerance, relative);
    if (!(c.cantileverTolerance > 0.0 && c.cantileverTolerance < 1.0))
      cantilever->fail("tolerance", describe(cantilever->at("tolerance")), relative);
  }
  for (const ScanStage& s : kScanStages)
    if (const auto stage = t.table(s.name, fmt::format("a table [{}] of scan keys", s.name))) {
      checkStageKeys(*stage);
      c.scans.emplace_back(&s, t.at(s.name));
    }
  if (c.scans.empty())
    throw InputError(path, "the scan stages", "no scan table",
                     "at least one of [stretch], [twist], [bend_soft], [bend_hard]");
  if (const auto knobs = t.table("knobs", "a table [knobs] of knob settings")) c.knobs = readKnobs(*knobs, c);
  return c;
}

std::string inlineCellText(const ChainFile& c) {
  toml::value cell = *c.inlineCell;
  const fs::path base = c.file.parent_path();
  auto absolute = [&](toml::value& v) {
    if (!v.is_string()) return;  // the reader has refused it already
    const fs::path p(v.as_string().str);
    if (!p.empty() && !p.is_absolute()) v = (base / p).string();
  };
  if (cell.contains("geometry") && cell.at("geometry").is_table() && cell.at("geometry").contains("file"))
    absolute(cell.at("geometry").at("file"));
  if (cell.contains("parameters") && cell.at("parameters").is_table())
    for (auto& [key, v] : cell.at("parameters").as_table()) {
      if (key == "prefix") absolute(v);
      // A table as the reader found it (beside the chain file, else in the project root).
      else if (c.inlineCellTables.count(key)) v = c.inlineCellTables.at(key);
    }
  return fmt::format("# the [cell] of {}, written by `mesochain chain`; docs/cell-file.md\n{}",
                     c.file.string(), toml::format(cell));
}

namespace {
nlohmann::json canonical(const toml::value& v) {
  if (v.is_table()) {
    nlohmann::json o = nlohmann::json::object();  // std::map: keys sorted
    for (const auto& [key, x] : v.as_table()) o[key] = canonical(x);
    return o;
  }
  if (v.is_array()) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& x : v.as_array()) a.push_back(canonical(x));
    return a;
  }
  if (v.is_boolean()) return v.as_boolean();
  if (v.is_integer()) return v.as_integer();
  if (v.is_floating()) return v.as_floating();
  if (v.is_string()) return v.as_string().str;
  return toml::format(v);  // dates and times: as written
}
}  // namespace

std::string inlineCellIdentity(const ChainFile& c) { return canonical(*c.inlineCell).dump(); }

std::string scanFileText(const ChainFile& c, const ScanStage& s, const toml::value& keys,
                         const std::string& outputName, bool withReference) {
  std::string t = fmt::format("# written by `mesochain chain {}`; docs/scan-file.md\nformat = 1\ncell = {}\nkind = \"{}\"\n",
                              c.file.filename().string(), quoted(c.cellPath), s.kind);
  if (*s.direction) t += fmt::format("direction = \"{}\"\n", s.direction);
  if (withReference) t += "reference = \"reference.json\"\n";
  std::string dimensions;
  for (const auto& [k, v] : keys.as_table()) {
    if (k == "dimensions" && v.is_table()) {  // [STAGE.dimensions] -> the scan's [dimensions]
      for (const auto& [dk, dv] : v.as_table()) dimensions += dk + " = " + toml::format(dv) + "\n";
      continue;
    }
    t += k + " = " + toml::format(v) + "\n";  // checked by readChainFile (checkStageKeys)
  }
  if (!dimensions.empty()) t += "[dimensions]\n" + dimensions;
  t += fmt::format("[relax]\nforce_tolerance = {:.17g}\n[output]\njson = \"{}.json\"\ncsv = \"{}.csv\"\n"
                   "checkpoint = \"{}.checkpoint.json\"\nstructures = \"structures/{}\"\n",
                   c.forceTolerance, outputName, outputName, outputName, outputName);
  return t;
}

std::string chainHash(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;
  return fmt::format("{:016x}", h);
}

}  // namespace mesochain::app
