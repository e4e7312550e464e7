#pragma once
// ObjectiveCell: N_o atoms plus the Symmetry that generates the whole structure from them.
// Positions in Bohr, z along the symmetry axis (the axis passes through x = y = 0).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "objective/core/symmetry.hpp"

namespace mesochain::objective {

// Atoms (and images) closer than this are an input error (Å): ObjectiveCell::validate's bound
// for every geometry read, built or restored.
inline constexpr double kMinimumAtomDistanceAngstrom = 0.5;

struct ObjectiveCell {
  Symmetry symmetry = Symmetry::ring(1);  // default: an isolated cluster (C_1, no periodicity)
  std::vector<std::string> speciesNames;  // e.g. {"C", "H"}
  std::vector<int> species;               // per atom: index into speciesNames
  Eigen::Matrix3Xd positions;             // 3 x N_o, Bohr

  int atomCount() const { return static_cast<int>(species.size()); }
  const std::string& speciesOf(int atom) const { return speciesNames[species[atom]]; }
  // Adds an atom (creating the species name if new); position in Bohr.
  void addAtom(const std::string& element, const Eigen::Vector3d& position);
  // Throws InputError when sizes disagree, a coordinate is not finite, or two atoms (or an atom
  // and an image of any atom) are closer than minDistance (Bohr). `source` names the input.
  void validate(const std::string& source, double minDistance) const;
};

}  // namespace mesochain::objective
