#include "mdem/contacts/drape_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mdem/contacts/portable_math.hpp"

namespace mesochain::mdem {

namespace {
constexpr double kNone = -std::numeric_limits<double>::infinity();

// max over t in [t0, t1] of F(t) = z0 + t bz + sqrt(D^2 - Q(t)), Q(t) = alpha t^2 + 2 beta t + gamma,
// restricted to Q <= D^2 (F is concave there: linear + sqrt of a concave quadratic).
double pieceMaximum(double t0, double t1, double alpha, double beta, double gamma, double z0, double bz, double d2) {
  if (t0 > t1) return kNone;
  constexpr double kTiny = 1e-14;
  if (alpha < kTiny) {
    // Q constant up to rounding (footprint of B parallel to the relevant line, or B vertical).
    const double q = gamma + 2.0 * beta * 0.5 * (t0 + t1);
    if (q > d2) return kNone;
  } else {
    const double disc = beta * beta - alpha * (gamma - d2);
    if (disc < 0.0) return kNone;
    const double sq = std::sqrt(disc);
    t0 = std::max(t0, (-beta - sq) / alpha);
    t1 = std::min(t1, (-beta + sq) / alpha);
    if (t0 > t1) return kNone;
  }
  auto f = [&](double t) { return z0 + t * bz + std::sqrt(std::max(0.0, d2 - (alpha * t + 2.0 * beta) * t - gamma)); };
  double best = std::max(f(t0), f(t1));
  // Stationary points: bz sqrt(D^2 - Q) = alpha t + beta, squared:
  // alpha (alpha + bz^2) t^2 + 2 beta (alpha + bz^2) t + beta^2 - bz^2 (D^2 - gamma) = 0.
  const double m = alpha + bz * bz;
  if (m > kTiny && alpha > kTiny) {
    const double c = (beta * beta - bz * bz * (d2 - gamma)) / m;
    // disc = 0 is the common case bz = 0 (Q's vertex); rounding may make it slightly negative.
    // Evaluating F at a point that is not stationary is harmless (F is only maximised).
    const double disc = beta * beta - alpha * c;
    {
      const double sq = std::sqrt(std::max(0.0, disc));
      for (double t : {(-beta - sq) / alpha, (-beta + sq) / alpha})
        if (t > t0 && t < t1) best = std::max(best, f(t));
    }
  }
  return best;
}
}  // namespace

double supportHeight(const Vec3& a, double ha, const Vec3& c, const Vec3& b, double hb, double clearance) {
  const double d2 = clearance * clearance;
  // In-plane frame of A: xi along a, eta across.
  const double nx = -a.y(), ny = a.x();
  const double cxi = c.x() * a.x() + c.y() * a.y(), ceta = c.x() * nx + c.y() * ny;
  const double bxi = b.x() * a.x() + b.y() * a.y(), beta = b.x() * nx + b.y() * ny;
  // Pieces of t: footprint of B(t) projecting before (xi < -ha), onto, or after (xi > ha) A.
  double midLo = -hb, midHi = hb, leftLo = 1.0, leftHi = 0.0, rightLo = 1.0, rightHi = 0.0;  // empty by default
  if (std::abs(bxi) < 1e-14) {
    if (cxi < -ha) leftLo = -hb, leftHi = hb, midLo = 1.0, midHi = 0.0;
    else if (cxi > ha) rightLo = -hb, rightHi = hb, midLo = 1.0, midHi = 0.0;
  } else {
    const double tA = (-ha - cxi) / bxi, tB = (ha - cxi) / bxi;
    midLo = std::max(-hb, std::min(tA, tB)), midHi = std::min(hb, std::max(tA, tB));
    if (bxi > 0.0) leftLo = -hb, leftHi = std::min(hb, tA), rightLo = std::max(-hb, tB), rightHi = hb;
    else leftLo = std::max(-hb, tA), leftHi = hb, rightLo = -hb, rightHi = std::min(hb, tB);
  }
  // Middle: d_h = |eta(t)|; ends: distance to the end point (xi0 -/+ ha shifted).
  double best = pieceMaximum(midLo, midHi, beta * beta, ceta * beta, ceta * ceta, c.z(), b.z(), d2);
  const double bh2 = bxi * bxi + beta * beta;
  for (int side = -1; side <= 1; side += 2) {
    const double u = cxi - side * ha;  // xi relative to the end point at xi = side * ha
    const double lo = side < 0 ? leftLo : rightLo, hi = side < 0 ? leftHi : rightHi;
    best = std::max(best, pieceMaximum(lo, hi, bh2, u * bxi + ceta * beta, u * u + ceta * ceta, c.z(), b.z(), d2));
  }
  return best;
}

std::vector<double> drapeEnvelope(const std::vector<double>& required, const DrapeProfile& p) {
  const int n = static_cast<int>(required.size());
  const double s = p.elementLength * portableSin(p.maxSlope);
  // f(d) for d <= k, beyond which f grows linearly with slope s per element.
  const int k = std::max(0, static_cast<int>(std::ceil(p.maxSlope / p.bendPerElement + 0.5)) - 1);
  std::vector<double> f(k + 1, 0.0);
  for (int i = 1; i <= k; ++i) f[i] = f[i - 1] + p.elementLength * portableSin(std::min(p.maxSlope, (i - 0.5) * p.bendPerElement));
  std::vector<double> z(n), forward(n), backward(n);
  for (int e = 0; e < n; ++e) forward[e] = e == 0 ? required[0] : std::max(required[e], forward[e - 1] - s);
  for (int e = n - 1; e >= 0; --e) backward[e] = e == n - 1 ? required[e] : std::max(required[e], backward[e + 1] - s);
  for (int e = 0; e < n; ++e) {
    double h = required[e];
    for (int d = 1; d <= k; ++d) {
      if (e - d >= 0) h = std::max(h, required[e - d] - f[d]);
      if (e + d < n) h = std::max(h, required[e + d] - f[d]);
    }
    if (e - k >= 0) h = std::max(h, forward[e - k] - f[k]);
    if (e + k < n) h = std::max(h, backward[e + k] - f[k]);
    z[e] = h;
  }
  return z;
}

}  // namespace mesochain::mdem
