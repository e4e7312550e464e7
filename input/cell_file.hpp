#pragma once
// The objective-cell input file (TOML, format = 1): geometry, symmetry, k-points, electronic
// temperature, parameter tables, dispersion and task. Every key, unit and default is documented
// in docs/cell-file.md. Values in the file carry explicit units (Å, degrees, K, kcal/mol,
// Ha/Bohr); CellInput holds atomic units (Bohr, radians, Hartree).
#include <map>
#include <string>
#include <vector>

#include "dftb/scc_term.hpp"
#include "objective/core/cell.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::objective {

// Defaults of model = "lj" (E(r) = epsilon [(r0/r)^12 - 2 (r0/r)^6], minimum -epsilon at r0).
inline constexpr double kDefaultLjEpsilonKcalPerMol = 0.069;
inline constexpr double kDefaultLjR0Angstrom = 3.80;
// At 30 Å the neglected r^-6 tail of a graphene-like sheet (0.38 atoms/Å^2) is
// pi * sigma * epsilon * r0^6 / r_c^4 ~ 3e-4 kcal/mol per atom; see docs/cell-file.md.
inline constexpr double kDefaultLjCutoffAngstrom = 30.0;
// The largest cutoff accepted (the image list grows with it; see readDispersion).
inline constexpr double kMaximumLjCutoffAngstrom = 1000.0;
// Default C-C bond length of the [builder] table (Å).
inline constexpr double kDefaultBondLengthAngstrom = 1.42;
// Defaults of [builder] type = "collapsed" (Å): the graphite interlayer distance and starting
// radii of the dog-bone contour (the relaxation refines them).
inline constexpr double kDefaultCollapseInterlayerAngstrom = 3.4;
inline constexpr double kDefaultCollapseBulbRadiusAngstrom = 3.4;
inline constexpr double kDefaultCollapseTransitionRadiusAngstrom = 3.4;

// Defaults of model = "kc" (dftb/dispersion_kc.hpp): the bond graph's covalent cutoff (Å) and
// the largest cutoff accepted (Å).
inline constexpr double kDefaultKcBondCutoffAngstrom = 1.7;
inline constexpr double kMaximumKcCutoffAngstrom = 100.0;

// Per-element Lennard-Jones parameters ([dispersion] parameters = "uff" or elements = {...}).
struct LjElementInput {
  double epsilon = 0;  // Hartree, well depth
  double r0 = 0;       // Bohr, position of the minimum
};

struct DispersionInput {
  std::string model = "none";  // "none" | "lj" | "kc"
  double epsilon = 0;          // Hartree (lj: one parameter set for every pair; 0 with `elements`)
  double r0 = 0;               // Bohr (lj)
  // lj: "" (epsilon, r0 or explicit elements) | "uff" (objective/core/uff_parameters.hpp)
  std::string parameters;
  // lj, per element of the cell, when non-empty (then epsilon = r0 = 0): pairs combine by
  // geometric means, as DFTB+ (dftb::DispersionSettings).
  std::map<std::string, LjElementInput> elements;
  double cutoff = 0;           // Bohr (lj; kc: 0 = the parameter set's)
  std::string summation = "cutoff";  // r^-6 tail: "cutoff" | "ewald" (lj)
  double ewaldTolerance = 1e-8;      // relative, with summation = "ewald" (lj)
  std::string kcParameters = "kc2005";  // kc: "kc2005" | "ouyang2018"
  double kcTaperStart = -1;             // Bohr (kc; < 0 = the parameter set's)
  double kcBondCutoff = 0;              // Bohr (kc)
};

struct TaskInput {
  std::string type = "energy";    // energy | forces | relax
  double forceTolerance = 1e-4;   // Hartree/Bohr (relax)
  int maxSteps = 500;             // relax
  bool relaxTranslation = false;  // relax: also optimise the screw translation T
};

struct CellInput {
  std::string source;  // the file path
  ObjectiveCell cell;
  int helicalKPoints = 1;
  AngularSampling angular;
  double electronicTemperature = 0;  // k_B T in Hartree (input in K)
  // "A-B" -> resolved path, for all ordered pairs of the species in the cell.
  std::map<std::string, std::string> parameterFiles;
  // The name of the parameter set when `[parameters] set = ...` was used (else empty).
  std::string parameterSet;
  std::map<std::string, int> maxAngularMomentum;  // optional per species: 0 = s, 1 = p, ...
  DispersionInput dispersion;
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
