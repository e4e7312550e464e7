#pragma once
// The energy density of a point against a whole straight segment, tabulated once per pair of
// tube kinds and partner half-length (docs/mdem-contacts.md, "Anisotropic form: cost"):
//
//   D(h, u0) = H(h, -l_b - u0) - H(h, l_b - u0) = \int_{-l_b - u0}^{l_b - u0} w(sqrt(h^2 + v^2)) dv,
//
// for a point at distance h from the axis line of segment b (half-length l_b) whose foot point
// lies at the axial coordinate u0 from b's centre. The anisotropic kernel then needs one table
// lookup per quadrature point instead of the two or three of H (tube_potential.hpp). D is even in
// h and in u0 and vanishes for h >= d_c or |u0| >= l_b + d_c.
//
// The node data (value, both slopes, cross derivative) are those of the H table's interpolant,
// so when l_b is a whole number of grid steps the bicubic interpolant of D is the difference of
// the two H interpolants: the same energy as the two-lookup kernel to round-off.
#include "mdem/contacts/tube_potential.hpp"

namespace mesochain::mdem {

class SegmentLineTable {
 public:
  SegmentLineTable(const TubePairPotential& potential, double halfLengthB);

  double halfLength() const { return halfLength_; }
  // Beyond these D is zero: h >= hCut or |u0| >= uCut.
  double hCut() const { return hCut_; }
  double uCut() const { return uCut_; }
  // D(h, |u0|) and its partial derivatives (h >= 0, u >= 0, inside the cuts).
  double eval(double h, double u, double* dh, double* du) const { return table_.eval(h, u, dh, du); }
  // The grid step of the table (nm): the early-out margin of the kernel is a few steps.
  double step() const { return step_; }

 private:
  double halfLength_ = 0.0, hCut_ = 0.0, uCut_ = 0.0, step_ = 0.0;
  BicubicTable table_;
};

}  // namespace mesochain::mdem
