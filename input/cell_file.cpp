#include "input/cell_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <optional>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/electronic_temperature.hpp"
#include "common/toml_file.hpp"
#include "common/units.hpp"
#include "dftb/band_table.hpp"
#include "dftb/dispersion_table.hpp"
#include "dftb/scc_table.hpp"
#include "input/cell_document.hpp"
#include "input/cell_file_sections.hpp"
#include "input/text_reader.hpp"
#include "common/toml_table.hpp"
#include "objective/core/uff_parameters.hpp"

#ifndef MESOCHAIN_PARAMS_DIR
#error "MESOCHAIN_PARAMS_DIR must be defined (input/CMakeLists.txt)"
#endif
#ifndef MESOCHAIN_PROJECT_DIR
#error "MESOCHAIN_PROJECT_DIR must be defined (input/CMakeLists.txt)"
#endif

namespace mesochain::objective {

namespace fs = std::filesystem;

std::string parameterSetsDirectory() { return MESOCHAIN_PARAMS_DIR; }

std::vector<std::string> parameterSetSearchPath() {
  std::vector<std::string> path;
  if (const char* env = std::getenv("MESOCHAIN_PARAMS_PATH")) {
    std::stringstream list(env);
    for (std::string d; std::getline(list, d, ':');)
      if (!d.empty()) path.push_back(d);
  }
  // An installed binary (cmake --install): PREFIX/bin/mesochain finds PREFIX/share/mesochain/params.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && exe.has_parent_path()) {
    const fs::path installed = (exe.parent_path() / ".." / "share" / "mesochain" / "params").lexically_normal();
    if (fs::is_directory(installed, ec)) path.push_back(installed.string());
  }
  path.push_back(parameterSetsDirectory());
  return path;
}

std::map<std::string, std::string> parameterSetFiles(const std::string& set,
                                                     const std::vector<std::string>& species,
                                                     const std::string& source,
                                                     const std::string& where) {
  const bool plainName =
      !set.empty() && set != "." && set != ".." && std::all_of(set.begin(), set.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
      });
  const std::vector<std::string> search = parameterSetSearchPath();
  std::error_code ec;
  fs::path dir;
  if (plainName)
    for (const std::string& folder : search)
      if (fs::is_directory(fs::path(folder) / set, ec)) {
        dir = fs::path(folder) / set;
        break;
      }
  if (dir.empty()) {
    std::vector<std::string> sets;
    for (const std::string& folder : search)
      for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.is_directory() && std::find(sets.begin(), sets.end(), e.path().filename().string()) == sets.end())
          sets.push_back(e.path().filename().string());
    std::sort(sets.begin(), sets.end());
    std::string list, folders;
    for (const auto& s : sets) list += (list.empty() ? "" : ", ") + ("\"" + s + "\"");
    for (const auto& f : search) folders += (folders.empty() ? "" : ":") + f;
    throw InputError(source, where, "set \"" + set + "\"",
                     "the name of a parameter set in " + folders +
                         " (MESOCHAIN_PARAMS_PATH, the installed params, the source tree's): " +
                         (list.empty() ? "(none installed)" : list));
  }
  return tablesWithPrefix(dir.string() + "/", species, source, where, "set \"" + set + "\"");
}

std::map<std::string, std::string> tablesWithPrefix(const std::string& prefix,
                                                    const std::vector<std::string>& species,
                                                    const std::string& source, const std::string& where,
                                                    const std::string& what) {
  std::error_code ec;
  std::map<std::string, std::string> files;
  for (const auto& a : species)
    for (const auto& b : species) {
      const fs::path f = prefix + a + "-" + b + ".skf";
      if (!fs::is_regular_file(f, ec))
        throw InputError(source, where,
                         fmt::format("no table for the pair {}-{} in {} ({} is missing)", a, b, what,
                                     f.string()),
                         "a set with a table for every ordered pair of the elements of the "
                         "cell, or an explicit \"" +
                             a + "-" + b + "\" = \"path\" entry");
      files[a + "-" + b] = f.lexically_normal().string();
    }
  return files;
}

