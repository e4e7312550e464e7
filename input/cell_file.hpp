#pragma once
// The objective-cell input file (TOML, format = 1): geometry, symmetry, k-points, electronic
// temperature, parameter tables, dispersion and task. Every key, unit and default is documented
// in docs/cell-file.md. Values in the file carry explicit units (Å, degrees, K, kcal/mol,
// Ha/Bohr); CellInput holds atomic units (Bohr, radians, Hartree).
#include <map>
#include <string>
#include <vector>

#include "dftb/band_structure.hpp"
#include "dftb/dispersion_table.hpp"
#include "dftb/scc_term.hpp"
#include "objective/core/cell.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::objective {

// Default C-C bond length of the [builder] table (Å).
inline constexpr double kDefaultBondLengthAngstrom = 1.42;
// Defaults of [builder] type = "collapsed" (Å): the graphite interlayer distance and starting
// radii of the dog-bone contour (the relaxation refines them).
inline constexpr double kDefaultCollapseInterlayerAngstrom = 3.4;
inline constexpr double kDefaultCollapseBulbRadiusAngstrom = 3.4;
inline constexpr double kDefaultCollapseTransitionRadiusAngstrom = 3.4;

struct TaskInput {
  std::string type = "energy";    // energy | forces | relax
  double forceTolerance = 1e-4;   // Hartree/Bohr (relax)
  int maxSteps = 500;             // relax
  bool relaxTranslation = false;  // relax: also optimise the screw translation T
};

struct CellInput {
  std::string source;  // the file path
  ObjectiveCell cell;
  // [kpoints] and [electrons] (dftb/band_table.hpp): helical k-points, angular sampling and the
  // electronic temperature k_B T in Hartree (input in K).
  dftb::BandSettings band;
  // "A-B" -> resolved path, for all ordered pairs of the species in the cell.
  std::map<std::string, std::string> parameterFiles;
  // The name of the parameter set when `[parameters] set = ...` was used (else empty).
  std::string parameterSet;
  std::map<std::string, int> maxAngularMomentum;  // optional per species: 0 = s, 1 = p, ...
  dftb::DispersionTable dispersion;  // [dispersion], read and written by dftb/dispersion_table.hpp
  dftb::SccSettings scc;  // [scc], read and written by dftb/scc_table.hpp
  TaskInput task;
};

CellInput readCellFile(const std::string& path);
// Writes a cell file that reads back to the same CellInput: inline atoms in Å, the symmetry,
// k-points, temperature, `set = parameterSet` (when non-empty) plus explicit entries for the
// tables that differ from the set, dispersion and task.
void writeCellFile(const std::string& path, const CellInput& input);

// The directory of the parameter sets in the source tree (the project's params/).
std::string parameterSetsDirectory();
// Where `[parameters] set = "NAME"` is looked for, in order: the folders of the environment
// variable MESOCHAIN_PARAMS_PATH (colon-separated), the installed sets beside the binary
// (PREFIX/share/mesochain/params for PREFIX/bin/mesochain, when present), the source tree's.
std::vector<std::string> parameterSetSearchPath();
// "A-B" -> PREFIX + "A-B.skf" for every ordered pair; InputError(source, where) naming `what`
// and the missing table otherwise.
std::map<std::string, std::string> tablesWithPrefix(const std::string& prefix,
                                                    const std::vector<std::string>& species,
                                                    const std::string& source, const std::string& where,
                                                    const std::string& what);
// "A-B" -> params/<set>/A-B.skf for every ordered pair of `species`; InputError naming
// `source` and `where` when the set or a table does not exist.
std::map<std::string, std::string> parameterSetFiles(const std::string& set,
                                                     const std::vector<std::string>& species,
                                                     const std::string& source,
                                                     const std::string& where);

}  // namespace mesochain::objective
