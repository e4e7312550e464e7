#include "beam/curve_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::beam {

namespace {

struct LeastSquares {
  Eigen::VectorXd coef;
  Eigen::MatrixXd covariance;  // residual variance times (A^T A)^-1
  bool ok = false;
};

// Ordinary least squares with the covariance of the coefficients (needs rows > columns).
LeastSquares leastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& y) {
  LeastSquares r;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < a.cols()) return r;
  r.coef = qr.solve(y);
  const double rss = (a * r.coef - y).squaredNorm();
  const double dof = static_cast<double>(a.rows() - a.cols());
  const Eigen::MatrixXd normal = a.transpose() * a;
  r.covariance = (rss / dof) * normal.ldlt().solve(Eigen::MatrixXd::Identity(a.cols(), a.cols()));
  r.ok = true;
  return r;
}

// Columns in the scaled variable t = x / X: [1], [t], t^2/2, then with `extended` t^4 [and t^3].
// Returns the indices of the constant, t^2/2, t, t^4 and t^3 columns (-1 when absent); the
// constant is absent when U(0) is anchored.
struct Basis {
  int constant = -1, quadratic = -1, linear = -1, quartic = -1, cubic = -1;
  int columns = 0;
};

Basis makeBasis(bool linearTerm, bool extended, bool anchored) {
  Basis b;
  int c = 0;
  if (!anchored) b.constant = c++;
  if (linearTerm) b.linear = c++;
  b.quadratic = c++;
  if (extended) {
    b.quartic = c++;
    if (linearTerm) b.cubic = c++;
  }
  b.columns = c;
  return b;
}

Eigen::MatrixXd design(const std::vector<CurvePoint>& p, int n, double scale, const Basis& b) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, b.columns);
  for (int i = 0; i < n; ++i) {
    const double t = p[i].x / scale;
    if (b.constant >= 0) a(i, b.constant) = 1.0;
    if (b.linear >= 0) a(i, b.linear) = t;
    a(i, b.quadratic) = 0.5 * t * t;
    if (b.quartic >= 0) a(i, b.quartic) = t * t * t * t;
    if (b.cubic >= 0) a(i, b.cubic) = t * t * t;
  }
  return a;
}

// Number of distinct values of x (or |x| for an even model) among the first n points.
int distinctValues(const std::vector<CurvePoint>& p, int n, bool even) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(even ? std::abs(p[i].x) : p[i].x);
  std::sort(v.begin(), v.end());
  int count = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (i == 0 || v[i] - v[i - 1] > 1e-12 * std::max(std::abs(v[i]), std::abs(v[i - 1])) + 1e-300) ++count;
  return count;
}

