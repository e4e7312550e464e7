#pragma once
// The [dispersion] table of the cell file (docs/cell-file.md) beside the two terms it selects:
// model = "lj" fills DispersionSettings (dftb/dispersion_term.hpp), model = "kc" fills
// KolmogorovCrespiSettings (dftb/dispersion_kc.hpp). Its keys, file units (kcal/mol, Å), ranges
// and defaults are read here and written back here, so the cell-file reader and writer, the
// extended XYZ settings keys and the scan identity list no key of it (the SCC pattern,
// dftb/scc_table.hpp).
#include <map>
#include <string>
#include <vector>

#include "common/setting_entries.hpp"
#include "common/toml_table.hpp"
#include "dftb/dispersion_kc.hpp"
#include "dftb/dispersion_term.hpp"

namespace mesochain::dftb {

// Defaults of model = "lj" (E(r) = epsilon [(r0/r)^12 - 2 (r0/r)^6], minimum -epsilon at r0).
inline constexpr double kDefaultLjEpsilonKcalPerMol = 0.069;
inline constexpr double kDefaultLjR0Angstrom = 3.80;
// At 30 Å the neglected r^-6 tail of a graphene-like sheet (0.38 atoms/Å^2) is
// pi * sigma * epsilon * r0^6 / r_c^4 ~ 3e-4 kcal/mol per atom; see docs/cell-file.md.
inline constexpr double kDefaultLjCutoffAngstrom = 30.0;
// The largest cutoff accepted: the image list grows with it (a 1e6 Å cutoff would list ~1e6
// images per atom pair); beyond 1000 Å the neglected tail is below 3e-10 kcal/mol per atom, and
// summation = "ewald" gives the exact tail anyway.
inline constexpr double kMaximumLjCutoffAngstrom = 1000.0;
// Defaults of model = "kc": the bond graph's covalent cutoff (Å) and the largest cutoff (Å).
inline constexpr double kDefaultKcBondCutoffAngstrom = 1.7;
inline constexpr double kMaximumKcCutoffAngstrom = 100.0;

// What the table selects: at most one of the two terms is enabled.
struct DispersionTable {
  DispersionSettings lj;        // lj.enabled with model = "lj"
  KolmogorovCrespiSettings kc;  // kc.enabled with model = "kc"
  // How the LJ pairs were given: "" (epsilon and r0, or elements = {...}) or "uff" (the UFF set,
  // objective/core/uff_parameters.hpp; lj.elements then holds its values for the cell's
  // elements, and the table is written back as parameters = "uff").
  std::string ljParameters;

  std::string model() const { return lj.enabled ? "lj" : kc.enabled ? "kc" : "none"; }
  bool operator==(const DispersionTable&) const = default;
};

// Per-element LJ parameters in atomic units.
struct LjElement {
  double epsilon = 0.0;  // Hartree, well depth
  double r0 = 0.0;       // Bohr, position of the minimum
};

// settings.elements / elementEpsilon / elementR0 from `elements`, in the map's (name) order.
void setLjElements(DispersionSettings& settings, const std::map<std::string, LjElement>& elements);
// The inverse: element name -> its parameters.
std::map<std::string, LjElement> ljElements(const DispersionSettings& settings);

// Reads the table into `d`, which it resets first (a cell file without the table keeps the
// default, model "none"); `species` are the elements of the cell (each needs LJ parameters). Strict: an unknown key, a key
// of the other model, a wrong type or a value out of range is an InputError naming it.
void readDispersionTable(const TomlTable& t, const std::vector<std::string>& species,
                         DispersionTable& d);

// Every key of the table, in order, in the file's units, as it reads back to `d`
// (elements as dotted keys elements.C.epsilon, elements.C.r0).
SettingEntries dispersionTableEntries(const DispersionTable& d);

}  // namespace mesochain::dftb
