#include "mdem/contacts/tube_potential.hpp"

#include <algorithm>
#include <cmath>

#include "mdem/contacts/quadrature.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
constexpr double kPi = units::kPi;

// Quintic smooth step: 1 at x <= 0, 0 at x >= 1, C2 (value, slope, curvature match).
double switchFactor(double x, double* dsdx) {
  if (x <= 0.0) return *dsdx = 0.0, 1.0;
  if (x >= 1.0) return *dsdx = 0.0, 0.0;
  *dsdx = -30.0 * x * x * (1.0 - x) * (1.0 - x);
  return 1.0 - x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
}

// Cubic Hermite on one interval, t in [0, 1], slopes already scaled by the step.
double hermite(double f0, double f1, double m0, double m1, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * m1;
}
double hermiteSlope(double f0, double f1, double m0, double m1, double t) {
  const double t2 = t * t;
  return (6 * t2 - 6 * t) * f0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * f1 + (3 * t2 - 2 * t) * m1;
}
}  // namespace

double ljLineIntegral(const LennardJones& lj, double h, double* derivative) {
  const double s6 = std::pow(lj.sigma / h, 6);
  const double c12 = 63.0 * kPi / 256.0, c6 = 3.0 * kPi / 8.0;
  const double a = c12 * s6 * s6 * h, b = c6 * s6 * h;  // sigma^12/h^11, sigma^6/h^5
  if (derivative) *derivative = 4.0 * lj.epsilon * (-11.0 * a + 5.0 * b) / h;
  return 4.0 * lj.epsilon * (a - b);
}

double parallelTubeEnergyPerLength(const LennardJones& lj, double r1, double r2, double d,
                                   double* derivative, int ringPoints) {
  const double da = 2.0 * kPi / ringPoints;
  std::vector<double> ca(ringPoints), sa(ringPoints);
  for (int k = 0; k < ringPoints; ++k) ca[k] = std::cos(k * da), sa[k] = std::sin(k * da);
  double e = 0.0, g = 0.0;
  for (int i = 0; i < ringPoints; ++i) {
    for (int j = 0; j < ringPoints; ++j) {
      const double x = d + r2 * ca[j] - r1 * ca[i], y = r2 * sa[j] - r1 * sa[i];
      const double h = std::sqrt(x * x + y * y);
      double dq;
      e += ljLineIntegral(lj, h, &dq);
      g += dq * x / h;
    }
  }
  const double scale = lj.surfaceDensity * lj.surfaceDensity * r1 * r2 * da * da;
  if (derivative) *derivative = scale * g;
  return scale * e;
}

BicubicTable::BicubicTable(int nx, int ny, double x0, double y0, double dx, double dy)
    : nx_(nx), ny_(ny), x0_(x0), y0_(y0), dx_(dx), dy_(dy), invDx_(1.0 / dx), invDy_(1.0 / dy),
      tLast_(nx - 1.0), sLast_(ny - 1.0), data_(4 * nx * ny, 0.0) {}

void BicubicTable::set(int i, int j, double f, double fx, double fy, double fxy) {
  double* p = &data_[4 * (i * ny_ + j)];
  p[0] = f, p[1] = fx * dx_, p[2] = fy * dy_, p[3] = fxy * dx_ * dy_;
}

double BicubicTable::eval(double x, double y, double* fx, double* fy, double* fxy) const {
  double t = (x - x0_) * invDx_, s = (y - y0_) * invDy_;
  t = std::clamp(t, 0.0, nx_ - 1.0), s = std::clamp(s, 0.0, ny_ - 1.0);
  const int i = std::min(static_cast<int>(t), nx_ - 2), j = std::min(static_cast<int>(s), ny_ - 2);
  t -= i, s -= j;
  // Hermite basis and derivatives: index 0 = value at 0, 1 = value at 1, 2 = slope at 0, 3 = slope at 1.
  const double t2 = t * t, t3 = t2 * t, s2 = s * s, s3 = s2 * s;
  const double bt[4] = {2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, t3 - 2 * t2 + t, t3 - t2};
  const double dbt[4] = {6 * t2 - 6 * t, -6 * t2 + 6 * t, 3 * t2 - 4 * t + 1, 3 * t2 - 2 * t};
  const double bs[4] = {2 * s3 - 3 * s2 + 1, -2 * s3 + 3 * s2, s3 - 2 * s2 + s, s3 - s2};
  const double dbs[4] = {6 * s2 - 6 * s, -6 * s2 + 6 * s, 3 * s2 - 4 * s + 1, 3 * s2 - 2 * s};
  double f = 0.0, gt = 0.0, gs = 0.0, gts = 0.0;
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      const double* p = &data_[4 * ((i + a) * ny_ + (j + b))];
      // value: B_a(t) B_b(s); x-slope: B_{2+a}(t) B_b(s); y-slope: B_a(t) B_{2+b}(s); cross.
      auto sum = [&](const double* ct, const double* cs) {
        return p[0] * ct[a] * cs[b] + p[1] * ct[2 + a] * cs[b] + p[2] * ct[a] * cs[2 + b] + p[3] * ct[2 + a] * cs[2 + b];
      };
      f += sum(bt, bs), gt += sum(dbt, bs), gs += sum(bt, dbs), gts += sum(dbt, dbs);
    }
  }
  *fx = gt * invDx_, *fy = gs * invDy_, *fxy = gts * invDx_ * invDy_;
  return f;
}

