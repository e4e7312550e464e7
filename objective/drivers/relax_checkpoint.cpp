#include "objective/drivers/relax_checkpoint.hpp"

#include "common/errors.hpp"
#include "objective/drivers/scan.hpp"
#include "objective/drivers/scan_checkpoint.hpp"

namespace mesochain::objective {

namespace {

// A one-point "scan" of the cell: point 0 relaxed with these settings (its translation searched
// when relax.relaxTranslation), which is what the relaxation is.
ScanSettings asScan(const RelaxInput& in) {
  ScanSettings s;
  s.relax = in.relax;
  s.relax.progress = nullptr;
  s.relax.snapshot = nullptr;
  s.relax.resumeFrom = nullptr;
  s.identity = in.tables;
  s.progressBar = false;
  return s;
}

}  // namespace

void writeRelaxCheckpoint(const std::string& path, const RelaxInput& in, const RelaxProgress& progress) {
  const ScanSettings s = asScan(in);
  ScanCheckpoint c;
  c.inputHash = scanInputHash(in.cell, in.calculator, s);
  c.settings = scanIdentity(in.cell, in.calculator, s);
  c.kind = s.kind;
  c.planSize = 1;
  c.inProgress = PointInProgress{0, 0.0, 0, progress};
  writeScanCheckpoint(path, c, in.cell);
}

std::shared_ptr<const RelaxProgress> readRelaxCheckpoint(const std::string& path, const RelaxInput& in) {
  const ScanSettings s = asScan(in);
  const ScanCheckpoint c = readScanCheckpoint(path, in.cell);
  requireCheckpointOfThisInput(path, c, in.cell, in.calculator, s, "remove it to start the relaxation afresh");
  if (!c.inProgress || c.planSize != 1)
    throw InputError(path, "key in_progress", "no relaxation in progress (a scan's checkpoint?)",
                     "the checkpoint of this relaxation (the same cell, calculator, relaxation and tables)");
  return std::make_shared<const RelaxProgress>(c.inProgress->progress);
}

}  // namespace mesochain::objective
