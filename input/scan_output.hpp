#pragma once
// The energy-against-deformation table of a scan, as JSON (read by the beam fitter; format
// documented in docs/scan-file.md) and CSV with the same columns. Units are in the key names:
// energies in Hartree per slice of length T0 (ScanResult::cellsPerSlice objective cells; see
// objective/drivers/scan.hpp), atoms_per_cell likewise per slice, lengths in Bohr, time in
// seconds. PNG plots of a curve come from the plot library (hook: app/cmd_scan.cpp).
#include <string>

#include <nlohmann/json.hpp>

#include "objective/drivers/scan.hpp"

namespace mesochain::objective {

nlohmann::json scanCurveJson(const ScanResult& result);
std::string scanCurveCsv(const ScanResult& result);
// Writes the JSON and/or CSV (an empty path skips that file); InputError when unwritable.
void writeScanCurve(const ScanResult& result, const std::string& jsonPath,
                    const std::string& csvPath);
// The relaxed cell of every point as PREFIX-NNN.xyz, in curve order, with its energy (the scan
// file's [output] structures; read back by `mesochain bench knobs`). "" writes nothing.
void writeScanStructures(const ScanResult& result, const std::string& prefix);

}  // namespace mesochain::objective
