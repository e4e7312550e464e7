#pragma once
// The `mesochain beam` workflow as a library call: curves and/or given constants -> fitted
// constants -> beam (chosen closure, alternatives with residuals) -> brick -> JSON report and
// mDEM files. Every number in the report carries its unit in its key (docs/beam.md).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "beam/beam_model.hpp"
#include "beam/brick.hpp"
#include "beam/curve_fit.hpp"
#include "beam/scan_table.hpp"

namespace mesochain::beam {

// One constant given directly, with its standard uncertainty (0 when unknown).
struct GivenConstant {
  double value = 0.0;
  double uncertainty = 0.0;
  std::string source;
};

// How the bend fits set U(0) (docs/beam.md): "anchored" (default) fixes it at the energy of the
// straight reference, the table's point at curvature 0 or `referenceEnergy` (Hartree per cell,
// for tables of rings alone); "free" fits it. A table with neither is fitted with U(0) free and
// a warning.
struct BendAnchor {
  std::string offset = "anchored";
  std::optional<double> referenceEnergy;
};

// Integer limits of the inputs (int fields; larger values would wrap): a brick of 1e7 cells is
// ~1 mm of tube, far beyond a DEM element; 1e8 atoms per cell exceeds any DFTB cell.
inline constexpr long long kMaxCellsPerBrick = 10'000'000;
inline constexpr long long kMaxAtomsPerCell = 100'000'000;

struct BeamInputs {
  std::vector<ScanCurve> curves;
  // Constants given directly (atomic units), keyed "C", "K", "D_s", "D_h".
  std::optional<GivenConstant> stretch, twist, bendSoft, bendHard;
  std::optional<double> cellLength;  // T0, Bohr
  std::optional<int> atomsPerCell;
  std::optional<double> cellMass;    // dalton; default atoms_per_cell * 12.011
  std::optional<double> thickness;   // measured h, Bohr (overrides the scans')
  int cellsPerBrick = 0;             // required (> 0)
  std::string closure = "four_constants";  // or "measured_thickness" (rectangle)
  std::string section = "rectangle";       // or "circle", "annulus"
  double wall = 3.4 * 1.8897261246257702;  // annulus wall, Bohr (3.4 Å)
  std::string linearTerm = "auto";   // auto (twist and stretch yes, bend no), "on", "off"
  bool measuredCurvature = false;    // bend: fit against the measured curvature
  double tolerance = 0.02;           // FitOptions::relativeTolerance
  BendAnchor bendAnchor;             // how U(0) of the bends is set (anchored by default)
  std::string source = "<command line>";
};

// One curve as fitted: the points the fit saw (x after --measured-curvature), its options and
// result (for plots, beam/fit_plot.hpp).
struct FittedCurve {
  std::string quantity;         // "C", "K", "D_s", "D_h"
  std::string reportKey;        // "C_hartree", ... (the key in report["constants"])
  std::string label;            // "stretch", "bend soft", ...
  std::string source;           // file name
  std::string deformationUnit;  // "strain", "rad_per_cell", "per_bohr"
  std::vector<CurvePoint> points;  // converged points, as fitted
  int unconvergedSkipped = 0;
  std::vector<std::string> warnings;  // e.g. a bend fitted with U(0) free for want of a reference
  FitOptions options;
  QuadraticFit fit;
};

struct BeamRun {
  std::vector<FittedCurve> curves;  // in input order
  BeamConstants constants;
  BeamConstants uncertainties;  // standard uncertainties (0 when unknown)
  Beam beam;                    // the chosen closure
  std::vector<Beam> alternatives;
  Brick brick;
  nlohmann::json report;
};

// Fits one scan curve (unconverged points left out; bends against the measured curvature when
// asked). linearTerm: "auto" (on for stretch and twist, off for bends), "on" or "off".
// Bends: U(0) as `anchor` says.
FittedCurve fitScanCurve(const ScanCurve& curve, const std::string& quantity, const std::string& reportKey,
                         double tolerance, const std::string& linearTerm, bool measuredCurvature,
                         const BendAnchor& anchor = {});

// The energy of the straight reference of a bend table: its converged point at deformation 0
// (nullopt when it has none, e.g. a sector cell's table or rings alone).
std::optional<double> straightReferenceEnergy(const ScanCurve& curve);

// Throws InputError for missing, duplicated or inconsistent inputs and refused curves.
BeamRun runBeam(const BeamInputs& inputs);

// Reads the constants file (TOML, format = 1; keys in docs/beam.md) into `inputs`.
void readConstantsFile(const std::string& path, BeamInputs& inputs);

}  // namespace mesochain::beam
