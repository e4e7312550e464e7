#include "beam/bend_curve.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "common/units.hpp"
#include "common/errors.hpp"

namespace mesochain::beam {

namespace {

// Ordinary least squares y ≈ A p: coefficients and their standard errors (0 without spare dof).
struct Solution {
  Eigen::VectorXd coef, error;
};

Solution solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& y) {
  Solution s;
  s.coef = a.colPivHouseholderQr().solve(y);
  s.error = Eigen::VectorXd::Zero(a.cols());
  const long dof = a.rows() - a.cols();
  if (dof > 0) {
    const double variance = (a * s.coef - y).squaredNorm() / static_cast<double>(dof);
    const Eigen::MatrixXd inv = (a.transpose() * a).inverse();
    for (long i = 0; i < a.cols(); ++i) s.error(i) = std::sqrt(std::max(0.0, variance * inv(i, i)));
  }
  return s;
}

// Anchored ½ D κ² over the given points.
LeastSquaresConstant quadraticThroughReference(const std::vector<BendCurvePoint>& p) {
  Eigen::MatrixXd a(p.size(), 1);
  Eigen::VectorXd y(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    a(i, 0) = 0.5 * p[i].sample.curvature * p[i].sample.curvature;
    y(i) = p[i].energyAbove;
  }
  const Solution s = solve(a, y);
  return {s.coef(0), s.error(0), static_cast<int>(p.size())};
}

double radiusNm(double curvature) { return units::si::kBohrInNm / curvature; }

}  // namespace

RingSection measureRingSection(const Eigen::Matrix3Xd& x) {
  RingSection r;
  if (x.cols() == 0) return r;
  Eigen::VectorXd rho(x.cols());
  for (long i = 0; i < x.cols(); ++i) rho(i) = std::hypot(x(0, i), x(1, i));
  const Eigen::ArrayXd u = rho.array() - rho.mean();
  r.radialExtent = u.maxCoeff() - u.minCoeff();
  r.meanSquareRadialOffset = u.square().mean();
  r.axialExtent = x.row(2).maxCoeff() - x.row(2).minCoeff();
  return r;
}

