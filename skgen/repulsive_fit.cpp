#include "skgen/repulsive_fit.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {

// Cardinal cubic B-spline B(t) on [0, 4] and its first three derivatives (right limits at the
// knots: the piece is chosen by floor(t)).
void cardinal(double t, double d[4]) {
  d[0] = d[1] = d[2] = d[3] = 0.0;
  if (t < 0.0 || t >= 4.0) return;
  const int piece = static_cast<int>(std::floor(t));
  switch (piece) {
    case 0:
      d[0] = t * t * t / 6.0, d[1] = t * t / 2.0, d[2] = t, d[3] = 1.0;
      break;
    case 1:
      d[0] = (-3 * t * t * t + 12 * t * t - 12 * t + 4) / 6.0;
      d[1] = (-9 * t * t + 24 * t - 12) / 6.0, d[2] = (-18 * t + 24) / 6.0, d[3] = -3.0;
      break;
    case 2:
      d[0] = (3 * t * t * t - 24 * t * t + 60 * t - 44) / 6.0;
      d[1] = (9 * t * t - 48 * t + 60) / 6.0, d[2] = (18 * t - 48) / 6.0, d[3] = 3.0;
      break;
    default: {
      const double u = 4.0 - t;
      d[0] = u * u * u / 6.0, d[1] = -u * u / 2.0, d[2] = u, d[3] = -1.0;
    }
  }
}

}  // namespace

DimerCurve readDimerCurve(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "no readable file", "a CSV dimer curve 'r_bohr,energy_hartree'");
  DimerCurve c;
  c.source = path;
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    line.erase(std::remove_if(line.begin(), line.end(), [](char ch) { return ch == ' ' || ch == '\r' || ch == '\t'; }),
               line.end());
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line != "r_bohr,energy_hartree")
        throw InputError(path, fmt::format("line {}", number), "header '" + line + "'",
                         "the header 'r_bohr,energy_hartree' (units in the column names)");
      header = true;
      continue;
    }
    std::istringstream ss(line);
    double r, e;
    char comma;
    if (!(ss >> r >> comma >> e) || comma != ',' || !ss.eof() || !std::isfinite(r) || !std::isfinite(e))
      throw InputError(path, fmt::format("line {}", number), "'" + line + "'", "two finite numbers 'r,energy'");
    if (!c.r.empty() && !(r > c.r.back()))
      throw InputError(path, fmt::format("line {}", number), fmt::format("r = {} after {}", r, c.r.back()),
                       "increasing distances");
    if (!(r > 0.0)) throw InputError(path, fmt::format("line {}", number), fmt::format("r = {}", r), "r > 0");
    c.r.push_back(r);
    c.energy.push_back(e);
  }
  if (c.r.size() < 4)
    throw InputError(path, "", fmt::format("{} points", c.r.size()), "at least 4 points of the dimer curve");
  return c;
}

double dimerElectronicEnergy(const ElementBasis& a, const ElementBasis& b, XcKind xc,
                             const TwoCentreQuadrature& q, double r) {
  // orbitals per atom: s, then p_x, p_y, p_z for a p shell; the dimer axis is z, so σ couples
  // s and p_z, π couples p_x with p_x and p_y with p_y
  auto layout = [](const ElementBasis& e) {
    std::vector<std::pair<int, int>> o;  // (orbital index in e.orbitals, m: −1 x, 0 z/s, +1 y)
    for (int k = 0; k < static_cast<int>(e.orbitals.size()); ++k) {
      if (e.orbitals[k].l == 0) o.push_back({k, 0});
      else for (int m : {-1, 1, 0}) o.push_back({k, m});
    }
    return o;
  };
  const auto oa = layout(a), ob = layout(b);
  const int na = static_cast<int>(oa.size()), nb = static_cast<int>(ob.size()), n = na + nb;
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n), s = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < na; ++i) h(i, i) = a.data.onsite[a.orbitals[oa[i].first].l];
  for (int j = 0; j < nb; ++j) h(na + j, na + j) = b.data.onsite[b.orbitals[ob[j].first].l];
  const XcFunctional f(xc, false);
  const auto integrals = twoCentreIntegrals(a.orbitals, b.orbitals, &a.atom, &b.atom, &f, r, q);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      const int mi = oa[i].second, mj = ob[j].second;
      if (mi != mj) continue;  // σ with σ (m = 0), π_x with π_x, π_y with π_y
      for (const SkIntegral& I : integrals)
        if (I.a == oa[i].first && I.b == ob[j].first && I.m == std::abs(mi)) {
          h(i, na + j) = h(na + j, i) = I.h;
          s(i, na + j) = s(na + j, i) = I.s;
        }
    }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(h, s);
  double electrons = 0.0;
  for (double occ : a.data.occupation) electrons += occ;
  for (double occ : b.data.occupation) electrons += occ;
  const Eigen::VectorXd& e = es.eigenvalues();
  double energy = 0.0;
  int k = 0;
  while (electrons > 1e-12 && k < n) {
    int g = k;  // degenerate group [k, g)
    while (g < n && std::abs(e[g] - e[k]) < 1e-8) ++g;
    const double put = std::min(electrons, 2.0 * (g - k));
    for (int i = k; i < g; ++i) energy += put / (g - k) * e[i];
    electrons -= put;
    k = g;
  }
  return energy;
}

