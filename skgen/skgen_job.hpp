#pragma once
// `mesochain skgen ELEMENTS.toml`: the input file (docs/skgen.md) and the run that writes one
// .skf file per requested pair.
//
//   functional = "pbe"                 # none | lda | lda-vwn | pbe
//   hubbard_functional = "lda"         # optional (default: functional)
//   superposition = "density"          # optional: "density" (default) or "potential"
//   output_dir = "skf"                 # optional (default "skf"), relative to the working folder
//   pairs = ["C-C", "C-H", "H-C", "H-H"]  # optional (default: every ordered pair)
//   [grid]   spacing_bohr, cutoff_bohr, quadrature_points, quadrature_extent_bohr, atom_log_step
//   [elements.C]
//   basis = "slater"                   # or "grid" (numerical radial grid)
//   exponents_per_bohr = [0.5, 1.14, 2.62, 6.0]
//   powers = 3
//   density = { r0_bohr = 7.0, power = 2 }
//   wavefunction = { r0_bohr = 2.7, power = 2 }        # every valence shell, or per shell:
//   [elements.C.shells] 2s = {...}  2p = {...}          # (overrides `wavefunction`)
//   confinement tables: { r0_bohr, power } or { type = "woods-saxon", r0_bohr, height_hartree,
//   slope_per_bohr }
//   [repulsive.C-C]                    # optional per unordered pair (skgen/repulsive_fit.hpp)
//   curve_csv = "c2.csv"               # r_bohr,energy_hartree; relative to the input file
//   cutoff_bohr = 3.9
//   intervals = 20
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "skgen/element_basis.hpp"
#include "skgen/sk_table.hpp"

namespace mesochain::skgen {

struct RepulsiveRequest {
  std::string a, b;        // the pair (also used for B-A)
  std::string curve;       // path of the dimer curve
  double cutoff = 0.0;     // Bohr
  int intervals = 20;
  std::string key;         // "repulsive.A-B", for messages
};

struct SkgenJob {
  std::string source;
  XcKind xc = XcKind::Pbe;
  XcKind hubbardXc = XcKind::Pbe;
  std::vector<ElementSettings> elements;  // in file order
  std::vector<std::pair<std::string, std::string>> pairs;
  TableGrid grid;
  std::string outputDir = "skf";
  std::vector<RepulsiveRequest> repulsive;
};

// Strict reader: every unknown key, wrong type, unknown element, bad value or inconsistent
// setting is an InputError naming the file and the key (with its line).
SkgenJob readSkgenJob(const std::string& path);

// Builds every element (free, density- and wavefunction-confined atoms, spin data of the free
// atom) and every pair table; writes outputDir/A-B.skf with the fitted repulsive of the pair, or
// the explicit zero repulsive when none is requested, and a documentation block of the recipe,
// and outputDir/atomic-data.json (atomicDataJson). `progress(fraction, what)` along the way.
// A confinement radius too small for a bound state is an InputError naming the shell.
struct SkgenOutput {
  std::vector<std::string> tables;  // the .skf files, in pair order
  std::string atomicData;           // the JSON of atomic data
};
SkgenOutput runSkgen(const SkgenJob& job,
                     const std::function<void(double, const std::string&)>& progress = {});

// Atomic data of every element as JSON text (units in the key names): on-site energies, Hubbard
// U, occupations, spin constants W (DFTB+ SpinConstants order: the valence shells, row-major),
// the spin-polarisation energy (the .skf "SPE" field), functionals, mass.
std::string atomicDataJson(const SkgenJob& job, const std::vector<std::pair<std::string, const ElementBasis*>>& elements);

// The documentation block written after the spline (recipe of the two elements).
std::string skgenDocumentation(const SkgenJob& job, const ElementSettings& a,
                               const ElementSettings& b, const RepulsiveRequest* repulsive);

}  // namespace mesochain::skgen
