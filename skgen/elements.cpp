#include "skgen/elements.hpp"

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {
const std::vector<Element>& table() {
  static const std::vector<Element> t = {
      {"H", 1, 1.008, {{1, 0, 1.0}}, {0}},
      {"He", 2, 4.0026, {{1, 0, 2.0}}, {0}},
      {"Li", 3, 6.94, {{1, 0, 2.0}, {2, 0, 1.0}, {2, 1, 0.0}}, {1, 2}},
      {"Be", 4, 9.0122, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 0.0}}, {1, 2}},
      {"B", 5, 10.81, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 1.0}}, {1, 2}},
      {"C", 6, 12.011, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 2.0}}, {1, 2}},
      {"N", 7, 14.007, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 3.0}}, {1, 2}},
      {"O", 8, 15.999, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 4.0}}, {1, 2}},
      {"F", 9, 18.998, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 5.0}}, {1, 2}},
      {"Ne", 10, 20.180, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 6.0}}, {1, 2}},
  };
  return t;
}

// Atomic number of a chemical symbol (0 when it is none).
int atomicNumber(const std::string& symbol) {
  static const char* const kSymbols[] = {
      "H",  "He", "Li", "Be", "B",  "C",  "N",  "O",  "F",  "Ne", "Na", "Mg", "Al", "Si", "P",
      "S",  "Cl", "Ar", "K",  "Ca", "Sc", "Ti", "V",  "Cr", "Mn", "Fe", "Co", "Ni", "Cu", "Zn",
      "Ga", "Ge", "As", "Se", "Br", "Kr", "Rb", "Sr", "Y",  "Zr", "Nb", "Mo", "Tc", "Ru", "Rh",
      "Pd", "Ag", "Cd", "In", "Sn", "Sb", "Te", "I",  "Xe", "Cs", "Ba", "La", "Ce", "Pr", "Nd",
      "Pm", "Sm", "Eu", "Gd", "Tb", "Dy", "Ho", "Er", "Tm", "Yb", "Lu", "Hf", "Ta", "W",  "Re",
      "Os", "Ir", "Pt", "Au", "Hg", "Tl", "Pb", "Bi", "Po", "At", "Rn", "Fr", "Ra", "Ac", "Th",
      "Pa", "U",  "Np", "Pu", "Am", "Cm", "Bk", "Cf", "Es", "Fm", "Md", "No", "Lr", "Rf", "Db",
      "Sg", "Bh", "Hs", "Mt", "Ds", "Rg", "Cn", "Nh", "Fl", "Mc", "Lv", "Ts", "Og"};
  for (int z = 1; z <= 118; ++z)
    if (symbol == kSymbols[z - 1]) return z;
  return 0;
}

// d (or f) valence: the transition metals, lanthanides and actinides.
bool needsD(int z) {
  return (z >= 21 && z <= 30) || (z >= 39 && z <= 48) || (z >= 57 && z <= 80) || (z >= 89 && z <= 112);
}
}  // namespace

const Element& findElement(const std::string& symbol, const std::string& source,
                           const std::string& key) {
  for (const auto& e : table())
    if (e.symbol == symbol) return e;
  const int z = atomicNumber(symbol);
  if (z > 0 && needsD(z))
    throw InputError(source, key,
                     fmt::format("the element {} (Z = {}), whose valence needs d (or f) shells", symbol, z),
                     "an element from H to Ne: skgen computes s and p shells only (d and f "
                     "atomic shells and two-centre integrals are not supported)");
  if (z > 0)
    throw InputError(source, key, fmt::format("the element {} (Z = {}), not in skgen's element list", symbol, z),
                     "an element from H to Ne (the table generator's element list)");
  throw InputError(source, key, "unknown element '" + symbol + "'",
                   "an element from H to Ne (the table generator's element list)");
}

}  // namespace mesochain::skgen
