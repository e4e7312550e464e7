#include "beam/scan_table.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/csv.hpp"
#include "common/errors.hpp"

namespace mesochain::beam {

namespace {
// As beam::kMaxAtomsPerCell: atoms_per_cell is an int.
constexpr double kMaxTableAtomsPerCell = 1e8;
}  // namespace


namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string expectedUnit(const std::string& kind) {
  if (kind == "stretch") return "strain";
  if (kind == "twist") return "rad_per_cell";
  return "per_bohr";
}

// Checks the header fields common to both formats.
void validateHeader(ScanCurve& c) {
  const std::string& s = c.source;
  if (c.kind != "stretch" && c.kind != "twist" && c.kind != "bend")
    throw InputError(s, "key kind", "\"" + c.kind + "\"", "\"stretch\", \"twist\" or \"bend\"");
  if (c.kind == "bend") {
    if (c.direction != "soft" && c.direction != "hard")
      throw InputError(s, "key direction", c.direction.empty() ? "nothing" : "\"" + c.direction + "\"",
                       "\"soft\" or \"hard\" for a bend scan");
  } else if (!c.direction.empty() && c.direction != "none") {
    throw InputError(s, "key direction", "\"" + c.direction + "\"", "no direction for a " + c.kind + " scan");
  } else {
    c.direction.clear();
  }
  if (c.deformationUnit != expectedUnit(c.kind))
    throw InputError(s, "key deformation_unit", "\"" + c.deformationUnit + "\"",
                     "\"" + expectedUnit(c.kind) + "\" for a " + c.kind + " scan");
  if (!std::isfinite(c.cellLength) || c.cellLength <= 0.0)
    throw InputError(s, "key T0_bohr", std::to_string(c.cellLength), "a length > 0 (Bohr)");
  if (c.atomsPerCell < 1)
    throw InputError(s, "key atoms_per_cell", std::to_string(c.atomsPerCell), "an integer >= 1");
  for (const char* k : {"thickness_bohr", "width_bohr"}) {
    const double v = std::string(k) == "thickness_bohr" ? c.thickness : c.width;
    if (!std::isnan(v) && !(std::isfinite(v) && v > 0.0))
      throw InputError(s, std::string("key ") + k, std::to_string(v), "a length > 0 (Bohr)");
  }
  if (c.points.empty()) throw InputError(s, "key points", "no points", "at least one point");
}

double jsonNumber(const json& j, const std::string& key, const std::string& source, const std::string& where) {
  if (!j.contains(key)) throw InputError(source, where + key, "nothing", "a number");
  const json& v = j.at(key);
  if (!v.is_number()) throw InputError(source, where + key, v.dump(), "a number");
  const double x = v.get<double>();
  requireFinite(x, source, where + key);
  return x;
}

std::string jsonString(const json& j, const std::string& key, const std::string& source, bool required) {
  if (!j.contains(key)) {
    if (required) throw InputError(source, "key " + key, "nothing", "a string");
    return "";
  }
  if (!j.at(key).is_string()) throw InputError(source, "key " + key, j.at(key).dump(), "a string");
  return j.at(key).get<std::string>();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\"");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\"");
  return s.substr(b, e - b + 1);
}

double csvNumber(const std::string& text, const std::string& source, const std::string& where) {
  std::size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw InputError(source, where, "\"" + text + "\"", "a number");
  requireFinite(x, source, where);
  return x;
}

}  // namespace

ScanCurve parseScanJson(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(source, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) throw InputError(source, "the top level", j.type_name(), "a JSON object");
  ScanCurve c;
  c.source = source;
  const double format = jsonNumber(j, "format", source, "key ");
  if (format != 1.0) throw InputError(source, "key format", std::to_string(format), "1");
  c.kind = jsonString(j, "kind", source, true);
  c.direction = jsonString(j, "direction", source, false);
  c.deformationUnit = jsonString(j, "deformation_unit", source, true);
  c.cellLength = jsonNumber(j, "T0_bohr", source, "key ");
  const double atoms = jsonNumber(j, "atoms_per_cell", source, "key ");
  if (atoms != std::floor(atoms) || !(atoms >= 1 && atoms <= kMaxTableAtomsPerCell))
    throw InputError(source, "key atoms_per_cell", fmt::format("{}", atoms),
                     fmt::format("an integer from 1 to {:.0f}", kMaxTableAtomsPerCell));
  c.atomsPerCell = static_cast<int>(atoms);
  if (j.contains("thickness_bohr") && !j.at("thickness_bohr").is_null())
    c.thickness = jsonNumber(j, "thickness_bohr", source, "key ");
  if (j.contains("width_bohr") && !j.at("width_bohr").is_null()) c.width = jsonNumber(j, "width_bohr", source, "key ");
  if (!j.contains("points") || !j.at("points").is_array())
    throw InputError(source, "key points", j.contains("points") ? j.at("points").type_name() : "nothing",
                     "an array of points");
  const json& pts = j.at("points");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::string where = "points[" + std::to_string(i) + "].";
    if (!pts[i].is_object()) throw InputError(source, "key " + where, pts[i].dump(), "an object");
    ScanPoint p;
    p.deformation = jsonNumber(pts[i], "deformation", source, "key " + where);
    p.energy = jsonNumber(pts[i], "energy_hartree", source, "key " + where);
    if (pts[i].contains("converged")) {
      if (!pts[i].at("converged").is_boolean())
        throw InputError(source, "key " + where + "converged", pts[i].at("converged").dump(), "true or false");
      p.converged = pts[i].at("converged").get<bool>();
    }
    if (pts[i].contains("measured_curvature_per_bohr") && !pts[i].at("measured_curvature_per_bohr").is_null())
      p.measuredCurvature = jsonNumber(pts[i], "measured_curvature_per_bohr", source, "key " + where);
    c.points.push_back(p);
  }
  validateHeader(c);
  return c;
}