dftb::SplineRepulsiveData fitRepulsiveSpline(const std::vector<double>& r,
                                             const std::vector<double>& y, double cutoff,
                                             int intervals, const std::string& source,
                                             const std::string& key) {
  if (intervals < 1) throw InputError(source, key, fmt::format("{} intervals", intervals), "at least 1");
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (r[i] < cutoff) {
      xs.push_back(r[i]);
      ys.push_back(y[i]);
    }
  if (xs.empty() || !(cutoff > xs.front()))
    throw InputError(source, key, fmt::format("cutoff {} bohr", cutoff), "a cutoff beyond the shortest reference distance");
  const double r0 = xs.front(), h = (cutoff - r0) / intervals;
  // basis j = −3 .. intervals − 4 (the three non-zero at the cutoff dropped)
  const int nb = intervals;
  if (static_cast<int>(xs.size()) < nb + 1)
    throw InputError(source, key, fmt::format("{} reference points below the cutoff", xs.size()),
                     fmt::format("more points than spline intervals ({})", intervals));
  Eigen::MatrixXd A(xs.size(), nb);
  Eigen::VectorXd b(xs.size());
  double d[4];
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double t = (xs[i] - r0) / h;
    for (int j = 0; j < nb; ++j) {
      cardinal(t - (j - 3), d);
      A(i, j) = d[0];
    }
    b[i] = ys[i];
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < nb)
    throw InputError(source, key, "spline intervals without reference points",
                     "fewer intervals or reference points spread over [r_min, cutoff]");
  const Eigen::VectorXd c = qr.solve(b);
  // value and derivatives (d/dr) at r, right limits
  auto eval = [&](double x, double out[4]) {
    out[0] = out[1] = out[2] = out[3] = 0.0;
    const double t = (x - r0) / h;
    for (int j = 0; j < nb; ++j) {
      cardinal(t - (j - 3), d);
      for (int k = 0; k < 4; ++k) out[k] += c[j] * d[k] / std::pow(h, k);
    }
  };
  dftb::SplineRepulsiveData s;
  s.declaredCutoff = cutoff;
  // Taylor coefficients about each interval start, from the derivatives at the interval's
  // midpoint (inside one polynomial piece, so no left/right ambiguity at the knots)
  for (int k = 0; k < intervals; ++k) {
    double m[4];
    eval(r0 + (k + 0.5) * h, m);
    const double u = -0.5 * h;  // start − midpoint
    s.start.push_back(r0 + k * h);
    s.end.push_back(k + 1 == intervals ? cutoff : r0 + (k + 1) * h);
    s.coeffs.push_back({m[0] + u * (m[1] + u * (m[2] / 2.0 + u * m[3] / 6.0)),
                        m[1] + u * (m[2] + u * m[3] / 2.0), (m[2] + u * m[3]) / 2.0, m[3] / 6.0, 0.0,
                        0.0});
  }
  const double v[3] = {s.coeffs[0][0], s.coeffs[0][1], 2.0 * s.coeffs[0][2]};
  if (!(v[1] < 0.0) || !(v[2] > 0.0))
    throw InputError(source, key,
                     fmt::format("a fitted repulsive with E' = {:.4g} Ha/bohr, E'' = {:.4g} Ha/bohr² at r_min = {} bohr",
                                 v[1], v[2], r0),
                     "a repulsive (E' < 0, E'' > 0) at the shortest distance, for the exponential head");
  const double a1 = -v[2] / v[1];
  const double amp = -v[1] / a1;  // e^{−a1 r0 + a2}
  s.expHead = {a1, std::log(amp) + a1 * r0, v[0] - amp};
  return s;
}

dftb::SplineRepulsiveData fitRepulsive(const ElementBasis& a, const ElementBasis& b, XcKind xc,
                                       const TwoCentreQuadrature& q, const DimerCurve& curve,
                                       double cutoff, int intervals, const std::string& key) {
  if (!(curve.r.back() >= cutoff))
    throw InputError(curve.source, key, fmt::format("a curve ending at {} bohr", curve.r.back()),
                     fmt::format("reference points up to the repulsive cutoff ({} bohr)", cutoff));
  // E_ref(r_c) by linear interpolation between the neighbouring points
  const auto it = std::lower_bound(curve.r.begin(), curve.r.end(), cutoff);
  const std::size_t i = static_cast<std::size_t>(it - curve.r.begin());
  double refC = curve.energy[i];
  if (i > 0 && curve.r[i] != cutoff) {
    const double w = (cutoff - curve.r[i - 1]) / (curve.r[i] - curve.r[i - 1]);
    refC = (1 - w) * curve.energy[i - 1] + w * curve.energy[i];
  }
  const double elC = dimerElectronicEnergy(a, b, xc, q, cutoff);
  std::vector<double> r, y;
  for (std::size_t k = 0; k < curve.r.size() && curve.r[k] < cutoff; ++k) {
    r.push_back(curve.r[k]);
    y.push_back((curve.energy[k] - refC) - (dimerElectronicEnergy(a, b, xc, q, curve.r[k]) - elC));
  }
  return fitRepulsiveSpline(r, y, cutoff, intervals, curve.source, key);
}

}  // namespace mesochain::skgen
