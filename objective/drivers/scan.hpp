#pragma once
// Deformation scans of an objective cell (stretch, twist, bend), every point relaxed at fixed
// symmetry (objective/drivers/relax.hpp) and warm-started from its neighbour's relaxed atoms.
//
// The scan first relaxes the straight reference cell (optionally finding T0 where dF/dT = 0);
// that is the point of deformation 0 of every curve. Then, in this order:
//   stretch: T = T0 (1 + eps), twist = the cell's own twist gamma0; eps > 0 ascending from
//            the reference, then eps < 0 descending (each from its neighbour nearer 0); the z
//            coordinates are scaled affinely with T for the warm start.
//   twist:   T = T0, twist = gamma0 + dgamma (rad per cell), same order; the warm start turns
//            each atom about z by the change of twist times z / T0 (a uniform twist).
//   bend:    rings of N_a cells (T = 0, rotation by 2 pi / N_a; objective/core/ring_map.hpp)
//            with nominal radius R = N_a T0 / (2 pi) and nominal curvature 1/R; N_a descending
//            (curvature ascending), the first ring from the straight reference, each next one
//            unbent from its neighbour and rebent at the new radius. The measured curvature is
//            1 / (mean distance of the relaxed atoms from the ring axis).
// ScanPoint energies are Mermin free energies per objective cell (Hartree); for a ring, the
// total ring energy / N_a, i.e. per cell of the straight reference (the same atoms), so curves
// compare directly with the reference energy. The curve files (scan_output.hpp) multiply by
// cellsPerSlice: energies per slice of length T0 (N_a objective cells of a helical cell with
// rotation order N_a; one translational cell).
//
// A checkpoint (JSON) is written atomically (temporary file + rename) after every point, and
// during a long point every snapshotSeconds with where its relaxation stands; a scan
// resumed from it skips the completed points whose deformation is in the current list
// (restoring their relaxed atoms for warm starts), continues the point in progress from its
// snapshot (RelaxProgress: its atoms, the T search, the evaluations so far), computes the others,
// keeps the checkpointed points no longer listed aside in the file, and refuses a checkpoint whose
// input hash (all settings except the deformation list) differs from the current input. (Points
// computed by groups of MPI ranks, below, are checkpointed when finished only.)
//
// The SCC loop of a point starts from the converged charges of the point it is warm-started
// from (when this run computed that point with the same kind of cell, straight or ring), else
// from neutral atoms.
//
// Over MPI ranks (comm, docs/cluster.md): the reference is computed by all ranks (its k-points
// split over them); then the chains of the plan (stretch and twist: the points above and below
// the reference, each warm-started from its neighbour; a sector bend likewise; a ring bend is
// one chain) go round-robin to groups of ranks, each group splitting the k-points of its points.
// Points are the same bits as in a serial scan (the same warm starts, exact k sums). The groups
// exchange their points after every round (one point per group), rank 0 writes the checkpoint
// and reports the points in the order of the plan. With --stop-after, or a single chain, all
// ranks work on one point at a time.
#include <functional>
#include <map>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "dftb/calculator.hpp"
#include "objective/core/cell.hpp"
#include "objective/core/ring_map.hpp"
#include "objective/drivers/relax.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::objective {

enum class ScanKind { Stretch, Twist, Bend };

const char* scanKindName(ScanKind kind);          // "stretch" | "twist" | "bend"
const char* deformationUnit(ScanKind kind);       // "strain" | "rad_per_cell" | "per_bohr"
const char* bendDirectionName(BendDirection d);   // "soft" | "hard"

struct ScanPoint;
struct ScanReference;

struct ScanSettings {
  ScanKind kind = ScanKind::Stretch;
  BendDirection direction = BendDirection::Soft;  // bend only
  std::vector<double> values;        // stretch: strains; twist: rad per cell (added to gamma0)
  std::vector<int> rotationOrders;   // bend: N_a of the rings
  RelaxSettings relax;               // per point; relax.relaxTranslation applies to the reference
  AngularSampling ringAngular;       // angular quantum numbers of the rings (default: all)
  // > 0: measure thickness and width of the relaxed reference (measureCollapsed) with this
  // interlayer (Bohr); 0: a round cell, no dimensions reported.
  double dimensionsInterlayer = 0.0;
  // Free-form text that identifies the input beyond what the driver sees (e.g. parameter file
  // paths); part of the input hash.
  std::string identity;
  std::string checkpointPath;        // empty: no checkpoint
  // Inside a point's relaxation, the checkpoint is also written after an accepted step when this
  // much wall time has passed since the last write (the point in progress; 0: every step).
  double snapshotSeconds = 600.0;
  bool resume = false;               // read checkpointPath (if it exists) and continue
  int stopAfter = -1;                // >= 0: return after computing this many new points
  bool progressBar = true;           // draw common/progress_bar on stderr (when a terminal)
  // Called after each point of the list is computed or restored from the checkpoint, in the
  // order of the plan (the reference, index 0, first), with the point's index and the plan size:
  // the command line prints and flushes a table row per point (not only at the end).
  std::function<void(const ScanPoint& point, int index, int total)> pointDone;
  // A reference relaxed before (relaxScanReference, objective/drivers/scan_reference.hpp):
  // point 0 is taken from it instead of being relaxed again. Its referenceIdentity must equal
  // this scan's (same cell, calculator, relaxation and tables), else InputError naming its file.
  std::shared_ptr<const ScanReference> reference;
};

