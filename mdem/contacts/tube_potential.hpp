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
#include <cstring>
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

// Two doubles operated on together (GCC/Clang vector extension: SSE2 on x86-64, scalar code
// elsewhere); loaded from two adjacent doubles.
using Lanes = double __attribute__((vector_size(16)));
inline Lanes lanes(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

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
  // Cubic Hermite basis: 0 = value at 0, 1 = value at 1, 2 = slope at 0, 3 = slope at 1; lanes
  // (t, s), i.e. the x and y directions together.
  const Lanes ts{t, s}, ts2 = ts * ts, ts3 = ts2 * ts;
  const Lanes b1 = 3.0 * ts2 - 2.0 * ts3, b2 = ts3 - 2.0 * ts2 + ts, b3 = ts3 - ts2, b0 = 1.0 - b1;
  const Lanes d1 = 6.0 * (ts - ts2), d2 = 3.0 * ts2 - 4.0 * ts + 1.0, d3 = 3.0 * ts2 - 2.0 * ts;
  const double b0t = b0[0], b1t = b1[0], b2t = b2[0], b3t = b3[0], d1t = d1[0], d2t = d2[0], d3t = d3[0];
  const double b0s = b0[1], b1s = b1[1], b2s = b2[1], b3s = b3[1], d1s = d1[1], d2s = d2[1], d3s = d3[1];
  // Along y on the two rows i, i+1 (nodes j, j+1 are adjacent in memory): the value part (f, fy)
  // and the x-slope part (fx, fxy), each with its y-derivative. Two lanes at once: a node's
  // (f, fx dx) and (fy dy, fxy dx dy) are adjacent, so lane 0 carries the value part and lane 1
  // the x-slope part through the same operations in the same order as the scalar sums
  // vp = p0 b0s + p4 b1s + p2 b2s + p6 b3s, xp = p1 b0s + ... (the results are those of the scalar
  // form bit for bit; the build has no FMA contraction).
  const double* p = &data_[4 * (i * ny_ + j)];
  const double* q = p + 4 * ny_;
  const Lanes p01 = lanes(p), p23 = lanes(p + 2), p45 = lanes(p + 4), p67 = lanes(p + 6);
  const Lanes q01 = lanes(q), q23 = lanes(q + 2), q45 = lanes(q + 4), q67 = lanes(q + 6);
  const Lanes vxp = p01 * b0s + p45 * b1s + p23 * b2s + p67 * b3s;      // (vp, xp)
  const Lanes vxq = q01 * b0s + q45 * b1s + q23 * b2s + q67 * b3s;      // (vq, xq)
  const Lanes vxpS = (p45 - p01) * d1s + p23 * d2s + p67 * d3s;         // (vpS, xpS)
  const Lanes vxqS = (q45 - q01) * d1s + q23 * d2s + q67 * d3s;         // (vqS, xqS)
  *fx = ((vxq[0] - vxp[0]) * d1t + vxp[1] * d2t + vxq[1] * d3t) * invDx_;
  // (value, fy): lane 0 = vp b0t + vq b1t + xp b2t + xq b3t, lane 1 the same of the y-derivatives.
  const Lanes v = Lanes{vxp[0], vxpS[0]} * b0t + Lanes{vxq[0], vxqS[0]} * b1t + Lanes{vxp[1], vxpS[1]} * b2t +
                  Lanes{vxq[1], vxqS[1]} * b3t;
  *fy = v[1] * invDy_;
  return v[0];
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
