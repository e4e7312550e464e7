#include "objective/core/images.hpp"

#include <limits>

namespace mesochain::objective {

ImageList::ImageList(const ObjectiveCell& cell, double cutoff)
    : cutoff_(cutoff), shortest_(std::numeric_limits<double>::infinity()) {
  const int n = cell.atomCount();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d xi = cell.positions.col(i);
    for (int j = 0; j < n; ++j) {
      forEachImageNear(cell.symmetry, xi, cell.positions.col(j), cutoff,
                       [&](const GroupElement& g, const Eigen::Vector3d& y) {
                         if (i == j && g.isIdentity()) return;
                         ImagePair p{i, j, g, y - xi, (y - xi).norm()};
                         if (p.r < shortest_) shortest_ = p.r;
                         pairs_.push_back(p);
                       });
    }
  }
}

}  // namespace mesochain::objective
