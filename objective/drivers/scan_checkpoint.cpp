#include "objective/drivers/scan_checkpoint.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "common/units.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::objective {

using nlohmann::json;

namespace {

json cellJson(const ObjectiveCell& cell) {
  const Symmetry& s = cell.symmetry;
  json j = {{"translation_bohr", s.translation()},
            {"twist_rad", s.twist()},
            {"symmetry_rotation_order", s.rotationOrder()}};
  json pos = json::array();
  for (int a = 0; a < cell.atomCount(); ++a)
    pos.push_back({cell.positions(0, a), cell.positions(1, a), cell.positions(2, a)});
  j["positions_bohr"] = pos;
  return j;
}

// The cell of a checkpoint entry, with the species of speciesSource, checked as a read geometry
// (json exceptions pass to the caller).
ObjectiveCell readCell(const json& cj, const std::string& path, const std::string& what,
                       const ObjectiveCell& speciesSource) {
  const json& pos = cj.at("positions_bohr");
  if (static_cast<int>(pos.size()) != speciesSource.atomCount())
    throw InputError(path, what, fmt::format("{} atoms instead of {}", pos.size(), speciesSource.atomCount()),
                     "a checkpoint written by mesochain scan (format 1)");
  ObjectiveCell cell;
  cell.speciesNames = speciesSource.speciesNames;
  cell.species = speciesSource.species;
  cell.positions.resize(3, speciesSource.atomCount());
  for (int a = 0; a < speciesSource.atomCount(); ++a)
    for (int k = 0; k < 3; ++k) cell.positions(k, a) = pos.at(a).at(k).get<double>();
  cell.symmetry = Symmetry::fromParameters(cj.at("translation_bohr").get<double>(),
                                           cj.at("twist_rad").get<double>(),
                                           cj.at("symmetry_rotation_order").get<int>(), path.c_str());
  // The restored atoms warm-start other points: checked as a read geometry is.
  cell.validate(path + ", " + what, kMinimumAtomDistanceAngstrom * units::kAngstromInBohr);
  return cell;
}

json inProgressJson(const PointInProgress& q) {
  const RelaxProgress& p = q.progress;
  json history = json::array();
  for (const RelaxStep& h : p.history)
    history.push_back({{"translation_bohr", h.translation},
                       {"free_energy_hartree", h.freeEnergy},
                       {"max_force_hartree_per_bohr", h.maxForce},
                       {"axial_force_hartree_per_bohr", h.axialForce}});
  const TranslationSearch& t = p.search;
  return {{"index", q.index},
          {"deformation", q.deformation},
          {"rotation_order", q.rotationOrder},
          {"evaluations", p.evaluations},
          {"relaxations", history},
          {"translation_search",
           {{"iteration", t.iteration}, {"t0", t.t0}, {"g0", t.g0}, {"t1", t.t1},
            {"bracketed", t.bracketed}, {"ta", t.ta}, {"ga", t.ga}, {"tb", t.tb}, {"gb", t.gb},
            {"side", t.side}}},
          {"cell", cellJson(p.cell)}};
}

PointInProgress readInProgress(const json& e, const std::string& path, const ObjectiveCell& speciesSource) {
  PointInProgress q;
  q.index = e.at("index").get<int>();
  q.deformation = e.at("deformation").get<double>();
  q.rotationOrder = e.at("rotation_order").get<int>();
  RelaxProgress& p = q.progress;
  p.evaluations = e.at("evaluations").get<int>();
  for (const json& h : e.at("relaxations"))
    p.history.push_back({h.at("translation_bohr").get<double>(), h.at("free_energy_hartree").get<double>(),
                         h.at("max_force_hartree_per_bohr").get<double>(),
                         h.at("axial_force_hartree_per_bohr").get<double>()});
  const json& t = e.at("translation_search");
  TranslationSearch& s = p.search;
  s.iteration = t.at("iteration").get<int>();
  s.t0 = t.at("t0").get<double>(), s.g0 = t.at("g0").get<double>(), s.t1 = t.at("t1").get<double>();
  s.bracketed = t.at("bracketed").get<bool>();
  s.ta = t.at("ta").get<double>(), s.ga = t.at("ga").get<double>();
  s.tb = t.at("tb").get<double>(), s.gb = t.at("gb").get<double>();
  s.side = t.at("side").get<int>();
  p.cell = readCell(e.at("cell"), path, "the point in progress", speciesSource);
  return q;
}

json pointJson(int index, const ScanPoint& p) {
  json j;
  j["index"] = index;
  j["deformation"] = p.deformation;
  j["rotation_order"] = p.rotationOrder;
  j["energy_hartree"] = p.energy;
  j["energies_hartree"] = p.energies;
  j["converged"] = p.converged;
  j["max_force_hartree_per_bohr"] = p.maxForce;
  j["time_s"] = p.timeSeconds;
  j["helical_kpoints"] = p.helicalKPoints;
  j["angular_points"] = p.angularPoints;
  j["evaluations"] = p.evaluations;
  j["measured_curvature_per_bohr"] =
      std::isnan(p.measuredCurvature) ? json(nullptr) : json(p.measuredCurvature);
  j["cell"] = cellJson(p.cell);
  return j;
}

// One entry of "completed" or "kept_aside" (json exceptions pass to the caller).
std::pair<int, ScanPoint> readPoint(const json& e, const std::string& path,
                                    const ObjectiveCell& speciesSource) {
  ScanPoint p;
  const int index = e.at("index").get<int>();
  p.deformation = e.at("deformation").get<double>();
  p.rotationOrder = e.at("rotation_order").get<int>();
  p.energy = e.at("energy_hartree").get<double>();
  if (e.contains("energies_hartree"))
    p.energies = e.at("energies_hartree").get<std::map<std::string, double>>();
  p.converged = e.at("converged").get<bool>();
  p.maxForce = e.at("max_force_hartree_per_bohr").get<double>();
  p.timeSeconds = e.at("time_s").get<double>();
  p.helicalKPoints = e.at("helical_kpoints").get<int>();
  p.angularPoints = e.at("angular_points").get<int>();
  p.evaluations = e.at("evaluations").get<int>();
  const json& mc = e.at("measured_curvature_per_bohr");
  p.measuredCurvature = mc.is_null() ? std::nan("") : mc.get<double>();
  p.cell = readCell(e.at("cell"), path, fmt::format("completed point with index {}", index), speciesSource);
  return std::make_pair(index, std::move(p));
}

}  // namespace

