#pragma once
// The straight reference of deformation scans, relaxed once and shared (issue 15, item 1:
// `mesochain chain` relaxes it and finds T0 before its scans; a scan file names it with the key
// `reference`, docs/scan-file.md). It is point 0 of runScan, computed by runScan itself (the
// same relaxation and T0 search), and carries the settings it was computed with so that a scan
// of other settings refuses it.
#include <map>
#include <memory>
#include <string>

#include "objective/drivers/scan.hpp"

namespace mesochain::objective {

// The entries of scanIdentity that determine the reference: the calculator settings
// ("calculator.*"), the relaxation ("scan.relax.*"), the tables ("scan.identity") and the cell.
// Scans of any kind, direction or list with the same ones share the reference.
std::map<std::string, std::string> referenceIdentity(const ObjectiveCell& cell,
                                                     const dftb::CalculatorSettings& calculator,
                                                     const ScanSettings& settings);

// Relaxes the reference of the scan `settings` (runScan stopped after its point 0: the straight
// cell relaxed at fixed symmetry, T0 searched when settings.relax.relaxTranslation). With a
// checkpoint path in `settings`, the relaxation is kept there as it goes (snapshotSeconds) and a
// later call continues it, or returns the reference recorded there when it was finished; a
// checkpoint of other settings is replaced (a note on stderr). Resume, list and given reference
// of `settings` are not used.
ScanReference relaxScanReference(const ObjectiveCell& cell,
                                 std::shared_ptr<const dftb::ParameterSet> params,
                                 const dftb::CalculatorSettings& calculator,
                                 const ScanSettings& settings,
                                 const parallel::Communicator& comm = parallel::Communicator::world());

// Throws InputError naming reference.source and every setting that differs from `identity`.
void requireSameReference(const ScanReference& reference,
                          const std::map<std::string, std::string>& identity);

// "KEY (WHAT OLD, now NEW); ..." for the entries that differ between a recorded identity (`what`:
// "checkpoint", "reference") and the current one; "" when they are equal.
std::string settingChanges(const std::map<std::string, std::string>& recorded,
                           const std::map<std::string, std::string>& now, const std::string& what);

// The reference file (JSON, format 1, written atomically): T0, twist, energy per cell, the
// settings identity and the relaxed cell (docs/scan-file.md, "The shared reference").
void writeScanReference(const std::string& path, const ScanReference& reference);
// Reads it back; atoms get the species of `speciesSource` (the scan's cell). InputError naming
// the file when it is not a reference file or its atom count differs.
ScanReference readScanReference(const std::string& path, const ObjectiveCell& speciesSource);

}  // namespace mesochain::objective
