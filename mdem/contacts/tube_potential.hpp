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
#include <algorithm>
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
  // Inline: it is the inner loop of the contact kernel (44 multiply-adds, no division).
  double eval(double x, double y, double* fx, double* fy) const;
  // The same with the cross derivative d2f/dxdy of the interpolant (tables built from tables).
  double eval(double x, double y, double* fx, double* fy, double* fxy) const;
  double xMax() const { return x0_ + (nx_ - 1) * dx_; }
  double yMax() const { return y0_ + (ny_ - 1) * dy_; }

 private:
  int nx_ = 0, ny_ = 0;
  double x0_ = 0, y0_ = 0, dx_ = 1, dy_ = 1, invDx_ = 1, invDy_ = 1;
  double tLast_ = 0, sLast_ = 0;  // nx - 1, ny - 1: the clamps in grid units
  std::vector<double> data_;  // 4 per node: f, fx dx, fy dy, fxy dx dy
};

inline double BicubicTable::eval(double x, double y, double* fx, double* fy) const {
  double t = (x - x0_) * invDx_, s = (y - y0_) * invDy_;
  t = std::clamp(t, 0.0, tLast_), s = std::clamp(s, 0.0, sLast_);
  const int i = std::min(static_cast<int>(t), nx_ - 2), j = std::min(static_cast<int>(s), ny_ - 2);
  t -= i, s -= j;
  // Cubic Hermite basis: 0 = value at 0, 1 = value at 1, 2 = slope at 0, 3 = slope at 1.
  const double t2 = t * t, s2 = s * s, t3 = t2 * t, s3 = s2 * s;
  const double b1t = 3 * t2 - 2 * t3, b2t = t3 - 2 * t2 + t, b3t = t3 - t2, b0t = 1 - b1t;
  const double d1t = 6 * (t - t2), d2t = 3 * t2 - 4 * t + 1, d3t = 3 * t2 - 2 * t;
  const double b1s = 3 * s2 - 2 * s3, b2s = s3 - 2 * s2 + s, b3s = s3 - s2, b0s = 1 - b1s;
  const double d1s = 6 * (s - s2), d2s = 3 * s2 - 4 * s + 1, d3s = 3 * s2 - 2 * s;
  // Along y on the two rows i, i+1 (nodes j, j+1 are adjacent in memory): the value part (f, fy)
  // and the x-slope part (fx, fxy), each with its y-derivative.
  const double* p = &data_[4 * (i * ny_ + j)];
  const double* q = p + 4 * ny_;
  const double vp = p[0] * b0s + p[4] * b1s + p[2] * b2s + p[6] * b3s;
  const double xp = p[1] * b0s + p[5] * b1s + p[3] * b2s + p[7] * b3s;
  const double vq = q[0] * b0s + q[4] * b1s + q[2] * b2s + q[6] * b3s;
  const double xq = q[1] * b0s + q[5] * b1s + q[3] * b2s + q[7] * b3s;
  const double vpS = (p[4] - p[0]) * d1s + p[2] * d2s + p[6] * d3s;
  const double xpS = (p[5] - p[1]) * d1s + p[3] * d2s + p[7] * d3s;
  const double vqS = (q[4] - q[0]) * d1s + q[2] * d2s + q[6] * d3s;
  const double xqS = (q[5] - q[1]) * d1s + q[3] * d2s + q[7] * d3s;
  *fx = ((vq - vp) * d1t + xp * d2t + xq * d3t) * invDx_;
  *fy = (vpS * b0t + vqS * b1t + xpS * b2t + xqS * b3t) * invDy_;
  return vp * b0t + vq * b1t + xp * b2t + xq * b3t;
}

// The coarse-grained interaction of one pair of tube kinds (steps 1-4), built once.
class TubePairPotential {
 public:
  static constexpr double kDefaultGridStep = 0.005;  // nm
  explicit TubePairPotential(const TubePairSpec& spec, double gridStep = kDefaultGridStep);

  const TubePairSpec& spec() const { return spec_; }
  // Axis distance beyond which everything vanishes: R1 + R2 + g_c.
  double cutoffDistance() const { return dc_; }
  // Phi of the model (switched, with the wall continuation) and Phi'.
  double phi(double d, double* derivative = nullptr) const;
  // The line-line kernel w(rho).
  double kernel(double rho) const;
  // H(h, u) = \int_u^inf w(sqrt(h^2 + v^2)) dv and its partial derivatives.
  double lineIntegral(double h, double u, double* dh, double* du) const;
  // The same with the cross derivative d2H/dh du of the interpolant (to build other tables).
  double lineIntegral(double h, double u, double* dh, double* du, double* dhu) const;
  // Grid step of the tables (nm).
  double gridStep() const { return step_; }
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