TubePairPotential::TubePairPotential(const TubePairSpec& spec, double gridStep)
    : spec_(spec), step_(gridStep) {
  const double rr = spec.radiusA + spec.radiusB;
  dc_ = rr + spec.cutoffGap;
  dMin_ = rr + 0.7 * spec.lj.sigma;
  // Step 1: Phi and Phi' on a grid from dMin to dc.
  const int nPhi = static_cast<int>(std::ceil((dc_ - dMin_) / step_)) + 1;
  phiNodes_.resize(nPhi), dphiNodes_.resize(nPhi);
  for (int k = 0; k < nPhi; ++k)
    phiNodes_[k] = parallelTubeEnergyPerLength(spec.lj, spec.radiusA, spec.radiusB, dMin_ + k * step_,
                                               &dphiNodes_[k]);
  // Equilibrium (minimum of the switched Phi), refined on a fine scan.
  dEq_ = dMin_, phiEq_ = phi(dMin_);
  for (double d = dMin_; d < dc_; d += 0.05 * step_) {
    const double p = phi(d);
    if (p < phiEq_) phiEq_ = p, dEq_ = d;
  }
  // Step 3: kernel by the inverse Abel transform, split at y = dMin where Phi'' jumps.
  const QuadratureRule gl = gaussLegendre(64);
  const int nW = static_cast<int>(std::ceil(dc_ / step_)) + 3;
  wNodes_.assign(nW, 0.0);
  rhoLow_ = 0.5 * dMin_;
  auto abel = [&](double rho) {
    const double tEnd = std::sqrt(std::max(0.0, dc_ * dc_ - rho * rho));
    const double tKink = rho < dMin_ ? std::sqrt(dMin_ * dMin_ - rho * rho) : 0.0;
    double sum = 0.0;
    for (auto [t0, t1] : {std::pair{0.0, tKink}, std::pair{tKink, tEnd}}) {
      if (t1 <= t0) continue;
      for (std::size_t q = 0; q < gl.x.size(); ++q) {
        const double t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * gl.x[q];
        const double y = std::sqrt(rho * rho + t * t);
        double dphi;
        phi(y, &dphi);
        sum += 0.5 * (t1 - t0) * gl.w[q] * dphi / y;
      }
    }
    return -sum / kPi;
  };
  for (int k = 0; k < nW; ++k) wNodes_[k] = abel(std::max(k * step_, rhoLow_));
  // Step 4: G(h, u) = \int_u^dc w(sqrt(h^2 + v^2)) dv on the (h, u) grid by Simpson's rule per cell.
  const int n = static_cast<int>(std::ceil(dc_ / step_)) + 2;
  std::vector<double> gv(n * n), gu(n * n);
  for (int i = 0; i < n; ++i) {
    const double h = i * step_;
    auto w = [&](double v) { return kernel(std::sqrt(h * h + v * v)); };
    double acc = 0.0;
    gv[i * n + n - 1] = 0.0;
    gu[i * n + n - 1] = -w((n - 1) * step_);
    for (int j = n - 2; j >= 0; --j) {
      const double u0 = j * step_, u1 = u0 + step_;
      acc += step_ / 6.0 * (w(u0) + 4.0 * w(u0 + 0.5 * step_) + w(u1));
      gv[i * n + j] = acc;
      gu[i * n + j] = -w(u0);
    }
  }
  g_ = BicubicTable(n, n, 0.0, 0.0, step_, step_);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      double gh, ghu;
      if (i == 0) {
        gh = ghu = 0.0;  // G is even in h
      } else if (i == n - 1) {
        gh = (gv[i * n + j] - gv[(i - 1) * n + j]) / step_;
        ghu = (gu[i * n + j] - gu[(i - 1) * n + j]) / step_;
      } else {
        gh = (gv[(i + 1) * n + j] - gv[(i - 1) * n + j]) / (2 * step_);
        ghu = (gu[(i + 1) * n + j] - gu[(i - 1) * n + j]) / (2 * step_);
      }
      g_.set(i, j, gv[i * n + j], gh, gu[i * n + j], ghu);
    }
  }
}

