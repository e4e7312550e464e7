#pragma once
// Van der Waals interaction between two carbon tubes, coarse-grained from the carbon-carbon
// Lennard-Jones potential phi(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6] smeared over the tube
// walls (surface density n atoms/nm^2). The derivation is in docs/mdem-contacts.md; in short:
//
//  1. Parallel infinite tubes (radii R1, R2, axis distance d): the energy per unit length
//       Phi(d) = n^2 R1 R2 \int\int q(h(a, b)) da db,
//     where q(h) = \int phi(sqrt(h^2 + z^2)) dz = 4 eps [63 pi/256 sigma^12/h^11 - 3 pi/8 sigma^6/h^5]
//     is the LJ potential of an atom and an infinite line of atoms at distance h (closed form),
//     and a, b run over the two ring angles (periodic trapezoid rule, spectrally accurate).
//     (Girifalco, Hodak & Lee, Phys. Rev. B 62, 13104 (2000) take the same route.)
//  2. Phi is switched smoothly to zero between the gaps g_s and g_c (gap = d - R1 - R2) and,
//     below the gap g_min = 0.7 sigma, continued linearly (a finite wall; never reached).
//  3. A line-line kernel w(rho) (energy per length^2 between two axis elements at distance rho)
//     with \int w(sqrt(d^2 + u^2)) du = Phi(d) exactly: the inverse Abel transform
//       w(rho) = -1/pi \int_rho^dc Phi'(y) / sqrt(y^2 - rho^2) dy.
//     Two axes then interact by E = \int ds \int du w(|p(s) - q(u)|): exact for parallel tubes,
//     and an approximation for crossed ones in the spirit of the "tubular potential" of Volkov &
//     Zhigilei, J. Phys. Chem. C 114, 5513 (2010) (accuracy measured in tests/mdem).
//  4. The inner integral along one axis is tabulated once: H(h, u) = \int_u^inf w(sqrt(h^2+v^2)) dv,
//     a C1 bicubic Hermite table, so a point at distance h from a straight segment spanning
//     v in [a, b] (relative to the foot point) has energy density H(h, a) - H(h, b).
//
// Units: nm, zJ (mdem/units.hpp).
#include <vector>

namespace mesochain::mdem {

struct LennardJones {
  double epsilon = 0.0;         // zJ
  double sigma = 0.0;           // nm
  double surfaceDensity = 0.0;  // atoms / nm^2
};

// Geometry and cut-off of one pair of tube kinds.
struct TubePairSpec {
  LennardJones lj;
  double radiusA = 0.0, radiusB = 0.0;  // nm
  double switchGap = 0.0;               // g_s, nm: Phi unchanged below
  double cutoffGap = 0.0;               // g_c, nm: Phi = 0 beyond
};

// Closed-form line integral of the LJ potential, q(h) and q'(h).
double ljLineIntegral(const LennardJones& lj, double h, double* derivative = nullptr);

// Phi(d) of two parallel infinite tubes (no switch), by the ring quadrature (step 1), and its
// derivative. `ringPoints` points per ring.
double parallelTubeEnergyPerLength(const LennardJones& lj, double r1, double r2, double d,
                                   double* derivative = nullptr, int ringPoints = 96);

// C1 bicubic Hermite table on a uniform grid x = x0 + i dx, y = y0 + j dy.
class BicubicTable {
 public:
  BicubicTable() = default;
  BicubicTable(int nx, int ny, double x0, double y0, double dx, double dy);
  // Node data: value, d/dx, d/dy, d2/dxdy.
  void set(int i, int j, double f, double fx, double fy, double fxy);
  // Value and partial derivatives at (x, y), clamped to the table (the caller keeps inside).
  double eval(double x, double y, double* fx, double* fy) const;
  double xMax() const { return x0_ + (nx_ - 1) * dx_; }
  double yMax() const { return y0_ + (ny_ - 1) * dy_; }

 private:
  int nx_ = 0, ny_ = 0;
  double x0_ = 0, y0_ = 0, dx_ = 1, dy_ = 1;
  std::vector<double> data_;  // 4 per node
};

// The coarse-grained interaction of one pair of tube kinds (steps 1-4), built once.
class TubePairPotential {
 public:
  explicit TubePairPotential(const TubePairSpec& spec, double gridStep = 0.005);

  const TubePairSpec& spec() const { return spec_; }
  // Axis distance beyond which everything vanishes: R1 + R2 + g_c.
  double cutoffDistance() const { return dc_; }
  // Phi of the model (switched, with the wall continuation) and Phi'.
  double phi(double d, double* derivative = nullptr) const;
  // The line-line kernel w(rho).
  double kernel(double rho) const;
  // H(h, u) = \int_u^inf w(sqrt(h^2 + v^2)) dv and its partial derivatives.
  double lineIntegral(double h, double u, double* dh, double* du) const;
  // Minimum of Phi: equilibrium axis distance and depth (zJ/nm, negative).
  double equilibriumDistance() const { return dEq_; }
  double wellDepthPerLength() const { return phiEq_; }

 private:
  double phiRaw(double d, double* derivative) const;  // from the 1D table (before the switch)
  TubePairSpec spec_;
  double dc_ = 0.0, dMin_ = 0.0, dEq_ = 0.0, phiEq_ = 0.0;
  double step_ = 0.0;
  // Phi on a uniform grid in d from dMin_ (value, derivative) for cubic Hermite interpolation.
  std::vector<double> phiNodes_, dphiNodes_;
  // w on a uniform grid in rho from 0.
  std::vector<double> wNodes_;
  double rhoLow_ = 0.0;  // w is held constant below (overlapping axes, never reached)
  BicubicTable g_;       // G(h, u) = H(h, u) for u >= 0
};

}  // namespace mesochain::mdem
