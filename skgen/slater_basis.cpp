#include "skgen/slater_basis.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {

// ∫_0^∞ r^m e^{−βr} dr = m! / β^{m+1}
double gammaIntegral(int m, double beta) {
  if (m < 0) throw std::logic_error("Slater integral with a negative power");
  return std::exp(std::lgamma(m + 1.0) - (m + 1.0) * std::log(beta));
}

}  // namespace

SlaterValue evaluateSlater(const std::vector<SlaterTerm>& terms, int l, double r) {
  SlaterValue v;
  const double ll = l * (l + 1.0);
  for (const SlaterTerm& s : terms) {
    const double e = s.c * std::exp(-s.alpha * r);
    const int k = s.k;
    // r^{k−2}, r^{k−1}, r^k with the k = l cancellations done analytically (k >= l >= 0)
    const double rk = std::pow(r, k);
    const double rk1 = k >= 1 ? std::pow(r, k - 1) : 0.0;
    v.R += e * rk;
    v.dR += e * (k * rk1 - s.alpha * rk);
    // R'' + 2R'/r − l(l+1)R/r² = e [ (k(k+1) − l(l+1)) r^{k−2} − 2α(k+1) r^{k−1} + α² r^k ]
    const double a = k * (k + 1.0) - ll;
    const double rk2 = a != 0.0 ? std::pow(r, k - 2) : 0.0;
    double lap = a * rk2 + s.alpha * s.alpha * rk;
    if (k >= 1) lap -= 2.0 * s.alpha * (k + 1.0) * rk1;
    else lap -= 2.0 * s.alpha / r;  // k = l = 0: −2α/r, the s-orbital cusp term
    v.t += -0.5 * e * lap;
  }
  return v;
}

SlaterRadialSolver::SlaterRadialSolver(const SlaterBasis& basis, const LogGrid& grid, int l)
    : grid_(&grid), l_(l) {
  if (basis.exponents.empty() || basis.powers < 1)
    throw std::invalid_argument("Slater basis: need at least one exponent and one power");
  for (double a : basis.exponents)
    if (!(a > 0.0)) throw std::invalid_argument("Slater basis: exponents must be > 0");
  for (double a : basis.exponents)
    for (int i = 0; i < basis.powers; ++i) {
      power_.push_back(l + i);
      alpha_.push_back(a);
    }
  const int n = size();
  s_.resize(n, n);
  t_.resize(n, n);
  const double ll = l * (l + 1.0);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double beta = alpha_[a] + alpha_[b];
      const int ka = power_[a], kb = power_[b];
      s_(a, b) = gammaIntegral(ka + kb + 2, beta);
      // ∫ χ_a t_b r² dr, t_b from evaluateSlater's expansion
      const double ab = alpha_[b];
      const double a0 = kb * (kb + 1.0) - ll;  // zero for k = l (no r^{k−2} term)
      double t = a0 != 0.0 ? a0 * gammaIntegral(ka + kb, beta) : 0.0;
      t -= 2.0 * ab * (kb + 1.0) * gammaIntegral(ka + kb + 1, beta);
      t += ab * ab * gammaIntegral(ka + kb + 2, beta);
      t_(a, b) = -0.5 * t;
    }
  t_ = 0.5 * (t_ + t_.transpose()).eval();
  chi_.resize(n, grid.size());
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < grid.size(); ++i)
      chi_(a, i) = std::pow(grid.r[i], power_[a]) * std::exp(-alpha_[a] * grid.r[i]);
}

std::vector<SlaterState> SlaterRadialSolver::solve(const std::vector<double>& v, int count) const {
  const LogGrid& g = *grid_;
  const int n = size();
  const int np = g.size();
  if (count > n)
    throw NumericalError(fmt::format("Slater basis of {} functions for l = {} cannot hold {} states",
                                     n, l_, count));
  // V_ab = ∫ χ_a v χ_b r² dr = ∫ χ_a χ_b v r³ dx (trapezoid in x)
  Eigen::VectorXd w(np);
  for (int i = 0; i < np; ++i) w[i] = v[i] * g.r[i] * g.r[i] * g.r[i] * g.h;
  w[0] *= 0.5;
  w[np - 1] *= 0.5;
  // row-by-row dot products: an Eigen matrix product here would be spread over OpenMP threads,
  // which costs far more than it saves for a 12 x 2000 x 12 product on a shared machine
  Eigen::MatrixXd h = t_;
  for (int a = 0; a < n; ++a) {
    const Eigen::RowVectorXd cw = chi_.row(a).cwiseProduct(w.transpose());
    for (int b = 0; b <= a; ++b) {
      const double vab = cw.dot(chi_.row(b));
      h(a, b) += vab;
      if (b != a) h(b, a) += vab;
    }
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(h, s_);
  if (es.info() != Eigen::Success)
    throw NumericalError(fmt::format(
        "Slater basis (l = {}): the generalized eigenproblem failed (overlap matrix not positive "
        "definite: exponents too close or too many powers)",
        l_));
  std::vector<SlaterState> out(count);
  for (int k = 0; k < count; ++k) {
    SlaterState& st = out[k];
    st.energy = es.eigenvalues()[k];
    Eigen::VectorXd c = es.eigenvectors().col(k);
    c /= std::sqrt(c.dot(s_ * c));  // c^T S c = 1 (the solver's normalisation, made exact)
    const Eigen::VectorXd R = chi_.transpose() * c;
    // sign convention of the Slater-Koster tables: the outermost lobe (the tail) is positive
    const double peak = R.cwiseAbs().maxCoeff();
    double sign = 1.0;
    for (int i = np - 1; i >= 0; --i)
      if (std::abs(R[i]) * g.r[i] > 1e-3 * peak) {
        sign = R[i] > 0.0 ? 1.0 : -1.0;
        break;
      }
    c *= sign;
    st.u.resize(np);
    for (int i = 0; i < np; ++i) st.u[i] = sign * R[i] * g.r[i];
    for (int a = 0; a < n; ++a) st.terms.push_back({c[a], power_[a], alpha_[a]});
  }
  return out;
}

}  // namespace mesochain::skgen
