#pragma once
// `mesochain bench knobs`: the inputs of the benchmark (a finished scan with its relaxed
// structures; the knob settings from the command line). The benchmark itself is in
// app/bench_knobs.cpp; the method is in docs/benchmarks.md ("mesochain bench knobs").
#include <functional>
#include <string>
#include <vector>

#include "beam/scan_table.hpp"
#include "dftb/calculator.hpp"
#include "objective/core/cell.hpp"
#include "objective/drivers/scan_file.hpp"

namespace mesochain::app::knobs {

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

// One setting of one knob: how it changes the calculator settings of the straight (T > 0)
// points and of the ring (T = 0) points.
struct KnobSetting {
  std::string knob;      // "kpoints", "angular", "sampling", "dispersion", "temperature"
  std::string label;     // "24", "all", "cutoff:20", "ewald", "300"
  double accuracy = 0;   // larger = more accurate (the knob's reference is the largest)
  bool own = false;      // the scan's own setting
  std::function<void(dftb::CalculatorSettings& straight, dftb::CalculatorSettings& ring)> apply;
};

// The settings of each knob from the command line (comma-separated lists already split), the
// scan's own setting included (marked own, listed once), sorted from least to most accurate.
// A bad value is an InputError naming the option ("--kpoints", ...).
std::vector<KnobSetting> kpointSettings(const std::vector<std::string>& values, int own);
std::vector<KnobSetting> angularSettings(const std::vector<std::string>& values, int own);
// Helical k-points of the straight points and ring angular samples together, "K:M" (a bend's
// rings stand for the straight cell's 2M kappa points, docs/scan-file.md: varying one alone
// mixes a sampling mismatch into the curve). Accuracy is K.
std::vector<KnobSetting> samplingSettings(const std::vector<std::string>& values, int ownKpoints,
                                          int ownAngular);
std::vector<KnobSetting> dispersionSettings(const std::vector<std::string>& values,
                                            const dftb::DispersionSettings& own);
std::vector<KnobSetting> temperatureSettings(const std::vector<std::string>& values,
                                             double ownHartree);

}  // namespace mesochain::app::knobs
