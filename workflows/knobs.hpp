#pragma once
// The accuracy-against-time table of a finished scan's knobs (`mesochain bench knobs` and the
// knobs stage of `mesochain chain`; method in docs/benchmarks.md, "mesochain bench knobs").
//
// The relaxed cell of every curve point (the scan's [output] structures) is re-evaluated,
// energy only, at the scan's own settings (a consistency check: it must reproduce the curve)
// and then one knob at a time; each set of energies is fitted with the fitter and options of
// `mesochain beam` (beam/beam_run.hpp fitScanCurve). The relaxed energy is stationary in the
// atomic coordinates, so the change of a point's relaxed energy with a setting equals the
// change at fixed geometry to first order; the relaxation response is second order. The
// relaxation tolerance itself changes the geometry and is measured by comparing whole scans
// (compare curves).
//
// This is a workflow of two layers, the DFTB evaluations (objective/drivers) and the beam
// fitter (beam/), so it lives above both (workflows/), below the command line that calls it.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "beam/scan_table.hpp"
#include "dftb/calculator.hpp"
#include "objective/core/cell.hpp"
#include "input/scan_file.hpp"

namespace mesochain::workflows {

// A finished scan: its input, its curve (as the beam fitter reads it) and the relaxed cell of
// every curve point (PREFIX-NNN.xyz, in curve order).
struct FinishedScan {
  objective::ScanInput input;
  beam::ScanCurve curve;
  std::vector<objective::ObjectiveCell> cells;
  std::vector<std::string> structureFiles;
  int cellsPerSlice = 1;  // curve energies are per slice = cellsPerSlice objective cells
};

// Reads the scan file, its curve JSON and its structures. InputError when the scan file has no
// [output] structures, a structure file is missing (naming it), there are more or fewer
// structures than curve points, or a structure's symmetry does not give its point's
// deformation (stretch: T/T0 - 1; twist: gamma - gamma of the reference; bend: 2 pi/(N_a T0)
// for a ring or sector, 0 for the straight reference) or its energy.
// `scanOutputDir`: the -o folder the scan ran with ("" = the working folder), where its
// [output] files are.
FinishedScan readFinishedScan(const std::string& scanFile, const std::string& scanOutputDir = "");

// Where knob values came from, for errors: the command line ("<command line>", options
// "--kpoints", ...) or a chain file (its path, keys "knobs.kpoints", ...).
struct KnobSource {
  std::string source = "<command line>";
  std::string prefix = "--";
  std::string option(const std::string& knob) const { return prefix + knob; }
};

// One setting of one knob: how it changes the calculator settings of the straight (T > 0)
// points and of the ring (T = 0) points.
struct KnobSetting {
  std::string knob;      // "kpoints", "angular", "sampling", "dispersion", "temperature"
  std::string label;     // "24", "all", "cutoff:20", "ewald", "300"
  double accuracy = 0;   // larger = more accurate (the knob's reference is the largest)
  bool own = false;      // the scan's own setting
  std::function<void(dftb::CalculatorSettings& straight, dftb::CalculatorSettings& ring)> apply;
};

// The settings of each knob (comma-separated lists already split), the scan's own setting
// included (marked own, listed once), sorted from least to most accurate. A bad value is an
// InputError naming the option (where.option("kpoints"), ...).
std::vector<KnobSetting> kpointSettings(const std::vector<std::string>& values, int own,
                                        const KnobSource& where = {});
std::vector<KnobSetting> angularSettings(const std::vector<std::string>& values, int own,
                                         const KnobSource& where = {});
// Helical k-points of the straight points and ring angular samples together, "K:M" (a bend's
// rings stand for the straight cell's 2M kappa points, docs/scan-file.md: varying one alone
// mixes a sampling mismatch into the curve). Accuracy is K.
std::vector<KnobSetting> samplingSettings(const std::vector<std::string>& values, int ownKpoints,
                                          int ownAngular, const KnobSource& where = {});
std::vector<KnobSetting> dispersionSettings(const std::vector<std::string>& values,
                                            const dftb::DispersionSettings& own,
                                            const KnobSource& where = {});
std::vector<KnobSetting> temperatureSettings(const std::vector<std::string>& values,
                                             double ownHartree, const KnobSource& where = {});

// What to measure: the finished scan, the knobs' settings, curves of the same scan made
// otherwise, and the fitter's options (as `mesochain beam`).
struct KnobsRequest {
  std::string scanFile;
  std::string scanOutputDir;
  std::vector<std::string> kpoints, angular, sampling, dispersion, temperature, compare;
  double tolerance = 0.02;
  std::string linearTerm = "auto";
  bool measuredCurvature = false;
  bool forces = false;
  KnobSource where;
  bool progressBar = true;
};

constexpr double kKnobNaN = std::numeric_limits<double>::quiet_NaN();

// One row of the table: a setting of a knob (or a whole scan, knob "relaxation"), its fitted
// constant, the relative difference to the knob's most accurate setting, and its cost.
struct KnobRow {
  std::string knob, setting;
  bool own = false, reference = false;
  double constant = kKnobNaN, uncertainty = kKnobNaN, relative = kKnobNaN;
  double cpuPerEvaluation = kKnobNaN, wallPerEvaluation = kKnobNaN, totalWall = kKnobNaN;
  double maxForce = kKnobNaN;  // largest |force| on the structures at this setting, Ha/Bohr
  int evaluations = 0;
  std::string note;
};

struct KnobsTable {
  FinishedScan scan;
  std::vector<KnobRow> rows;
  std::vector<std::string> notes;  // knobs that do not apply to this scan, ...
  double largestDifference = 0;    // re-evaluated against curve energies, Ha per slice
  KnobRow fromCurve;               // the fit of the curve JSON itself
  double scanSeconds = 0;          // the scan's relaxation (curve JSON time_s summed)
  int scanEvaluations = 0;
  nlohmann::json header;           // the JSON output's keys besides "rows"
};

// Validates every knob value and compare curve before any evaluation (InputError), then
// evaluates and fits. Under MPI every rank computes the same table.
KnobsTable runKnobs(const KnobsRequest& request);

// The table as printed by `mesochain bench knobs` (header lines, one row per setting).
void printKnobsTable(std::ostream& out, const KnobsTable& table);
// The JSON (header, "rows", "program") and CSV of the table (docs/benchmarks.md).
nlohmann::json knobsJson(const KnobsTable& table);
std::string knobsCsv(const KnobsTable& table);
// |relative difference| against the CPU time per evaluation, one series per knob; false (and
// nothing written) when no row has a nonzero difference.
bool writeKnobsPlot(const KnobsTable& table, const std::string& png);

}  // namespace mesochain::workflows
