#include "app/chain_file.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "beam/beam_run.hpp"
#include "common/errors.hpp"
#include "common/setting_entries.hpp"
#include "common/toml_file.hpp"

namespace mesochain::app {

namespace {

namespace fs = std::filesystem;

constexpr ScanStage kScanStages[] = {{"stretch", "stretch", ""},
                                     {"twist", "twist", ""},
                                     {"bend_soft", "bend", "soft"},
                                     {"bend_hard", "bend", "hard"}};

// A TOML string literal (basic string, escaped: common/setting_entries.hpp).
std::string quoted(const std::string& s) { return tomlStringText(s); }

std::string line(const toml::value& v) { return fmt::format("(line {})", v.location().line()); }

// [knobs]: lists of settings as `mesochain bench knobs` takes them (numbers or strings).
ChainKnobs readKnobs(const std::string& where, const toml::value& t, const ChainFile& c) {
  ChainKnobs k;
  k.given = true;
  const char* allowed = "stages, kpoints, angular, sampling, dispersion, temperature";
  for (const auto& [key, v] : t.as_table()) {
    const std::string at = fmt::format("key knobs.{} {}", key, line(v));
    if (!v.is_array()) throw InputError(where, at, toml::format(v), "an array of settings");
    std::vector<std::string> values;
    for (const toml::value& e : v.as_array()) {
      if (e.is_string()) values.push_back(e.as_string().str);
      else if (e.is_integer()) values.push_back(std::to_string(e.as_integer()));
      else if (e.is_floating()) values.push_back(fmt::format("{}", e.as_floating()));
      else throw InputError(where, at, toml::format(e), "numbers or strings, as bench knobs takes them");
    }
    if (key == "stages") {
      for (const std::string& s : values)
        if (std::none_of(c.scans.begin(), c.scans.end(), [&](const auto& p) { return s == p.first->name; }))
          throw InputError(where, at, "\"" + s + "\"", "scan stages of this chain file");
      k.stages = values;
    } else if (key == "kpoints") k.kpoints = values;
    else if (key == "angular") k.angular = values;
    else if (key == "sampling") k.sampling = values;
    else if (key == "dispersion") k.dispersion = values;
    else if (key == "temperature") k.temperature = values;
    else throw InputError(where, at, "an unknown key", allowed);
  }
  if (k.stages.empty())
    for (const auto& [stage, keys] : c.scans) k.stages.push_back(stage->name);
  return k;
}

}  // namespace

ChainFile readChainFile(const std::string& path) {
  const toml::value root = parseTomlFile(path, "chain file");
  ChainFile c;
  c.file = fs::absolute(path);
  c.dir = c.file.parent_path() / "chain-out";
  const std::string where = path;
  bool format = false, cell = false;
  const toml::value* knobs = nullptr;
  for (const auto& [key, v] : root.as_table()) {
    const std::string at = fmt::format("key {} {}", key, line(v));
    if (key == "format") {
      if (!v.is_integer() || v.as_integer() != 1) throw InputError(where, at, toml::format(v), "format = 1");
      format = true;
    } else if (key == "cell") {
      if (!v.is_string()) throw InputError(where, at, "not a string", "the path of a cell file (docs/cell-file.md)");
      c.cellPath = fs::absolute(c.file.parent_path() / v.as_string().str).lexically_normal().string();
      cell = true;
    } else if (key == "output") {
      if (!v.is_string() || v.as_string().str.empty()) throw InputError(where, at, "not a path", "a folder for the stages");
      c.dir = (c.file.parent_path() / v.as_string().str).lexically_normal();
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
    } else if (key == "beam") {
      if (!v.is_boolean()) throw InputError(where, at, toml::format(v), "true or false");
      c.beam = v.as_boolean();
    } else if (key == "cantilever") {
      if (!v.is_table()) throw InputError(where, at, "not a table", "a table [cantilever] with tolerance");
      for (const auto& [ck, cv] : v.as_table()) {
        const std::string cat = fmt::format("key cantilever.{} {}", ck, line(cv));
        if (ck != "tolerance") throw InputError(where, cat, "an unknown key", "tolerance");
        const double x = cv.is_floating() ? cv.as_floating() : -1.0;
        if (!(x > 0.0 && x < 1.0)) throw InputError(where, cat, toml::format(cv), "a relative tolerance in (0, 1)");
        c.cantileverTolerance = x;
      }
    } else if (key == "knobs") {
      if (!v.is_table()) throw InputError(where, at, "not a table", "a table [knobs] of knob settings");
      knobs = &v;
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
                         "format, cell, output, force_tolerance, cells_per_brick, section, beam, [stretch], [twist], "
                         "[bend_soft], [bend_hard], [cantilever], [knobs]");
    }
  }
  if (!format) throw InputError(where, "key format", "nothing", "format = 1");
  if (!cell) throw InputError(where, "key cell", "nothing", "cell = \"FILE.toml\" (the filament)");
  if (c.cellsPerBrick == 0 && c.beam)
    throw InputError(where, "key cells_per_brick", "nothing", "cells_per_brick = N (or beam = false)");
  if (c.scans.empty()) throw InputError(where, "stages", "no scan table", "at least [stretch] (and [twist], [bend_soft])");
  std::stable_sort(c.scans.begin(), c.scans.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (knobs) c.knobs = readKnobs(where, *knobs, c);
  return c;
}

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
    if (k == "direction" || k == "kind" || k == "cell" || k == "reference" || v.is_table())
      throw InputError(c.file.string(), fmt::format("key {}.{} (line {})", s.name, k, v.location().line()),
                       "a key the chain sets itself", "the scan's deformation keys (strains, rotation_orders, ...)");
    t += k + " = " + toml::format(v) + "\n";
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
