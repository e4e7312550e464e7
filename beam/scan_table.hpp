#pragma once
// Scan tables as written by `mesochain scan` (one curve per file), read by `mesochain beam`.
//
// JSON (format 1):
//   { "format": 1, "kind": "stretch" | "twist" | "bend", "direction": "soft" | "hard" (bend),
//     "T0_bohr": 4.6, "atoms_per_cell": 120, "thickness_bohr": 12.9 (optional),
//     "width_bohr": 80.0 (optional),
//     "deformation_unit": "strain" | "rad_per_cell" | "per_bohr" (must match the kind),
//     "points": [ { "deformation": 0.0, "energy_hartree": -123.4, "converged": true,
//                   "measured_curvature_per_bohr": 0.01 (bend, optional), ... } ] }
// Energies are per cell of length T0. Other point keys (forces, times, k-points) are kept out
// of the fit and ignored here.
// CSV: the same header keys as comment lines `# key = value` (or `# key: value`), then a
// header row naming the columns (deformation, energy_hartree required; converged,
// measured_curvature_per_bohr optional; others ignored), then one row per point.
#include <limits>
#include <string>
#include <vector>

namespace mesochain::beam {

struct ScanPoint {
  double deformation = 0.0;
  double energy = 0.0;  // Hartree per cell
  bool converged = true;
  double measuredCurvature = std::numeric_limits<double>::quiet_NaN();  // 1/Bohr (bend)
};

struct ScanCurve {
  std::string source;     // file name
  std::string kind;       // stretch, twist, bend
  std::string direction;  // soft, hard (bend); "" otherwise
  std::string deformationUnit;
  double cellLength = 0.0;  // T0, Bohr
  int atomsPerCell = 0;
  double thickness = std::numeric_limits<double>::quiet_NaN();  // Bohr, measured
  double width = std::numeric_limits<double>::quiet_NaN();      // Bohr, measured
  std::vector<ScanPoint> points;

  // "stretch", "twist", "bend soft", "bend hard".
  std::string label() const { return direction.empty() ? kind : kind + " " + direction; }
};

// The constant a curve gives, as `mesochain beam` names it: its symbol (C, K, D_s, D_h), the
// key of beam.json (Hartree units) and the unit.
struct CurveConstant {
  std::string name, key, unit;
};
CurveConstant curveConstant(const ScanCurve& curve);

// By extension: .json or .csv. Missing files, syntax errors and bad values are InputErrors
// naming the file and the key (or line).
ScanCurve readScanTable(const std::string& path);
ScanCurve parseScanJson(const std::string& text, const std::string& source);
ScanCurve parseScanCsv(const std::string& text, const std::string& source);

// The .json and .csv files of a folder, sorted.
std::vector<std::string> scanFilesIn(const std::string& directory);

}  // namespace mesochain::beam
