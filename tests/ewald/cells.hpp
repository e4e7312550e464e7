#pragma once
// Small objective cells for the Ewald tests (Bohr): charged sites at several radii, one on the
// screw axis.
#include "objective/core/cell.hpp"

namespace ewaldtest {

using mesochain::objective::ObjectiveCell;
using mesochain::objective::Symmetry;

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

inline Eigen::VectorXd sampleCharges() {
  Eigen::VectorXd q(4);
  q << 0.7, -0.4, 0.45, -0.75;
  return q;
}

}  // namespace ewaldtest
