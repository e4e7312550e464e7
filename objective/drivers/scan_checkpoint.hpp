#pragma once
// The checkpoint file of a deformation scan (JSON): the input hash and every completed point
// with its relaxed atoms, so that a resumed scan can skip it and warm-start its neighbours.
// Written atomically (common/atomic_file.hpp): the text goes to PATH.tmp.PID, which is then
// renamed over PATH, so an interruption leaves either the previous or the new checkpoint, never half of one.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "objective/drivers/scan.hpp"

namespace mesochain::objective {

// The point whose relaxation was under way: its plan index and key (deformation, or the ring's
// rotation order) and where its relaxation stood (RelaxSettings::snapshot).
struct PointInProgress {
  int index = -1;
  double deformation = 0.0;
  int rotationOrder = 0;
  RelaxProgress progress;
};

struct ScanCheckpoint {
  std::string inputHash;
  // scanIdentity (long values as their hash): names what changed when the hash differs; empty
  // in checkpoints of earlier versions.
  std::map<std::string, std::string> settings;
  ScanKind kind = ScanKind::Stretch;
  int planSize = 0;
  std::map<int, ScanPoint> completed;  // plan index -> point (with its relaxed cell)
  // Completed points whose deformation is no longer in the scan's list: kept (never deleted) so
  // that a later list holding them again reuses them, but not part of the curve.
  std::vector<ScanPoint> keptAside;
  // A point started but not finished (written every ScanSettings::snapshotSeconds of its
  // relaxation): a resumed scan continues it from there (no value: none, or an older checkpoint).
  std::optional<PointInProgress> inProgress;
};

// What identifies a planned point across deformation lists: stretch and twist points by their
// deformation value exactly (as written in the checkpoint), bend points by the ring's rotation
// order. Plan index 0 is the reference (always reused).
struct PlannedPoint {
  double deformation = 0.0;
  int rotationOrder = 0;
};

// Distributes the points of `old` (completed and kept aside) over the plan of the current
// list: a point whose key matches plan index k becomes completed[k] of the result; the others
// become its keptAside. The point in progress keeps its place when its key matches a plan index
// not completed (it gets that index), else it is dropped. The result carries `old`'s input hash
// and kind; planSize = plan.size().
ScanCheckpoint reuseCheckpoint(ScanCheckpoint old, const std::vector<PlannedPoint>& plan);

// Throws InputError naming `path` unless `old` was written for this input (scanInputHash of
// cell, calculator and settings): each changed setting with both values, or why a checkpoint of
// an earlier version cannot tell. `fix` says how to go on (e.g. "remove it to start afresh").
void requireCheckpointOfThisInput(const std::string& path, const ScanCheckpoint& old, const ObjectiveCell& cell,
                                  const dftb::CalculatorSettings& calculator, const ScanSettings& settings,
                                  const std::string& fix);

// Writes `checkpoint` (species taken from `speciesSource`, which has the cell's atoms).
void writeScanCheckpoint(const std::string& path, const ScanCheckpoint& checkpoint,
                         const ObjectiveCell& speciesSource);
// Reads a checkpoint; atoms get the species of `speciesSource`. InputError (naming the file)
// when it cannot be read, is not a scan checkpoint, or its atom count differs.
ScanCheckpoint readScanCheckpoint(const std::string& path, const ObjectiveCell& speciesSource);

// One point as the JSON text of its checkpoint entry, and back (all digits: the same doubles):
// how the points of one group of ranks reach the others in a distributed scan.
std::string scanPointText(int index, const ScanPoint& point);
std::pair<int, ScanPoint> scanPointFromText(const std::string& text,
                                            const ObjectiveCell& speciesSource);

}  // namespace mesochain::objective
