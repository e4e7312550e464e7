#include "objective/drivers/scan_reference.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/build_info.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "objective/drivers/scan_checkpoint.hpp"

namespace mesochain::objective {

using nlohmann::json;

std::map<std::string, std::string> referenceIdentity(const ObjectiveCell& cell,
                                                     const dftb::CalculatorSettings& calculator,
                                                     const ScanSettings& settings) {
  std::map<std::string, std::string> out;
  for (auto& [key, value] : scanIdentity(cell, calculator, settings))
    if (key.rfind("calculator.", 0) == 0 || key.rfind("scan.relax.", 0) == 0 ||
        key == "scan.identity" || key == "cell")
      out[key] = value;
  return out;
}

ScanReference relaxScanReference(const ObjectiveCell& cell,
                                 std::shared_ptr<const dftb::ParameterSet> params,
                                 const dftb::CalculatorSettings& calculator,
                                 const ScanSettings& settings,
                                 const parallel::Communicator& comm) {
  ScanSettings s = settings;
  // With a checkpoint path (the chain's reference.checkpoint.json), the reference's relaxation
  // is kept there as it goes and continued from it: a checkpoint of other settings is replaced.
  ScanReference out;
  out.identity = referenceIdentity(cell, calculator, settings);
  s.resume = !s.checkpointPath.empty() && std::filesystem::exists(s.checkpointPath);
  if (s.resume) {
    ScanCheckpoint old;
    bool same = false;
    try {
      old = readScanCheckpoint(s.checkpointPath, cell);
      same = old.inputHash == scanInputHash(cell, calculator, s);
    } catch (const InputError&) {
      same = false;  // unreadable, or of a cell with other atoms
    }
    if (!same) {
      std::cerr << fmt::format("mesochain: note: {} holds no reference of these settings; relaxing afresh\n",
                               s.checkpointPath);
      s.resume = false;
    } else if (old.completed.count(0)) {
      out.point = old.completed.at(0);  // relaxed before the stage could record it
      return out;
    }
  }
  s.reference = nullptr;
  s.pointDone = nullptr;
  s.stopAfter = 1;  // point 0, the reference, only
  // Any valid list: the plan is not computed beyond its reference.
  if (s.kind == ScanKind::Bend) {
    if (s.rotationOrders.empty()) s.rotationOrders = {2};
  } else if (s.values.empty()) {
    s.values = {0.01};
  }
  const ScanResult r = runScan(cell, std::move(params), calculator, s, comm);
  for (const ScanPoint& p : r.points) out.point = p;  // the only point
  return out;
}

std::string settingChanges(const std::map<std::string, std::string>& recorded,
                           const std::map<std::string, std::string>& now, const std::string& what) {
  std::string list;
  const auto add = [&list](const std::string& c) { list += (list.empty() ? "" : "; ") + c; };
  for (const auto& [key, value] : now) {
    const auto it = recorded.find(key);
    if (it == recorded.end())
      add(fmt::format("{} (not in the {}; now {})", key, what, value));
    else if (it->second != value)
      add(fmt::format("{} ({} {}, now {})", key, what, it->second, value));
  }
  for (const auto& [key, value] : recorded)
    if (!now.count(key)) add(fmt::format("{} (only in the {})", key, what));
  return list;
}

void requireSameReference(const ScanReference& reference,
                          const std::map<std::string, std::string>& identity) {
  const std::string changed = settingChanges(reference.identity, identity, "reference");
  if (!changed.empty())
    throw InputError(reference.source.empty() ? "<scan reference>" : reference.source, "key settings",
                     "a reference of other settings, changed: " + changed,
                     "the reference of this cell with the same calculator, relaxation and tables "
                     "(relax it again: remove the file or the key `reference`)");
}

void writeScanReference(const std::string& path, const ScanReference& r) {
  const ScanPoint& p = r.point;
  json j;
  j["format"] = 1;
  j["kind"] = "scan_reference";
  j["program"] = buildInfoJson();
  j["T0_bohr"] = p.cell.symmetry.translation();
  j["twist0_rad"] = p.cell.symmetry.twist();
  j["rotation_order"] = p.cell.symmetry.rotationOrder();
  j["atoms_per_cell"] = p.cell.atomCount();
  j["energy_hartree"] = p.energy;  // per objective cell
  j["converged"] = p.converged;
  j["max_force_hartree_per_bohr"] = p.maxForce;
  j["settings"] = r.identity;
  j["point"] = json::parse(scanPointText(0, p));
  requireFiniteJson(j, path);
  writeFileAtomically(path, j.dump(2) + "\n");
}

ScanReference readScanReference(const std::string& path, const ObjectiveCell& speciesSource) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "the reference file", "a file that cannot be read", "a reference JSON");
  std::stringstream text;
  text << in.rdbuf();
  const json j = json::parse(text.str(), nullptr, false);
  const char* expected = "a scan reference written by `mesochain chain` (format 1, kind \"scan_reference\")";
  if (j.is_discarded() || !j.is_object() || j.value("kind", "") != "scan_reference" || j.value("format", 0) != 1 ||
      !j.contains("point") || !j.contains("settings"))
    throw InputError(path, "the reference file", "not a scan reference", expected);
  ScanReference r;
  r.source = path;
  try {
    r.identity = j.at("settings").get<std::map<std::string, std::string>>();
  } catch (const json::exception&) {
    throw InputError(path, "key settings", "not a table of strings", expected);
  }
  try {
    r.point = scanPointFromText(j.at("point").dump(), speciesSource).second;
  } catch (const InputError& e) {
    throw InputError(path, "key point", e.what(), expected);
  }
  return r;
}

}  // namespace mesochain::objective