ScanCurve parseScanCsv(const std::string& text, const std::string& source) {
  ScanCurve c;
  c.source = source;
  std::map<std::string, std::string> header;
  std::vector<std::string> columns;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  auto column = [&](const std::string& name) {
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
  };
  int colX = -1, colE = -1, colConv = -1, colCurv = -1;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty()) continue;
    const std::string where = "line " + std::to_string(lineNo);
    if (t[0] == '#') {
      const std::string body = t.substr(1);
      const auto sep = body.find_first_of("=:");
      if (sep != std::string::npos) header[trim(body.substr(0, sep))] = trim(body.substr(sep + 1));
      continue;
    }
    std::vector<std::string> cells;
    if (!csvParseRecord(t, cells))
      throw InputError(source, where, "a malformed CSV record: " + t, "comma-separated fields quoted as RFC 4180");
    for (std::string& cell : cells) cell = trim(cell);
    if (columns.empty()) {
      columns = cells;
      colX = column("deformation");
      colE = column("energy_hartree");
      colConv = column("converged");
      colCurv = column("measured_curvature_per_bohr");
      if (colX < 0 || colE < 0)
        throw InputError(source, where, "columns " + t, "a header row with deformation and energy_hartree");
      continue;
    }
    if (cells.size() != columns.size())
      throw InputError(source, where, std::to_string(cells.size()) + " values",
                       std::to_string(columns.size()) + " values, one per column");
    ScanPoint p;
    p.deformation = csvNumber(cells[colX], source, where + ", column deformation");
    p.energy = csvNumber(cells[colE], source, where + ", column energy_hartree");
    if (colConv >= 0) {
      const std::string& v = cells[colConv];
      if (v == "true" || v == "1") p.converged = true;
      else if (v == "false" || v == "0") p.converged = false;
      else throw InputError(source, where + ", column converged", "\"" + v + "\"", "true, false, 1 or 0");
    }
    if (colCurv >= 0 && !cells[colCurv].empty())
      p.measuredCurvature = csvNumber(cells[colCurv], source, where + ", column measured_curvature_per_bohr");
    c.points.push_back(p);
  }
  auto get = [&](const std::string& k) { return header.count(k) ? header[k] : std::string(); };
  if (get("format") != "" && get("format") != "1") throw InputError(source, "header format", get("format"), "1");
  c.kind = get("kind");
  c.direction = get("direction");
  c.deformationUnit = get("deformation_unit");
  if (get("T0_bohr").empty()) throw InputError(source, "header T0_bohr", "nothing", "# T0_bohr = <Bohr>");
  c.cellLength = csvNumber(get("T0_bohr"), source, "header T0_bohr");
  if (get("atoms_per_cell").empty())
    throw InputError(source, "header atoms_per_cell", "nothing", "# atoms_per_cell = <integer>");
  const double atoms = csvNumber(get("atoms_per_cell"), source, "header atoms_per_cell");
  if (atoms != std::floor(atoms) || !(atoms >= 1 && atoms <= kMaxTableAtomsPerCell))
    throw InputError(source, "header atoms_per_cell", get("atoms_per_cell"),
                     fmt::format("an integer from 1 to {:.0f}", kMaxTableAtomsPerCell));
  c.atomsPerCell = static_cast<int>(atoms);
  if (!get("thickness_bohr").empty()) c.thickness = csvNumber(get("thickness_bohr"), source, "header thickness_bohr");
  if (!get("width_bohr").empty()) c.width = csvNumber(get("width_bohr"), source, "header width_bohr");
  validateHeader(c);
  return c;
}

ScanCurve readScanTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the scan table (missing or unreadable)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".json") return parseScanJson(buffer.str(), path);
  if (ext == ".csv") return parseScanCsv(buffer.str(), path);
  throw InputError(path, "file extension", "\"" + ext + "\"", ".json or .csv");
}

std::vector<std::string> scanFilesIn(const std::string& directory) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(directory, ec)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".json" || ext == ".csv")) files.push_back(e.path().string());
  }
  if (ec) throw InputError(directory, "cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

CurveConstant curveConstant(const ScanCurve& c) {
  if (c.kind == "stretch") return {"C", "C_hartree", "Ha"};
  if (c.kind == "twist") return {"K", "K_hartree_per_rad2", "Ha/rad^2"};
  if (c.direction == "hard") return {"D_h", "D_hard_hartree_bohr2", "Ha Bohr^2"};
  return {"D_s", "D_soft_hartree_bohr2", "Ha Bohr^2"};
}

}  // namespace mesochain::beam