BendCurve analyseBendCurve(std::vector<BendSample> rings, double reference, const BendCurveOptions& o) {
  const std::string& q = o.quantity;
  if (rings.empty()) throw InputError(o.source, q + " curve", "no ring (curvature > 0)", "at least one bent point");
  requireFinite(reference, o.source, q + " curve: reference energy");
  if (!(o.tolerance > 0.0) || !(o.energyNoise >= 0.0) || !std::isfinite(o.energyNoise))
    throw InputError(o.source, q + " curve options", "a non-positive tolerance or a negative noise",
                     "tolerance > 0 and energy noise >= 0");
  for (const BendSample& r : rings) {
    requireFinite(r.curvature, o.source, q + " curve: curvature");
    requireFinite(r.energy, o.source, q + " curve: energy");
    if (!(r.curvature > 0.0))
      throw InputError(o.source, q + " curve", fmt::format("a curvature of {:.6g} per Bohr", r.curvature),
                       "rings of positive curvature (the straight reference is the anchor)");
  }
  std::sort(rings.begin(), rings.end(), [](const BendSample& a, const BendSample& b) { return a.curvature < b.curvature; });
  for (std::size_t i = 1; i < rings.size(); ++i)
    if (rings[i].curvature - rings[i - 1].curvature <= 1e-12 * rings[i].curvature)
      throw InputError(o.source, q + " curve", fmt::format("the curvature {:.9g} per Bohr twice", rings[i].curvature),
                       "one point per curvature");
  if (o.window && !(o.window->first >= 0.0 && o.window->second > o.window->first))
    throw InputError(o.source, "curvature window", fmt::format("[{:.6g}, {:.6g}]", o.window->first, o.window->second),
                     "0 <= lo < hi");

  BendCurve c;
  c.referenceEnergy = reference;
  const int n = static_cast<int>(rings.size());
  for (const BendSample& r : rings) {
    BendCurvePoint p;
    p.sample = r;
    p.energyAbove = r.energy - reference;
    p.secant = 2.0 * p.energyAbove / (r.curvature * r.curvature);
    c.points.push_back(p);
  }
  // Moment and tangent: derivatives of the interpolant g(t) = ln ΔU, t = ln κ, quadratic in t
  // through the ring and its two neighbours (the tightest ring takes the last three, the
  // gentlest the first three); U' = ΔU g' / κ, U'' = ΔU (g'' + g'² − g') / κ². Exact for a power
  // law ΔU = A κ^p (quadratic: the secant), second order otherwise. With two rings g is linear
  // (the power law through both); with one ring, the quadratic through it and the reference.
  bool positive = true;
  for (const BendCurvePoint& p : c.points) positive = positive && p.energyAbove > 0.0;
  for (int i = 0; i < n; ++i) {
    BendCurvePoint& p = c.points[i];
    const double k = p.sample.curvature;
    if (n == 1 || !positive) {
      p.moment = p.secant * k;
      p.tangent = p.secant;
      continue;
    }
    const int m = std::min(n, 3);
    const int first = std::clamp(i - 1, 0, n - m);
    Eigen::MatrixXd a(m, m);
    Eigen::VectorXd y(m);
    const double t0 = std::log(k);
    for (int r = 0; r < m; ++r) {
      const double t = std::log(c.points[first + r].sample.curvature) - t0;
      a(r, 0) = 1.0;
      a(r, 1) = t;
      if (m == 3) a(r, 2) = t * t;
      y(r) = std::log(c.points[first + r].energyAbove);
    }
    const Eigen::VectorXd g = a.fullPivLu().solve(y);
    const double g1 = g(1), g2 = m == 3 ? 2.0 * g(2) : 0.0;
    const double du = std::exp(g(0));  // the interpolant at κ: ΔU itself
    p.moment = du * g1 / k;
    p.tangent = du * (g2 + g1 * g1 - g1) / (k * k);
  }
  if (!positive)
    c.warnings.push_back(fmt::format(
        "{}: a ring at or below the straight reference's energy: the curve is not convex; moment and tangent "
        "are the secant's", q));

  // Quadratic regime from the gentlest ring on.
  const double sigmaU = std::sqrt(2.0) * o.energyNoise;  // the ring's and the reference's noise
  auto secantSigma = [&](const BendCurvePoint& p) {
    return 2.0 * sigmaU / (p.sample.curvature * p.sample.curvature);
  };
  const BendCurvePoint& g = c.points.front();
  c.quadraticPoints = 1;
  for (int i = 1; i < n; ++i) {
    const BendCurvePoint& p = c.points[i];
    const double allowed = o.tolerance * std::abs(g.secant) + 3.0 * std::hypot(secantSigma(p), secantSigma(g));
    if (std::abs(p.secant - g.secant) > allowed) break;
    ++c.quadraticPoints;
  }
  for (int i = 0; i < c.quadraticPoints; ++i) c.points[i].quadratic = true;
  c.quadraticVerified = c.quadraticPoints >= 2;
  c.quadraticMaxCurvature = c.points[c.quadraticPoints - 1].sample.curvature;
  c.linear = quadraticThroughReference({c.points.begin(), c.points.begin() + c.quadraticPoints});
  if (n == 1) {
    c.warnings.push_back(fmt::format(
        "{}: one ring (R = {:.4g} nm): the quadratic regime is not verified; add gentler rings", q, radiusNm(g.sample.curvature)));
  } else if (!c.quadraticVerified) {
    const BendCurvePoint& h = c.points[1];
    c.warnings.push_back(fmt::format(
        "{}: no quadratic regime in the sampled curvatures: the secant stiffness changes by {:+.3g}% from the "
        "gentlest ring (R = {:.4g} nm) to the next (R = {:.4g} nm), beyond the tolerance {:.3g}%; the linear "
        "regime lies at gentler curvatures (R > {:.4g} nm) than sampled, and no constant here is its value",
        q, 100.0 * (h.secant / g.secant - 1.0), radiusNm(g.sample.curvature), radiusNm(h.sample.curvature),
        100.0 * o.tolerance, radiusNm(g.sample.curvature)));
  }

  // Anchored quartic law over all rings.
  if (n >= 2) {
    Eigen::MatrixXd a(n, 2);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
      const double k2 = c.points[i].sample.curvature * c.points[i].sample.curvature;
      a(i, 0) = 0.5 * k2;
      a(i, 1) = -k2 * k2;
      y(i) = c.points[i].energyAbove;
    }
    const Solution s = solve(a, y);
    c.hasQuartic = true;
    c.quarticStiffness = {s.coef(0), s.error(0), n};
    c.quarticCoefficient = s.coef(1);
    c.quarticError = s.error(1);
  }
  // Free-offset fit over all rings: what a fit that leaves U(0) free makes of the same points.
  if (n >= 3) {
    Eigen::MatrixXd a(n, 2);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
      a(i, 0) = 1.0;
      a(i, 1) = 0.5 * c.points[i].sample.curvature * c.points[i].sample.curvature;
      y(i) = c.points[i].energyAbove;
    }
    const Solution s = solve(a, y);
    c.hasFreeOffset = true;
    c.freeOffset = s.coef(0);
    c.freeOffsetError = s.error(0);
    c.freeStiffness = {s.coef(1), s.error(1), n};
    // The offset stands out when it exceeds the noise of one point (3 sigma) and, for exact
    // energies, a tolerance's share of the smallest bending energy.
    const double noise = std::hypot(3.0 * c.freeOffsetError, 3.0 * sigmaU);
    const double floor = o.tolerance * std::abs(g.energyAbove);
    if (std::abs(c.freeOffset) > std::max(noise, floor))
      c.warnings.push_back(fmt::format(
          "{}: a fit with U(0) free, U0 + D k^2/2 over all rings, gives D = {:.6g} +- {:.2g} with U0 {:+.3g} Ha "
          "from the straight reference ({:.3g} of its standard errors, {:.3g}x the gentlest ring's bending energy): "
          "the free offset absorbs a curve that is not quadratic; the anchored secant runs from {:.6g} to {:.6g}",
          q, c.freeStiffness.value, c.freeStiffness.error, c.freeOffset,
          c.freeOffsetError > 0.0 ? std::abs(c.freeOffset) / c.freeOffsetError : INFINITY,
          std::abs(c.freeOffset / g.energyAbove), g.secant, c.points.back().secant));
  }

  if (o.window) {
    WindowConstant w;
    w.lo = o.window->first, w.hi = o.window->second;
    std::vector<BendCurvePoint> in;
    for (const BendCurvePoint& p : c.points)
      if (p.sample.curvature >= w.lo * (1 - 1e-12) && p.sample.curvature <= w.hi * (1 + 1e-12)) in.push_back(p);
    if (in.empty())
      throw InputError(o.source, "curvature window",
                       fmt::format("[{:.6g}, {:.6g}] per Bohr (R = {:.4g} to {:.4g} nm) holds no ring", w.lo, w.hi,
                                   radiusNm(w.hi), w.lo > 0.0 ? radiusNm(w.lo) : INFINITY),
                       fmt::format("a window over the rings, curvatures {:.6g} to {:.6g} per Bohr",
                                   g.sample.curvature, c.points.back().sample.curvature));
    w.stiffness = quadraticThroughReference(in);
    w.secantMin = w.secantMax = in.front().secant;
    w.quadratic = true;
    for (const BendCurvePoint& p : in) {
      w.secantMin = std::min(w.secantMin, p.secant), w.secantMax = std::max(w.secantMax, p.secant);
      w.quadratic = w.quadratic && p.quadratic;
    }
    w.quadratic = w.quadratic && c.quadraticVerified;
    if (!w.quadratic)
      c.warnings.push_back(fmt::format(
          "{}: the window R = {:.4g} to {:.4g} nm is not in the quadratic regime (verified: {}; up to {:.6g} per Bohr, "
          "R >= {:.4g} nm): its constant {:.6g} is an effective one for this window, the secant runs from {:.6g} to "
          "{:.6g} in it",
          q, radiusNm(w.hi), w.lo > 0.0 ? radiusNm(w.lo) : INFINITY, c.quadraticVerified ? "yes" : "no",
          c.quadraticMaxCurvature, radiusNm(c.quadraticMaxCurvature), w.stiffness.value, w.secantMin, w.secantMax));
    c.window = w;
  }
  return c;
}

}  // namespace mesochain::beam
