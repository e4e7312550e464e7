#pragma once
// The scan input file (TOML, format = 1) of `mesochain scan`: the cell file it deforms, the
// kind of scan and its list of deformations (with explicit units), relaxation settings,
// dimensions, outputs and checkpoint. Every key is documented in docs/scan-file.md.
// Paths in the file are relative to the scan file.
#include <string>

#include "input/cell_file.hpp"
#include "objective/drivers/scan.hpp"

namespace mesochain::objective {

struct ScanInput {
  std::string source;        // the scan file
  CellInput cell;            // the cell file it names (its [task] is not used)
  ScanSettings settings;     // checkpointPath set; resume / stopAfter left to the caller
  std::string jsonPath;      // curve JSON (required)
  std::string csvPath;       // curve CSV (optional, "" = none)
  std::string structurePrefix;  // optional: write the relaxed cells as PREFIX-NNN.xyz
};

// Reads and validates the scan file and the cell file it names. InputError names the file
// and key of the first problem. The cell file is found relative to the scan file; the [output]
// paths are relative to `outputDir` (the command line's -o; "" is the working folder), never to
// the scan file's folder (docs/command-line.md: one output-folder convention).
ScanInput readScanFile(const std::string& path, const std::string& outputDir = "");

}  // namespace mesochain::objective