// Critical value of Student's t with `dof` degrees of freedom at the two-sided level of a
// normal z-score: the Cornish-Fisher expansion of Abramowitz & Stegun 26.7.5 (terms to 1/nu^3).
// Small windows estimate their noise from few residuals; this keeps them from looking
// "significant" by chance.
double studentCritical(double z, double dof) {
  const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2;
  const double g1 = (z3 + z) / 4.0;
  const double g2 = (5.0 * z5 + 16.0 * z3 + 3.0 * z) / 96.0;
  const double g3 = (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / 384.0;
  return z + g1 / dof + g2 / (dof * dof) + g3 / (dof * dof * dof);
}

double ratioOrInfinity(double num, double den) {
  if (den > 0.0) return num / den;
  return num > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

struct WindowResult {
  WindowFit fit;
  double slope = 0.0, slopeError = 0.0, energy0 = 0.0;
};

// Quadratic (and, when possible, extended) fit of the first n points.
bool fitWindow(const std::vector<CurvePoint>& p, int n, const FitOptions& o, WindowResult& out) {
  const double scale = std::abs(p[n - 1].x);
  const bool anchored = o.anchorEnergy.has_value();
  const Basis quad = makeBasis(o.linearTerm, false, anchored);
  if (n < quad.columns + 1 || distinctValues(p, n, !o.linearTerm) < quad.columns) return false;
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) y(i) = p[i].energy;
  const LeastSquares q = leastSquares(design(p, n, scale, quad), y);
  if (!q.ok) return false;
  WindowFit& w = out.fit;
  w.halfWidth = scale;
  w.points = n;
  const double s2 = scale * scale;
  w.stiffness = q.coef(quad.quadratic) / s2;
  w.standardError = std::sqrt(std::max(0.0, q.covariance(quad.quadratic, quad.quadratic))) / s2;
  out.energy0 = quad.constant >= 0 ? q.coef(quad.constant) : 0.0;
  if (quad.linear >= 0) {
    out.slope = q.coef(quad.linear) / scale;
    out.slopeError = std::sqrt(std::max(0.0, q.covariance(quad.linear, quad.linear))) / scale;
  }
  const Basis ext = makeBasis(o.linearTerm, true, anchored);
  if (n >= ext.columns + 1 && distinctValues(p, n, !o.linearTerm) >= ext.columns) {
    const LeastSquares e = leastSquares(design(p, n, scale, ext), y);
    if (e.ok && e.coef(ext.quadratic) != 0.0) {
      w.hasExtended = true;
      w.extendedStiffness = e.coef(ext.quadratic) / s2;
      w.extendedError = std::sqrt(std::max(0.0, e.covariance(ext.quadratic, ext.quadratic))) / s2;
      const double a2 = std::abs(e.coef(ext.quadratic));
      // Energy of the higher term at the window edge relative to the quadratic one: 2|a4|/a2.
      const double critical = studentCritical(o.zScore, n - ext.columns);
      auto term = [&](int col) {
        const double rel = 2.0 * std::abs(e.coef(col)) / a2;
        const double z = ratioOrInfinity(std::abs(e.coef(col)), std::sqrt(std::max(0.0, e.covariance(col, col))));
        w.anharmonicity = std::max(w.anharmonicity, rel);
        w.anharmonicZ = std::max(w.anharmonicZ, z);
        if (rel > o.relativeTolerance && z > critical) w.anharmonicTooLarge = true;
      };
      term(ext.quartic);
      if (ext.cubic >= 0) term(ext.cubic);
    }
  }
  return true;
}

// Criterion (d) of an anchored fit: the secant of the window's edge point against that of its
// innermost point (energies already relative to the anchor; points sorted by |x|).
bool secantDrift(const std::vector<CurvePoint>& p, int n, const FitOptions& o, WindowFit& f) {
  const CurvePoint& a = p.front();
  const CurvePoint& b = p[n - 1];
  auto secant = [](const CurvePoint& c) { return 2.0 * c.energy / (c.x * c.x); };
  auto sigma = [&](const CurvePoint& c) { return 2.0 * std::sqrt(2.0) * o.energyNoise / (c.x * c.x); };
  const double sa = secant(a), sb = secant(b);
  if (std::abs(sb - sa) <= o.relativeTolerance * std::abs(sa) + 3.0 * std::hypot(sigma(a), sigma(b))) return false;
  f.rejection = fmt::format(
      "not quadratic: the secant 2 (U - U(0)) / x^2 changes from {:.6g} (|x| = {:.6g}) to {:.6g} (|x| = {:.6g}), "
      "{:+.3g}%, beyond the tolerance {:.3g}%",
      sa, std::abs(a.x), sb, std::abs(b.x), 100.0 * (sb / sa - 1.0), 100.0 * o.relativeTolerance);
  return true;
}

}  // namespace

