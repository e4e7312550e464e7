#include "mdem/contacts/vdw_contact.hpp"

#include <algorithm>
#include <cmath>

namespace mesochain::mdem {

ContactPairResult anisotropicVdw(const TubePairPotential& potential, const QuadratureRule& rule,
                                 const Segment& a, const Segment& b) {
  ContactPairResult r;
  const double dc = potential.cutoffDistance();
  Vec3 gradR = Vec3::Zero();    // dE/d(x_a) (= -dE/d(x_b))
  Vec3 gradTa = Vec3::Zero();   // dE/d(t_a)
  Vec3 gradTb = Vec3::Zero();   // dE/d(t_b)
  const double la = a.halfLength, lb = b.halfLength;
  for (std::size_t q = 0; q < rule.x.size(); ++q) {
    const double s = la * rule.x[q], weight = la * rule.w[q];
    const Vec3 rel = a.centre + s * a.axis - b.centre;
    const double u0 = rel.dot(b.axis);
    const Vec3 perp = rel - u0 * b.axis;
    const double h = perp.norm();
    const double lo = -lb - u0, hi = lb - u0;
    if (h >= dc || lo >= dc || hi <= -dc) continue;
    double hLo, uLo, hHi, uHi;
    const double e = potential.lineIntegral(h, lo, &hLo, &uLo) - potential.lineIntegral(h, hi, &hHi, &uHi);
    // dE_q = gh dh + ga d(lo) + gb d(hi)
    const double gh = hLo - hHi, ga = uLo, gb = -uHi;
    // dh/drel = perp/h, d(lo)/drel = d(hi)/drel = -t_b;  dh/dt_b = -u0 rel/h, d(lo)/dt_b = -rel.
    const Vec3 dh = h > 1e-12 ? Vec3(perp / h) : Vec3::Zero();
    const Vec3 gRel = gh * dh - (ga + gb) * b.axis;
    const Vec3 gTb = (h > 1e-12 ? -gh * u0 / h : 0.0) * rel - (ga + gb) * rel;
    r.energy += weight * e;
    gradR += weight * gRel;
    gradTa += (weight * s) * gRel;
    gradTb += weight * gTb;
  }
  r.forceA = -gradR;
  r.forceB = gradR;
  r.torqueA = -a.axis.cross(gradTa);
  r.torqueB = -b.axis.cross(gradTb);
  return r;
}

IsotropicVdw::IsotropicVdw(const TubePairPotential& potential, double la, double lb) {
  step_ = 0.005;
  rMax_ = potential.cutoffDistance();
  const int n = static_cast<int>(std::ceil(rMax_ / step_)) + 2;
  u_.assign(n, 0.0), du_.assign(n, 0.0);
  // U(r) = \int_{-la}^{la} ds [H(r, -lb - s) - H(r, lb - s)], composite Gauss-Legendre in s.
  const QuadratureRule gl = gaussLegendre(16);
  constexpr int kPanels = 16;
  for (int k = 0; k < n; ++k) {
    const double r = k * step_;
    double e = 0.0, de = 0.0;
    for (int p = 0; p < kPanels; ++p) {
      const double s0 = -la + 2.0 * la * p / kPanels, s1 = s0 + 2.0 * la / kPanels;
      for (std::size_t q = 0; q < gl.x.size(); ++q) {
        const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * gl.x[q], w = 0.5 * (s1 - s0) * gl.w[q];
        double h0, u0, h1, u1;
        e += w * (potential.lineIntegral(r, -lb - s, &h0, &u0) - potential.lineIntegral(r, lb - s, &h1, &u1));
        de += w * (h0 - h1);
      }
    }
    u_[k] = e, du_[k] = de;
  }
}

double IsotropicVdw::energy(double r, double* derivative) const {
  if (r >= rMax_) return *derivative = 0.0, 0.0;
  const double x = r / step_;
  const int k = std::min(static_cast<int>(x), static_cast<int>(u_.size()) - 2);
  const double t = x - k, t2 = t * t, t3 = t2 * t;
  const double f0 = u_[k], f1 = u_[k + 1], m0 = du_[k] * step_, m1 = du_[k + 1] * step_;
  *derivative = ((6 * t2 - 6 * t) * f0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * f1 +
                 (3 * t2 - 2 * t) * m1) / step_;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * m1;
}

ContactPairResult IsotropicVdw::evaluate(const Vec3& centreA, const Vec3& centreB) const {
  ContactPairResult res;
  const Vec3 d = centreA - centreB;
  const double r = d.norm();
  if (r >= rMax_ || r < 1e-12) return res;
  double dU;
  res.energy = energy(r, &dU);
  res.forceA = -dU * d / r;
  res.forceB = -res.forceA;
  return res;
}

}  // namespace mesochain::mdem