namespace {

// [parameters]: a set and/or explicit "A-B" = "path" entries, max_angular_momentum.
void readParameters(const TomlTable& root, CellInput& in) {
  const auto t = root.table("parameters");
  if (!t)
    root.missing("parameters",
                 "a table [parameters] with set = \"pbc-0-3\" or \"A-B\" = \"path\" entries");
  const std::vector<std::string>& species = in.cell.speciesNames;
  auto isSpecies = [&](const std::string& s) {
    return std::find(species.begin(), species.end(), s) != species.end();
  };
  for (const std::string& key : t->keys()) {
    if (key == "set" || key == "prefix" || key == "max_angular_momentum") continue;
    const auto dash = key.find('-');
    const bool pairKey = dash != std::string::npos && detail::isElementName(key.substr(0, dash)) &&
                         detail::isElementName(key.substr(dash + 1));
    if (!pairKey)
      t->fail(key, "an unknown key '" + key + "'",
              "one of the keys of [parameters]: set, prefix, max_angular_momentum, or element pairs "
              "such as \"C-H\" = \"path/C-H.skf\"");
    const std::string a = key.substr(0, dash), b = key.substr(dash + 1);
    if (!isSpecies(a) || !isSpecies(b))
      t->fail(key, "the pair " + key + " of an element that is not in the cell",
              "pairs of the elements of the cell only");
  }
  const fs::path cellDir = fs::path(in.source).parent_path();
  if (t->has("set") && t->has("prefix"))
    t->fail("prefix", "both set and prefix", "one of them: set = \"NAME\" (a parameter set) or prefix = \"FOLDER/\"");
  if (t->has("set")) {
    in.parameterSet = t->string("set", "the name of a parameter set such as \"pbc-0-3\"");
    in.parameterFiles = parameterSetFiles(in.parameterSet, species, in.source, t->where("set"));
  }
  if (t->has("prefix")) {
    // As DFTB+'s Type2FileNames Prefix: the tables are PREFIX + "A-B.skf", PREFIX relative to
    // the cell file's folder ("skf/" names skf/C-C.skf; "skf/pbc-" names skf/pbc-C-C.skf).
    const std::string prefix = t->string("prefix", "a path prefix of the tables such as \"skf/\"");
    if (prefix.empty()) t->fail("prefix", "an empty prefix", "a path prefix such as \"skf/\"");
    in.parameterFiles = tablesWithPrefix((cellDir / prefix).string(), species, in.source, t->where("prefix"),
                                         "prefix \"" + prefix + "\"");
  }
  for (const std::string& key : t->keys()) {
    if (key == "set" || key == "prefix" || key == "max_angular_momentum") continue;
    const std::string file = t->string(key, "the path of the .skf table (a string)");
    std::error_code ec;
    fs::path p = cellDir / file;
    if (!fs::is_regular_file(p, ec)) p = fs::path(MESOCHAIN_PROJECT_DIR) / file;
    if (file.empty() || !fs::is_regular_file(p, ec))
      t->fail(key,
              "\"" + file +
                  "\", which exists neither relative to the cell file nor to the "
                  "project root " MESOCHAIN_PROJECT_DIR,
              "the path of an existing .skf table");
    in.parameterFiles[key] = p.lexically_normal().string();
  }
  for (const auto& a : species)
    for (const auto& b : species)
      if (!in.parameterFiles.count(a + "-" + b))
        throw InputError(in.source, "table [" + t->name() + "]",
                         "no table for the element pair " + a + "-" + b,
                         "set = \"NAME\" or an entry \"" + a + "-" + b + "\" = \"path\"");
  if (const auto m = t->table("max_angular_momentum", "an inline table such as { C = \"p\", H = \"s\" }")) {
    for (const std::string& el : m->keys()) {
      if (!isSpecies(el))
        m->fail(el, "element " + el + ", which is not in the cell", "elements of the cell only");
      const std::string shell = m->string(el, "\"s\", \"p\", \"d\" or \"f\"");
      const std::string shells = "spdf";
      if (shell.size() != 1 || shells.find(shell[0]) == std::string::npos)
        m->fail(el, "\"" + shell + "\"", "\"s\", \"p\", \"d\" or \"f\"");
      in.maxAngularMomentum[el] = static_cast<int>(shells.find(shell[0]));
    }
  }
}

void readTask(const TomlTable& root, CellInput& in) {
  const auto t = root.table("task");
  if (!t) return;  // documented default: type = "energy"
  t->allowOnly({"type", "force_tolerance", "max_steps", "relax_translation"});
  TaskInput& task = in.task;
  task.type = t->string("type", "\"energy\", \"forces\" or \"relax\"");
  if (task.type != "energy" && task.type != "forces" && task.type != "relax")
    t->fail("type", "\"" + task.type + "\"", "\"energy\", \"forces\" or \"relax\"");
  if (task.type != "relax")
    for (const char* k : {"force_tolerance", "max_steps", "relax_translation"})
      if (t->has(k))
        t->fail(k, "a relaxation setting with type = \"" + task.type + "\"",
                "force_tolerance, max_steps and relax_translation only with type = \"relax\"");
  if (t->has("force_tolerance")) {
    task.forceTolerance = t->number("force_tolerance", "a positive force (Ha/Bohr)");
    if (!(task.forceTolerance > 0.0))
      t->fail("force_tolerance", fmt::format("{}", task.forceTolerance),
              "a positive force (Ha/Bohr)");
  }
  if (t->has("max_steps")) {
    const long n = t->integer("max_steps", "an integer from 1 to 100000000");
    if (n < 1 || n > 100000000L) t->fail("max_steps", std::to_string(n), "an integer from 1 to 100000000");
    task.maxSteps = static_cast<int>(n);
  }
  if (t->has("relax_translation")) {
    task.relaxTranslation = t->boolean("relax_translation", "true or false");
    if (task.relaxTranslation && in.cell.symmetry.isRing())
      t->fail("relax_translation", "true for a closed ring (translation 0)",
              "relax_translation = true only for a screw with translation > 0");
  }
}

}  // namespace

