#pragma once
// Elements known to the table generator: nuclear charge, standard atomic mass (IUPAC 2013
// abridged values, the ones written into .skf files) and the spherical ground-state
// configuration (fractional occupations for open shells are fine: the atom is spherical).
#include <string>
#include <vector>

namespace mesochain::skgen {

struct ShellOccupation {
  int n = 1;
  int l = 0;
  double occupation = 0.0;  // electrons in the shell (both spins)
};

struct Element {
  std::string symbol;
  int z = 0;
  double mass = 0.0;  // atomic mass units
  std::vector<ShellOccupation> shells;  // core first, valence last
  std::vector<int> valence;            // indices into shells of the valence (basis) shells
};

// Throws InputError(source, key, ...) for symbols not in the table (H to Ne).
const Element& findElement(const std::string& symbol, const std::string& source,
                           const std::string& key);

}  // namespace mesochain::skgen
