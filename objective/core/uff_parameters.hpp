#pragma once
// The Lennard-Jones parameters of the Universal Force Field: per element the van der Waals
// distance x_I (the position of the pair minimum, Å) and well depth D_I (kcal/mol) of
// A. K. Rappe, C. J. Casewit, K. S. Colwell, W. A. Goddard III and W. M. Skiff, J. Am. Chem.
// Soc. 114, 10024 (1992), Table 1 (one value per element: the element's first atom type).
// DFTB+'s `Dispersion = LennardJones { Parameters = UFFParameters {} }` takes the same numbers
// for every element; mesochain lists H to Kr (Z = 1..36); other elements need explicit values.
#include <optional>
#include <string>
#include <vector>

namespace mesochain::objective {

struct UffLennardJonesParameters {
  double distanceAngstrom = 0;  // x_I: E(r) = D_I [(x_I/r)^12 - 2 (x_I/r)^6]
  double energyKcalPerMol = 0;  // D_I
};

// nullopt for an element that is not in the table.
std::optional<UffLennardJonesParameters> uffParameters(const std::string& element);
// The elements of the table (for messages).
std::string uffElementRange();

}  // namespace mesochain::objective
