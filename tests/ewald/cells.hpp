#pragma once
// Small objective cells for the Ewald tests (Bohr): charged sites at several radii, one on the
// screw axis.
#include <optional>
#include <vector>

#include "ewald/helical_lattice_sum.hpp"
#include "objective/core/cell.hpp"

namespace ewaldtest {

using mesochain::objective::ObjectiveCell;
using mesochain::objective::Symmetry;

// The lattice-sum matrix of `cell` at tolerance `tol` (splitting parameter `alpha` if given).
inline Eigen::MatrixXd phi(mesochain::ewald::Kernel k, const ObjectiveCell& cell, double tol = 1e-12,
                           std::optional<double> alpha = std::nullopt) {
  mesochain::ewald::LatticeSumSettings st;
  st.tolerance = tol;
  st.splitting = alpha;
  return mesochain::ewald::HelicalLatticeSum(k, st).matrix(cell);
}

inline ObjectiveCell sampleCell(const Symmetry& s) {
  // N_a > 1 maps an axis site onto itself: keep the third site off the axis then.
  const double off = s.rotationOrder() > 1 ? 1.3 : 0.0;
  ObjectiveCell c;
  c.symmetry = s;
  c.addAtom("C", {3.1, 0.4, 0.2});
  c.addAtom("C", {-1.2, 2.5, 1.9});
  c.addAtom("H", {off, 0.5 * off, -0.7});
  c.addAtom("H", {0.9, -4.2, 1.1});
  return c;
}

// Cell whose atoms are the images g_m(x_j) of `cell` under the listed elements, with symmetry s.
inline ObjectiveCell expanded(const ObjectiveCell& cell,
                              const std::vector<mesochain::objective::GroupElement>& gs,
                              const Symmetry& s) {
  ObjectiveCell out;
  out.symmetry = s;
  for (const auto& g : gs)
    for (int j = 0; j < cell.atomCount(); ++j)
      out.addAtom(cell.speciesOf(j), cell.symmetry.apply(g, cell.positions.col(j)));
  return out;
}

// Phi of the small cell from the expanded one: Phi_ij = sum_m PhiBig(i, m*N_o + j) (first copy
// is the identity).
inline Eigen::MatrixXd folded(const Eigen::MatrixXd& big, int no, int copies) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(no, no);
  for (int i = 0; i < no; ++i)
    for (int j = 0; j < no; ++j)
      for (int c = 0; c < copies; ++c) m(i, j) += big(i, c * no + j);
  return m;
}

inline Eigen::VectorXd sampleCharges() {
  Eigen::VectorXd q(4);
  q << 0.7, -0.4, 0.45, -0.75;
  return q;
}

}  // namespace ewaldtest
