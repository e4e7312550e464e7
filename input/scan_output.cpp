#include "input/scan_output.hpp"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "common/build_info.hpp"
#include "common/atomic_file.hpp"
#include "common/finite_output.hpp"
#include "common/errors.hpp"
#include "input/xyz_file.hpp"

namespace mesochain::objective {

using nlohmann::json;

json scanCurveJson(const ScanResult& r) {
  json j;
  j["format"] = 1;
  j["program"] = buildInfoJson();
  j["kind"] = scanKindName(r.kind);
  if (r.kind == ScanKind::Bend) j["direction"] = bendDirectionName(r.direction);
  j["T0_bohr"] = r.translation0;
  j["atoms_per_cell"] = r.atomsPerCell * r.cellsPerSlice;
  if (!std::isnan(r.thickness)) j["thickness_bohr"] = r.thickness;
  if (!std::isnan(r.width)) j["width_bohr"] = r.width;
  j["deformation_unit"] = deformationUnit(r.kind);
  j["points"] = json::array();
  for (const ScanPoint& p : r.points) {
    json q;
    q["deformation"] = p.deformation;
    q["energy_hartree"] = p.energy * r.cellsPerSlice;
    json ledger = json::object();
    for (const auto& [name, value] : p.energies) ledger[name] = value * r.cellsPerSlice;
    q["energies_hartree"] = ledger;
    q["converged"] = p.converged;
    q["max_force_hartree_per_bohr"] = p.maxForce;
    q["time_s"] = p.timeSeconds;
    q["helical_kpoints"] = p.helicalKPoints;
    q["angular_points"] = p.angularPoints;
    q["evaluations"] = p.evaluations;
    // The straight reference of a bend curve has curvature 0, measured and nominal.
    if (r.kind == ScanKind::Bend)
      q["measured_curvature_per_bohr"] = std::isnan(p.measuredCurvature) ? 0.0 : p.measuredCurvature;
    j["points"].push_back(q);
  }
  return j;
}

std::string scanCurveCsv(const ScanResult& r) {
  const bool bend = r.kind == ScanKind::Bend;
  // The header lines of the curve JSON as "# key = value" (beam/scan_table.hpp reads them, so
  // `mesochain beam` takes this CSV as it takes the JSON).
  std::string s = "# format = 1\n";
  s += fmt::format("# program = {}\n", versionLine());
  s += fmt::format("# kind = {}\n", scanKindName(r.kind));
  if (bend) s += fmt::format("# direction = {}\n", bendDirectionName(r.direction));
  s += fmt::format("# T0_bohr = {:.17g}\n", r.translation0);
  s += fmt::format("# atoms_per_cell = {}\n", r.atomsPerCell * r.cellsPerSlice);
  if (!std::isnan(r.thickness)) s += fmt::format("# thickness_bohr = {:.17g}\n", r.thickness);
  if (!std::isnan(r.width)) s += fmt::format("# width_bohr = {:.17g}\n", r.width);
  s += fmt::format("# deformation_unit = {}\n", deformationUnit(r.kind));
  s +=
      "deformation,energy_hartree,converged,max_force_hartree_per_bohr,time_s,helical_kpoints,"
      "angular_points,evaluations";
  s += bend ? ",measured_curvature_per_bohr\n" : "\n";
  for (const ScanPoint& p : r.points) {
    s += fmt::format("{:.17g},{:.17g},{},{:.6e},{:.3f},{},{},{}", p.deformation, p.energy * r.cellsPerSlice,
                     p.converged ? "true" : "false", p.maxForce, p.timeSeconds, p.helicalKPoints,
                     p.angularPoints, p.evaluations);
    if (bend)
      s += fmt::format(",{:.17g}", std::isnan(p.measuredCurvature) ? 0.0 : p.measuredCurvature);
    s += "\n";
  }
  return s;
}

void writeScanCurve(const ScanResult& r, const std::string& jsonPath, const std::string& csvPath) {
  const nlohmann::json j = scanCurveJson(r);
  requireFiniteJson(j, jsonPath.empty() ? std::string("the scan curve") : jsonPath);
  if (!jsonPath.empty()) writeFileAtomically(jsonPath, j.dump(2) + "\n");
  if (!csvPath.empty()) writeFileAtomically(csvPath, scanCurveCsv(r));
}

void writeScanStructures(const ScanResult& r, const std::string& prefix) {
  if (prefix.empty()) return;
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    XyzExtras extras;
    extras.energy = r.points[k].energy;
    writeXyzFile(fmt::format("{}-{:03d}.xyz", prefix, k), r.points[k].cell, extras);
  }
}

}  // namespace mesochain::objective
