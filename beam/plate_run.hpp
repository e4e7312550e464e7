#pragma once
// `mesochain beam plate`: bending rigidity of N-layer graphene against N, compared with the
// bonded plate (beam/plate.hpp) and with freely sliding layers, N D1 (the lower bound).
//
// Each stack (N layers) gives its rigidity either as a bend scan table (U = 1/2 D_cell (1/R)^2
// per cell, fitted as in `mesochain beam`; the plate rigidity per unit width is
// D = D_cell / a with a the middle-layer area per cell, T0 x width_bohr of the table or given),
// or directly. The plate file (TOML, format = 1; keys in docs/beam.md) also gives C2, Z0, nu
// and optionally D1 (else the N = 1 stack's). Atomic units inside (Hartree, Bohr).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "beam/beam_run.hpp"
#include "common/plot/canvas.hpp"

namespace mesochain::beam {

struct PlateStack {
  int layers = 0;
  std::optional<ScanCurve> scan;            // a bend table, or
  std::optional<GivenConstant> rigidity;    // D (Hartree) given directly
  std::optional<double> areaPerCell;        // Bohr^2; default T0 x width of the table
  std::optional<double> spacing;            // Bohr: this stack's measured mean interlayer
                                            // spacing for its bonded bound; default Z0
  std::string source;                       // where the stack was declared
};

struct PlateInputs {
  double inPlaneStiffness = 0.0;  // C2, Hartree / Bohr^2 (per layer)
  double spacing = 0.0;           // Z0, Bohr
  double poisson = 0.0;           // nu
  std::optional<GivenConstant> singleLayer;  // D1, Hartree; default: the N = 1 stack
  int maxLayers = 0;              // range of the curves; 0: max(6, largest N)
  std::vector<PlateStack> stacks;
  double tolerance = 0.02;        // FitOptions::relativeTolerance
  bool measuredCurvature = false;
  std::string source = "<command line>";
};

struct PlateStackResult {
  int layers = 0;
  double rigidity = 0.0, uncertainty = 0.0;  // Hartree
  std::string source;
  std::optional<FittedCurve> curve;          // when fitted from a scan
  double areaPerCell = 0.0;                  // Bohr^2 (scan only): D = D_cell / area
  double spacing = 0.0;                      // Bohr: the spacing of its bonded bound
};

struct PlateRun {
  double singleLayer = 0.0, singleLayerUncertainty = 0.0;  // D1, Hartree
  std::vector<int> layers;               // 1 .. maxLayers
  std::vector<double> bonded, sliding;   // Hartree, per entry of `layers`
  std::vector<PlateStackResult> stacks;  // sorted by N
  nlohmann::json report;
};

// Throws InputError for missing or inconsistent inputs and refused curves.
PlateRun runPlate(const PlateInputs& inputs);

// Reads the plate file; scan paths are relative to the file's folder.
void readPlateFile(const std::string& path, PlateInputs& inputs);

// D against N on a log axis: bonded plate, sliding bound, and the stacks with their error bars.
plot::Image renderPlatePlot(const PlateRun& run, int width = 900, int height = 650);

}  // namespace mesochain::beam
