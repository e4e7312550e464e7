#pragma once
// Images of the cell atoms under the objective group, enumerated with their group element.
//
// An ImagePair (i, j, g) is cell atom i together with image g of cell atom j, at distance
// vector d = g(x_j) - x_i. Lists hold every ordered pair with |d| < cutoff, except (i, i, e):
// both (i, j, g) and (j, i, g^-1) appear. Kernels loop over this list and never derive a
// rotation from positions; the rotation of the image comes from g.
#include <vector>

#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

struct ImagePair {
  int i = 0;
  int j = 0;
  GroupElement g;
  Eigen::Vector3d d;  // g(x_j) - x_i, Bohr
  double r = 0.0;     // |d|
};

class ImageList {
 public:
  ImageList() = default;
  // All ordered pairs with 0 < |d| < cutoff. A closed ring enumerates c = 0..N_a-1 with
  // zeta = 0; a screw enumerates every zeta whose axial offset can be within the cutoff.
  ImageList(const ObjectiveCell& cell, double cutoff);

  double cutoff() const { return cutoff_; }
  const std::vector<ImagePair>& pairs() const { return pairs_; }
  // Shortest distance found between distinct sites (Bohr); +inf when the list is empty.
  double shortestDistance() const { return shortest_; }

 private:
  double cutoff_ = 0.0;
  double shortest_ = 0.0;
  std::vector<ImagePair> pairs_;
};

// Calls f(g, y) for every group element g whose image y = g(x_j) lies within `cutoff` of x_i
// (identity included when i == j; f decides). Shared by ImageList and validation.
template <class F>
void forEachImageNear(const Symmetry& s, const Eigen::Vector3d& xi, const Eigen::Vector3d& xj,
                      double cutoff, F&& f);

}  // namespace mesochain::objective

#include "objective/core/images_impl.hpp"
