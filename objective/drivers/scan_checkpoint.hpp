#pragma once
// The checkpoint file of a deformation scan (JSON): the input hash and every completed point
// with its relaxed atoms, so that a resumed scan can skip it and warm-start its neighbours.
// Written atomically: the text goes to PATH.tmp, which is then renamed over PATH, so an
// interruption leaves either the previous or the new checkpoint, never half of one.
#include <map>
#include <string>

#include "objective/drivers/scan.hpp"

namespace mesochain::objective {

struct ScanCheckpoint {
  std::string inputHash;
  ScanKind kind = ScanKind::Stretch;
  int planSize = 0;
  std::map<int, ScanPoint> completed;  // plan index -> point (with its relaxed cell)
};

// Writes `checkpoint` (species taken from `speciesSource`, which has the cell's atoms).
void writeScanCheckpoint(const std::string& path, const ScanCheckpoint& checkpoint,
                         const ObjectiveCell& speciesSource);
// Reads a checkpoint; atoms get the species of `speciesSource`. InputError (naming the file)
// when it cannot be read, is not a scan checkpoint, or its atom count differs.
ScanCheckpoint readScanCheckpoint(const std::string& path, const ObjectiveCell& speciesSource);

}  // namespace mesochain::objective