std::string scanPointText(int index, const ScanPoint& point) {
  return pointJson(index, point).dump();
}

std::pair<int, ScanPoint> scanPointFromText(const std::string& text,
                                            const ObjectiveCell& speciesSource) {
  try {
    return readPoint(json::parse(text), "<scan point>", speciesSource);
  } catch (const json::exception& e) {
    throw InputError("<scan point>", std::string("a malformed scan point (") + e.what() + ")");
  }
}

ScanCheckpoint reuseCheckpoint(ScanCheckpoint old, const std::vector<PlannedPoint>& plan) {
  ScanCheckpoint out;
  out.inputHash = old.inputHash;
  out.settings = std::move(old.settings);
  out.kind = old.kind;
  out.planSize = static_cast<int>(plan.size());
  std::vector<ScanPoint> candidates = std::move(old.keptAside);
  for (auto& [index, p] : old.completed) {
    if (index == 0 && !plan.empty())
      out.completed[0] = std::move(p);  // the reference, whatever the list
    else
      candidates.push_back(std::move(p));
  }
  const bool bend = old.kind == ScanKind::Bend;
  for (ScanPoint& p : candidates) {
    int match = -1;
    for (int k = 1; k < static_cast<int>(plan.size()) && match < 0; ++k) {
      const bool same = bend ? p.rotationOrder == plan[k].rotationOrder
                             : p.deformation == plan[k].deformation;
      if (same && !out.completed.count(k)) match = k;
    }
    if (match >= 0)
      out.completed[match] = std::move(p);
    else
      out.keptAside.push_back(std::move(p));
  }
  if (old.inProgress) {
    PointInProgress& q = *old.inProgress;
    for (int k = 0; k < static_cast<int>(plan.size()); ++k) {
      const bool same = k == 0 ? q.index == 0
                        : bend ? q.index != 0 && q.rotationOrder == plan[k].rotationOrder
                               : q.index != 0 && q.deformation == plan[k].deformation;
      if (same && !out.completed.count(k)) {
        q.index = k;
        out.inProgress = std::move(q);
        break;
      }
    }
  }
  return out;
}

void writeScanCheckpoint(const std::string& path, const ScanCheckpoint& c,
                         const ObjectiveCell& /*speciesSource*/) {
  json j;
  j["format"] = 1;
  j["what"] = "mesochain scan checkpoint";
  j["input_hash"] = c.inputHash;
  j["settings"] = c.settings;
  j["kind"] = scanKindName(c.kind);
  j["plan_size"] = c.planSize;
  j["completed"] = json::array();
  for (const auto& [index, p] : c.completed) j["completed"].push_back(pointJson(index, p));
  j["kept_aside"] = json::array();
  for (const ScanPoint& p : c.keptAside) j["kept_aside"].push_back(pointJson(-1, p));
  if (c.inProgress) j["in_progress"] = inProgressJson(*c.inProgress);
  requireFiniteJson(j, path);
  writeFileAtomically(path, j.dump(1) + "\n");
}

ScanCheckpoint readScanCheckpoint(const std::string& path, const ObjectiveCell& speciesSource) {
  std::ifstream f(path);
  if (!f) throw InputError(path, "cannot open the checkpoint file");
  json j;
  try {
    j = json::parse(f);
  } catch (const std::exception& e) {
    throw InputError(path, "the whole file", std::string("invalid JSON (") + e.what() + ")",
                     "a checkpoint written by mesochain scan");
  }
  const auto bad = [&](const std::string& where, const std::string& found) {
    throw InputError(path, where, found, "a checkpoint written by mesochain scan (format 1)");
  };
  if (!j.is_object() || j.value("what", "") != "mesochain scan checkpoint")
    bad("key what", "another kind of JSON file");
  if (j.value("format", 0) != 1) bad("key format", j["format"].dump());
  ScanCheckpoint c;
  try {
    c.inputHash = j.at("input_hash").get<std::string>();
    if (j.contains("settings"))
      c.settings = j.at("settings").get<std::map<std::string, std::string>>();
    const std::string kind = j.at("kind").get<std::string>();
    c.kind = kind == "stretch" ? ScanKind::Stretch
             : kind == "twist" ? ScanKind::Twist
             : kind == "bend"  ? ScanKind::Bend
                               : (bad("key kind", kind), ScanKind::Stretch);
    c.planSize = j.at("plan_size").get<int>();
    for (const json& e : j.at("completed")) {
      auto [index, p] = readPoint(e, path, speciesSource);
      c.completed[index] = std::move(p);
    }
    if (j.contains("kept_aside"))
      for (const json& e : j.at("kept_aside")) c.keptAside.push_back(readPoint(e, path, speciesSource).second);
    if (j.contains("in_progress")) c.inProgress = readInProgress(j.at("in_progress"), path, speciesSource);
  } catch (const json::exception& e) {
    bad("its contents", std::string("a missing or mistyped entry (") + e.what() + ")");
  }
  return c;
}

}  // namespace mesochain::objective