struct ScanPoint {
  double deformation = 0.0;  // strain, rad per cell, or nominal curvature (1/Bohr)
  int rotationOrder = 0;     // bend: N_a of the ring (0 for the straight reference)
  double energy = 0.0;       // Mermin free energy per cell, Hartree
  // The energy ledger of the final evaluation (dftb/energy_ledger.hpp): entry name -> Hartree
  // per cell (empty in checkpoints of earlier versions).
  std::map<std::string, double> energies;
  bool converged = false;
  double maxForce = 0.0;     // Hartree/Bohr at the final geometry
  double timeSeconds = 0.0;
  int helicalKPoints = 0;
  int angularPoints = 0;
  int evaluations = 0;
  double measuredCurvature = std::numeric_limits<double>::quiet_NaN();  // bend, 1/Bohr
  ObjectiveCell cell;        // the relaxed cell
};

// The relaxed straight reference of a scan (point 0, at T0 when relax.relaxTranslation) with
// the settings it was computed with: computed once (relaxScanReference) and handed to every
// scan of the same cell, calculator and relaxation (ScanSettings::reference; the scan file's
// key `reference`, docs/scan-file.md).
struct ScanReference {
  std::string source;                           // the file it was read from ("" if computed)
  std::map<std::string, std::string> identity;  // referenceIdentity of its input
  ScanPoint point;                              // deformation 0: the relaxed cell, its energy
};

struct ScanResult {
  ScanKind kind = ScanKind::Stretch;
  BendDirection direction = BendDirection::Soft;
  double translation0 = 0.0;   // T0, Bohr
  double twist0 = 0.0;         // the reference twist, rad per cell
  int atomsPerCell = 0;        // atoms of the objective cell
  // Objective cells in one slice of length T0: the reference's rotation order N_a (a helical
  // cell with C_{N_a} holds 1/N_a of the slice). Curve files report energies per slice.
  int cellsPerSlice = 1;
  double thickness = std::numeric_limits<double>::quiet_NaN();  // Bohr (when measured)
  double width = std::numeric_limits<double>::quiet_NaN();
  std::vector<ScanPoint> points;  // sorted by deformation (reference included)
  bool complete = false;          // false when stopped by stopAfter
  int computed = 0;               // points computed in this call (not restored)
  int reused = 0;                 // points of the list restored from the checkpoint
  int keptAside = 0;              // checkpointed points not in the list (kept in the file)
  std::string inputHash;
};

// The scan of `cell` (a straight cell) with `params` and `calculator` settings. For bend, the
// rings use one helical k-point and settings.ringAngular. Throws InputError for bad settings
// (duplicate or empty deformation lists, strains <= -1, N_a < 2, a cell that cannot be bent)
// or a mismatched checkpoint (naming the checkpoint file).
ScanResult runScan(const ObjectiveCell& cell, std::shared_ptr<const dftb::ParameterSet> params,
                   const dftb::CalculatorSettings& calculator, const ScanSettings& settings,
                   const parallel::Communicator& comm = parallel::Communicator::world());

// Every setting that determines a point's result, by name ("calculator.scc.mixing",
// "scan.relax.force_tolerance", ...; objective/drivers/settings_fields.hpp visits every member of
// the settings structs, so none can be left out), plus "cell" (its symmetry and atoms). The
// deformation list and how the run proceeds (checkpoint path, --stop-after) are not part of it.
// Values longer than 80 characters (the cell, the tables' contents) appear as "fnv1a HASH".
std::map<std::string, std::string> scanIdentity(const ObjectiveCell& cell,
                                                const dftb::CalculatorSettings& calculator,
                                                const ScanSettings& settings);
// The hash (16 hex digits, FNV-1a 64) of scanIdentity.
std::string scanInputHash(const ObjectiveCell& cell, const dftb::CalculatorSettings& calculator,
                          const ScanSettings& settings);
// The hashes earlier versions would give this input (formats 1 and 2, which left out the SCC
// settings and the dispersion summation): such a checkpoint is refused, saying why.
std::vector<std::string> legacyScanInputHashes(const ObjectiveCell& cell,
                                               const dftb::CalculatorSettings& calculator,
                                               const ScanSettings& settings);

}  // namespace mesochain::objective
