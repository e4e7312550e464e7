#pragma once
// The anisotropic contact energy of two nearly parallel segments from five 2-D tables, one lookup
// cell per pair instead of a Gauss rule (docs/mdem-contacts.md, "Nearly parallel pairs").
//
// The kernel's energy is E = \int_{-la}^{la} D(h(s), u0(s)) ds (vdw_contact.hpp, D the table of
// the partner segment, segment_line_table.hpp). With r0 = x_a - x_b, c = t_a.t_b, f = t_b.r0 and
// sigma = sign(c), the squared distance of the point s of axis a from b's line is exactly
//   h(s)^2 = hA + hB s + hC s^2,  hA = |r0 - f t_b|^2,  hB = 2 (t_a.r0 - f c),  hC = 1 - c^2,
// and (D being even in u0) its foot point enters as u0 = Delta + s + eps s, Delta = sigma f,
// eps = |c| - 1. For exactly parallel axes hB = hC = eps = 0. Writing g(x, u) = D(sqrt(x), u) and
// expanding the integrand to second order in the tilt (hB is first order, hC and eps second):
//   E ~ G0 + hB K1 + hC K2 + hB^2 K3 / 2 + eps G4,
//   G0 = \int D(h0, Delta + s) ds,    K1 = \int s g_x ds,   K2 = \int s^2 g_x ds,
//   K3 = \int s^2 g_xx ds,            G4 = \int s g_u ds = la [D(h0, Delta + la) + D(h0, Delta - la)] - G0,
// all functions of (h0 = sqrt(hA), Delta) only, tabulated once per pair of element kinds as C1
// bicubic Hermite tables. The neglected terms are third order in the tilt (h varies by la sin(theta)
// along a); the caller uses this only inside a small angle window (vdw_contact.cpp).
//
// Construction (~0.3 s for 2-nm elements): along each table row h_i the integrals are exact
// integrals of the D interpolant (prefix sums of a 3-point Gauss rule per grid cell, exact for
// the cubic rows times s^2), G0 with exact slopes (dG0/dDelta = D(Delta + la) - D(Delta - la)),
// K3 = dK2/dx by central differences across rows, the other slopes by central differences.
#include <vector>

#include "mdem/contacts/segment_line_table.hpp"
#include "mdem/contacts/tube_potential.hpp"

namespace mesochain::mdem {

// The expansion's energy and its partial derivatives with respect to its five arguments.
struct AlignedEnergy {
  double energy = 0.0;
  double dH0 = 0.0, dDelta = 0.0, dHB = 0.0, dHC = 0.0, dEps = 0.0;
};

class AlignedPairTable {
 public:
  // `d`: the table D of the partner segment; `halfLengthA`: the quadrature element's half-length.
  // Node data are zero where the parallel segments' closest distance
  // rho = sqrt(h^2 + max(|Delta| - la - lb, 0)^2) is at least `zeroBeyond`, so the tables vanish
  // exactly for rho >= zeroBeyond + sqrt(2) step (vdw_contact.cpp keeps that inside the
  // neighbour list's reach; the D interpolant itself ends one step beyond d_c).
  AlignedPairTable(const SegmentLineTable& d, double halfLengthA, double zeroBeyond);

  double halfLengthA() const { return la_; }
  // Beyond these all five tables vanish (the caller's window stays well inside).
  double hMax() const { return hMax_; }
  double deltaMax() const { return deltaMax_; }

  AlignedEnergy evaluate(double h0, double delta, double hB, double hC, double eps) const;

  static constexpr int kTables = 5;  // G0, K1, K2, K3, G4

 private:
  // The five bicubic Hermite tables on one grid (h = i step, |Delta| = j step), node data
  // interleaved (per node and table: f, f_h step, f_Delta step, f_hDelta step^2), so that one
  // lookup computes the cell's basis once for all five.
  void set(int table, int i, int j, double f, double fh, double fd, double fhd);
  double la_ = 0.0, hMax_ = 0.0, deltaMax_ = 0.0, step_ = 0.0, invStep_ = 0.0;
  int nh_ = 0, nd_ = 0;
  std::vector<double> data_;
};

}  // namespace mesochain::mdem
