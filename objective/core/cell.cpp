#include "objective/core/cell.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/images.hpp"

namespace mesochain::objective {

void ObjectiveCell::addAtom(const std::string& element, const Eigen::Vector3d& position) {
  auto it = std::find(speciesNames.begin(), speciesNames.end(), element);
  int index = static_cast<int>(it - speciesNames.begin());
  if (it == speciesNames.end()) speciesNames.push_back(element);
  species.push_back(index);
  positions.conservativeResize(3, positions.cols() + 1);
  positions.col(positions.cols() - 1) = position;
}

void ObjectiveCell::validate(const std::string& source, double minDistance) const {
  if (positions.cols() != atomCount())
    throw InputError(source, fmt::format("{} positions for {} atoms", positions.cols(),
                                         atomCount()));
  if (atomCount() == 0) throw InputError(source, "geometry", "no atoms", "at least one atom");
  for (int a = 0; a < atomCount(); ++a) {
    if (species[a] < 0 || species[a] >= static_cast<int>(speciesNames.size()))
      throw InputError(source, fmt::format("atom {}", a + 1), "an unknown species index",
                       "a listed element");
    for (int k = 0; k < 3; ++k)
      requireFinite(positions(k, a), source, fmt::format("atom {} coordinate {}", a + 1, k + 1));
  }
  const double bohr = units::kBohrInAngstrom;
  for (int i = 0; i < atomCount(); ++i)
    for (int j = 0; j < atomCount(); ++j)
      forEachImageNear(symmetry, positions.col(i), positions.col(j), minDistance,
                       [&](const GroupElement& g, const Eigen::Vector3d& y) {
                         if (i == j && g.isIdentity()) return;
                         const double r = (y - positions.col(i)).norm();
                         std::string what =
                             (i == j) ? fmt::format("atom {} and its own image (zeta={}, c={})",
                                                    i + 1, g.zeta, g.c)
                                      : fmt::format("atom {} and atom {} (image zeta={}, c={})",
                                                    i + 1, j + 1, g.zeta, g.c);
                         throw InputError(source, what,
                                          fmt::format("a distance of {:.4f} Å", r * bohr),
                                          fmt::format("at least {:.2f} Å between atoms",
                                                      minDistance * bohr));
                       });
}

}  // namespace mesochain::objective