QuadraticFit fitQuadraticRegime(std::vector<CurvePoint> points, const FitOptions& o) {
  const std::string& q = o.quantity;
  for (const CurvePoint& pt : points) {
    requireFinite(pt.x, o.source, q + " curve: deformation");
    requireFinite(pt.energy, o.source, q + " curve: energy");
  }
  if (!(o.relativeTolerance > 0.0) || !(o.zScore > 0.0))
    throw InputError(o.source, "fit options", "a non-positive tolerance", "tolerance > 0 and z > 0");
  const bool anchored = o.anchorEnergy.has_value();
  if (anchored) requireFinite(*o.anchorEnergy, o.source, q + " curve: anchor energy U(0)");
  int dropped = 0;
  if (anchored) {
    // The reference itself: its energy is the anchor, not a data point of the fit.
    const auto atZero = [](const CurvePoint& p) { return p.x == 0.0; };
    dropped = static_cast<int>(std::count_if(points.begin(), points.end(), atZero));
    points.erase(std::remove_if(points.begin(), points.end(), atZero), points.end());
  }
  const int parameters = (anchored ? 0 : 1) + (o.linearTerm ? 1 : 0) + 1;
  const int minimum = parameters + 1;
  const int total = static_cast<int>(points.size());
  if (total < minimum)
    throw InputError(o.source, fmt::format(
        "{} curve: too few points ({}{}); a quadratic fit{}{} needs at least {} points near x = 0",
        q, total, anchored ? " besides the reference at x = 0" : "", o.linearTerm ? " with a linear term" : "",
        anchored ? " anchored at U(0)" : "", minimum));
  std::stable_sort(points.begin(), points.end(),
                   [](const CurvePoint& a, const CurvePoint& b) { return std::abs(a.x) < std::abs(b.x); });
  // Energies relative to the anchor, or to the point nearest x = 0 (conditioning).
  const double e0 = anchored ? *o.anchorEnergy : points.front().energy;
  for (CurvePoint& pt : points) pt.energy -= e0;

  QuadraticFit result;
  result.pointsTotal = total;
  result.anchored = anchored;
  result.referencePointsDropped = dropped;
  std::vector<WindowResult> accepted;
  const double tol = o.relativeTolerance;
  for (int n = minimum; n <= total; ++n) {
    // Windows end at a change of |x| so that points at the same distance enter together.
    if (n < total && std::abs(std::abs(points[n].x) - std::abs(points[n - 1].x)) <=
                         1e-12 * std::abs(points[n].x))
      continue;
    WindowResult w;
    if (!fitWindow(points, n, o, w)) continue;
    WindowFit& f = w.fit;
    if (!(f.stiffness > 0.0)) {
      f.rejection = fmt::format("not convex: {} = {:.6g} <= 0", q, f.stiffness);
    } else if (f.anharmonicTooLarge) {
      f.rejection = fmt::format(
          "anharmonic: the next term changes the energy at |x| = {:.6g} by {:.3g}% of the quadratic "
          "one ({:.1f} standard errors), beyond the tolerance {:.3g}%",
          f.halfWidth, 100.0 * f.anharmonicity, f.anharmonicZ, 100.0 * tol);
    } else if (anchored && !o.linearTerm && secantDrift(points, n, o, f)) {
      // f.rejection set by secantDrift
    } else {
      for (const WindowResult& a : accepted) {
        const double diff = std::abs(f.stiffness - a.fit.stiffness);
        const double noise = std::hypot(f.standardError, a.fit.standardError);
        const int dof = a.fit.points - parameters;  // the smaller window's
        if (diff > tol * a.fit.stiffness && diff > studentCritical(o.zScore, dof) * noise) {
          f.rejection = fmt::format(
              "{} changes from {:.6g} (|x| <= {:.6g}) to {:.6g} (|x| <= {:.6g}): {:.3g}%, beyond the "
              "tolerance {:.3g}% and {:.3g} standard errors",
              q, a.fit.stiffness, a.fit.halfWidth, f.stiffness, f.halfWidth,
              100.0 * diff / a.fit.stiffness, 100.0 * tol, o.zScore);
          break;
        }
      }
    }
    f.accepted = f.rejection.empty();
    result.windows.push_back(f);
    if (!f.accepted) break;
    accepted.push_back(w);
  }
  if (result.windows.empty())
    throw InputError(o.source, fmt::format(
        "{} curve: too few distinct deformations near x = 0 for a quadratic fit{} ({} points)", q,
        o.linearTerm ? " with a linear term" : "", total));
  const WindowFit& last = result.windows.back();
  if (accepted.empty())
    throw InputError(o.source, fmt::format(
        "{} curve: no quadratic regime: the smallest window (|x| <= {:.6g}, {} points) is {}",
        q, last.halfWidth, last.points, last.rejection));
  if (accepted.size() == 1 && !last.accepted)
    throw InputError(o.source, fmt::format(
        "{} curve: no quadratic regime: {}; only the smallest window (|x| <= {:.6g}, {} points) is "
        "left, too few to verify; add points at smaller deformations",
        q, last.rejection, accepted.front().fit.halfWidth, accepted.front().fit.points));

  const WindowResult& best = accepted.back();
  const WindowFit& b = best.fit;
  result.stiffness = b.stiffness;
  result.statisticalError = b.standardError;
  if (b.hasExtended) {
    // Squared bias estimate: the squared change of k when the next term is added, less its
    // variance under pure noise, Var(k - k_ext) = Var(k_ext) - Var(k) (Hausman's difference
    // test: k is the efficient estimator when the quadratic model holds).
    const double d = b.stiffness - b.extendedStiffness;
    const double noiseVariance = std::max(0.0, b.extendedError * b.extendedError - b.standardError * b.standardError);
    result.truncationError = std::sqrt(std::max(0.0, d * d - noiseVariance));
  }
  result.uncertainty = std::hypot(result.statisticalError, result.truncationError);
  if (accepted.size() >= 2)
    result.windowSpread = std::abs(b.stiffness - accepted[accepted.size() - 2].fit.stiffness);
  result.slope = best.slope;
  result.slopeError = best.slopeError;
  result.energy0 = best.energy0 + e0;
  result.windowHalfWidth = b.halfWidth;
  result.pointsUsed = b.points;
  result.regimeVerified = accepted.size() >= 2;
  if (last.accepted)
    result.note = result.regimeVerified ? "all points are in the quadratic regime"
                                        : "a single window: the quadratic regime is not verified";
  else
    result.note = "the window stopped growing: " + last.rejection;
  return result;
}

}  // namespace mesochain::beam
