#pragma once
// `mesochain run dftb_in.hsd`: the subset of DFTB+'s input that describes an objective-cell
// calculation, read into the same settings the cell file gives (objective::CellInput), so
// `run` and `convert` share the code after reading. The subset, its defaults (DFTB+'s) and the
// mapping to cell-file keys: docs/cell-file.md, "DFTB+ input (dftb_in.hsd)".
//
//   Geometry = GenFormat { <<< "geo.gen" }  (or the .gen lines inline)
//   Hamiltonian = DFTB { SCC, SCCTolerance, MaxSCCIterations, MaxAngularMomentum,
//     SlaterKosterFiles (explicit "A-B" entries or Type2FileNames { Prefix Separator Suffix
//     LowerCaseTypeName }), KPointsAndWeights (HelicalUniform, HelicalSampled for .gen type H;
//     SupercellFolding for S/F), Filling = Fermi { Temperature }, Dispersion = LennardJones
//     { Parameters = UFFParameters {} or per element { Distance Energy } } }
//   Driver = {} | LBFGS { MaxForceComponent MaxSteps } | ConjugateGradient { ... }
//   Analysis { PrintForces }, Options { WriteDetailedOut WriteResultsTag },
//   ParserOptions { ParserVersion }, Parallel { UseOmpThreads = Yes }
//
// Every other keyword is an InputError naming it and its line. Values are converted with
// DFTB+'s own constants (input/hsd/dftbplus_units.hpp), so the numbers are DFTB+'s.
#include <string>

#include "input/hsd/hsd_tree.hpp"
#include "input/cell_file.hpp"
#include "input/gen_file.hpp"

namespace mesochain::input::hsd {

objective::CellInput readDftbInput(const std::string& path);
// The same on a parsed tree (`path` names the input and anchors relative paths).
objective::CellInput readDftbInput(const Node& root, const std::string& path);

namespace detail {
// Hamiltonian = DFTB { ... } into `in` (tables, angular momenta, SCC, k-points, temperature,
// dispersion); needs in.cell and the .gen type of the geometry.
void readHamiltonian(const Node& root, objective::GenType type, objective::CellInput& in);
}  // namespace detail

}  // namespace mesochain::input::hsd
