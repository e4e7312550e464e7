#include "skgen/radial_schrodinger.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {

constexpr double kBig = 1e200;

// Numerov on φ'' = g φ with f = 1 − h² g / 12:
//   f_{i+1} φ_{i+1} = (12 − 10 f_i) φ_i − f_{i−1} φ_{i−1}.
class Shooter {
 public:
  Shooter(const LogGrid& g, const std::vector<double>& v, double z, int l)
      : g_(g), v_(v), z_(z), l_(l), n_(g.size()), f_(n_), phi_(n_), in_(n_) {}

  // Fills f_ at energy e; returns the outermost classical turning point m (−1 if none) and sets
  // end_, the last point used: the grid end, or earlier where the solution is deep in the
  // forbidden region beyond m (h² g / 12 > 0.5, where Numerov loses stability and the state
  // is below 1e−100 of its peak).
  int prepare(double e) {
    const double h2 = g_.h * g_.h / 12.0;
    const double lh = (l_ + 0.5) * (l_ + 0.5);
    int m = -1;
    for (int i = 0; i < n_; ++i) {
      const double r = g_.r[i];
      const double gi = lh + 2.0 * r * r * (v_[i] - e);
      f_[i] = 1.0 - h2 * gi;
      if (gi < 0.0) m = i;
    }
    end_ = n_ - 1;
    for (int i = std::max(m, 2); i < n_; ++i) {
      if (f_[i] < 0.5) {
        end_ = i;
        break;
      }
    }
    return m;
  }

  // Nodes of the outward solution over the whole grid (Dirichlet at the end point): equals the
  // number of eigenvalues below e (Sturm oscillation theorem for the discrete problem).
  int nodes(double e) {
    const int m = prepare(e);
    if (m < 2) return -1;  // below the potential everywhere
    outward(end_);
    int count = 0;
    for (int i = 1; i < end_; ++i)
      if (phi_[i] * phi_[i + 1] < 0.0 || (phi_[i] == 0.0 && i > 1)) ++count;
    return count;
  }

  // Eigenfunction at (the converged) e: outward to the turning point, inward from the end,
  // scaled to join at the turning point.
  void eigenfunction(double e) {
    int m = prepare(e);
    if (m < 2) m = 2;
    if (m > end_ - 2) m = end_ - 2;
    outward(m);
    const double outM = phi_[m];
    std::fill(in_.begin(), in_.end(), 0.0);
    in_[end_ - 1] = 1e-100;
    for (int i = end_ - 1; i > m; --i) {
      in_[i - 1] = ((12.0 - 10.0 * f_[i]) * in_[i] - f_[i + 1] * in_[i + 1]) / f_[i - 1];
      if (std::abs(in_[i - 1]) > kBig) {
        for (int k = i - 1; k <= end_; ++k) in_[k] /= kBig;
      }
    }
    const double scale = outM / in_[m];
    for (int i = m + 1; i < n_; ++i) phi_[i] = in_[i] * scale;
  }

  const std::vector<double>& phi() const { return phi_; }

 private:
  void outward(int last) {
    for (int i = 0; i < 2; ++i) {
      const double r = g_.r[i];
      phi_[i] = std::pow(r, l_ + 0.5) * (1.0 - z_ * r / (l_ + 1.0));
    }
    for (int i = 1; i < last; ++i) {
      phi_[i + 1] = ((12.0 - 10.0 * f_[i]) * phi_[i] - f_[i - 1] * phi_[i - 1]) / f_[i + 1];
      if (std::abs(phi_[i + 1]) > kBig) {
        for (int k = 0; k <= i + 1; ++k) phi_[k] /= kBig;
      }
    }
    for (int i = last + 1; i < n_; ++i) phi_[i] = 0.0;
  }

  const LogGrid& g_;
  const std::vector<double>& v_;
  double z_;
  int l_;
  int n_;
  int end_ = 0;
  std::vector<double> f_, phi_, in_;
};

}  // namespace

RadialState solveRadial(const LogGrid& grid, const std::vector<double>& v, double z, int n,
                        int l, double guess) {
  const int k = n - l - 1;
  if (k < 0) throw std::invalid_argument("solveRadial: need n > l");
  Shooter sh(grid, v, z, l);
  const std::string what = "radial state n=" + std::to_string(n) + " l=" + std::to_string(l);

  // Bracket [lo, hi]: nodes(lo) <= k < nodes(hi).
  double vmin = 0.0, vmax = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < grid.size(); ++i) {
    const double r = grid.r[i];
    const double w = v[i] + l * (l + 1) / (2.0 * r * r);
    vmin = std::min(vmin, w);
    vmax = std::max(vmax, w);
  }
  double lo = vmin, hi = vmax;
  if (std::isfinite(guess)) {
    double step = std::max(1e-4, 1e-4 * std::abs(guess));
    double a = guess - step;
    while (a > vmin && sh.nodes(a) > k) {
      step *= 4.0;
      a = guess - step;
    }
    if (a > vmin) lo = a;
    step = std::max(1e-4, 1e-4 * std::abs(guess));
    double b = guess + step;
    while (b < vmax && sh.nodes(b) <= k) {
      step *= 4.0;
      b = guess + step;
    }
    if (b < vmax) hi = b;
  }
  if (sh.nodes(hi) <= k) {
    throw NumericalError(what + ": no eigenvalue below the largest potential value on the grid (" +
                         std::to_string(vmax) + " Ha); enlarge r_max or check the potential");
  }
  for (int it = 0; it < 400; ++it) {
    const double e = 0.5 * (lo + hi);
    if (!(e > lo && e < hi)) break;
    if (sh.nodes(e) <= k) lo = e; else hi = e;
  }
  RadialState st;
  st.energy = 0.5 * (lo + hi);
  if (sh.nodes(lo) != k) {
    throw NumericalError(what + ": eigenvalue search failed (node count " +
                         std::to_string(sh.nodes(lo)) + " at the bracket, expected " +
                         std::to_string(k) + ")");
  }
  sh.eigenfunction(st.energy);
  const std::vector<double>& phi = sh.phi();
  // normalise: ∫ u² dr = ∫ r² φ² dx
  std::vector<double> w(grid.size());
  for (int i = 0; i < grid.size(); ++i) w[i] = grid.r[i] * grid.r[i] * phi[i] * phi[i];
  const double norm = std::sqrt(grid.integrateDx(w));
  const double sign = phi[0] >= 0.0 ? 1.0 : -1.0;
  st.u.resize(grid.size());
  for (int i = 0; i < grid.size(); ++i) st.u[i] = sign * std::sqrt(grid.r[i]) * phi[i] / norm;
  return st;
}

}  // namespace mesochain::skgen