CellInput readCellFile(const std::string& path) {
  return readCellDocument(parseTomlFile(path, "cell file"), path);
}

CellInput readCellDocument(const toml::value& data, const std::string& path, const std::string& name) {
  CellInput in;
  in.source = path;
  if (!data.is_table())
    throw InputError(path, name.empty() ? "the document" : "key " + name, typeName(data),
                     "a table of the cell-file sections");
  const TomlTable root(path, data, name);
  root.allowOnly({"format", "geometry", "builder", "symmetry", "kpoints", "electrons", "parameters",
                  "dispersion", "scc", "task"});
  const long format = root.integer("format", "format = 1");
  if (format != 1) root.fail("format", std::to_string(format), "format = 1");

  detail::readStructure(root, in);
  const bool ring = in.cell.symmetry.isRing();
  if (const auto k = root.table("kpoints"))
    dftb::readKPointsTable(*k, ring, in.band);
  else if (!ring)  // a ring without [kpoints]: every angular quantum number, no helical k-points
    root.missing("kpoints", "a table [kpoints] with helical = N (the screw needs helical k-points)");
  const auto el = root.table("electrons");
  if (!el) root.missing("electrons", "a table [electrons] with temperature (K)");
  dftb::readElectronsTable(*el, in.band);

  readParameters(root, in);
  if (const auto d = root.table("dispersion"))  // default: no dispersion
    dftb::readDispersionTable(*d, in.cell.speciesNames, in.dispersion);
  if (const auto scc = root.table("scc")) dftb::readSccTable(*scc, in.scc);  // default: no SCC
  readTask(root, in);
  in.cell.validate(path, kMinimumAtomDistanceAngstrom * units::kAngstromInBohr);
  return in;
}

}  // namespace mesochain::objective