double TubePairPotential::phiRaw(double d, double* derivative) const {
  const double x = (d - dMin_) / step_;
  const int k = std::clamp(static_cast<int>(x), 0, static_cast<int>(phiNodes_.size()) - 2);
  const double t = x - k;
  const double m0 = dphiNodes_[k] * step_, m1 = dphiNodes_[k + 1] * step_;
  *derivative = hermiteSlope(phiNodes_[k], phiNodes_[k + 1], m0, m1, t) / step_;
  return hermite(phiNodes_[k], phiNodes_[k + 1], m0, m1, t);
}

double TubePairPotential::phi(double d, double* derivative) const {
  double dp = 0.0, p = 0.0;
  if (d >= dc_) {
    p = dp = 0.0;
  } else if (d < dMin_) {  // linear wall continuation (the switch is 1 there)
    double d0;
    const double p0 = phiRaw(dMin_, &d0);
    p = p0 + d0 * (d - dMin_), dp = d0;
  } else {
    double raw, draw, ds;
    const double rr = spec_.radiusA + spec_.radiusB;
    raw = phiRaw(d, &draw);
    const double s = switchFactor((d - rr - spec_.switchGap) / (spec_.cutoffGap - spec_.switchGap), &ds);
    p = raw * s;
    dp = draw * s + raw * ds / (spec_.cutoffGap - spec_.switchGap);
  }
  if (derivative) *derivative = dp;
  return p;
}

double TubePairPotential::kernel(double rho) const {
  if (rho >= dc_) return 0.0;
  rho = std::max(rho, rhoLow_);
  // Catmull-Rom cubic through the nodes.
  const double x = rho / step_;
  const int k = std::clamp(static_cast<int>(x), 1, static_cast<int>(wNodes_.size()) - 3);
  const double t = x - k;
  const double p0 = wNodes_[k - 1], p1 = wNodes_[k], p2 = wNodes_[k + 1], p3 = wNodes_[k + 2];
  return hermite(p1, p2, 0.5 * (p2 - p0), 0.5 * (p3 - p1), t);
}

double TubePairPotential::lineIntegral(double h, double u, double* dh, double* du) const {
  h = std::abs(h);
  if (h >= g_.xMax()) return *dh = *du = 0.0, 0.0;
  if (u >= 0.0) {
    if (u >= g_.yMax()) return *dh = *du = 0.0, 0.0;
    return g_.eval(h, u, dh, du);
  }
  // H(h, u) = 2 G(h, 0) - G(h, -u) for u < 0.
  double h0, u0, h1, u1;
  const double g0 = g_.eval(h, 0.0, &h0, &u0);
  const double g1 = -u >= g_.yMax() ? (h1 = u1 = 0.0, 0.0) : g_.eval(h, -u, &h1, &u1);
  *dh = 2.0 * h0 - h1;
  *du = u1;
  return 2.0 * g0 - g1;
}

double TubePairPotential::lineIntegral(double h, double u, double* dh, double* du, double* dhu) const {
  const double sign = h < 0.0 ? -1.0 : 1.0;  // H is even in h
  h = std::abs(h);
  double value = 0.0;
  *dh = *du = *dhu = 0.0;
  if (h >= g_.xMax()) return 0.0;
  if (u >= 0.0) {
    if (u < g_.yMax()) value = g_.eval(h, u, dh, du, dhu);
  } else {
    // H(h, u) = 2 G(h, 0) - G(h, -u): dH/du = G_u(h, -u), d2H/dhdu = G_hu(h, -u).
    double h0, u0, c0, h1 = 0.0, u1 = 0.0, c1 = 0.0, g1 = 0.0;
    const double g0 = g_.eval(h, 0.0, &h0, &u0, &c0);
    if (-u < g_.yMax()) g1 = g_.eval(h, -u, &h1, &u1, &c1);
    value = 2.0 * g0 - g1, *dh = 2.0 * h0 - h1, *du = u1, *dhu = c1;
  }
  *dh *= sign, *dhu *= sign;
  return value;
}

}  // namespace mesochain::mdem
