#include "ewald/small_t_series.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "ewald/exponential_integral.hpp"

namespace mesochain::ewald::detail {

SmallTSeries::SmallTSeries(Kernel kernel, double tc, double rhoI, double rhoJ)
    : kernel_(kernel), tc_(tc), rhoI_(rhoI), rhoJ_(rhoJ) {
  const double a = rhoI * rhoI + rhoJ * rhoJ, b = 2 * rhoI * rhoJ;
  const double s = tc * (a + b);
  if (!(tc > 0) || s > 1 + 1e-12)
    throw NumericalError("helical Ewald: small-t series used beyond t_c (a + b) = 1");
  // omega(t) dt/t = c t^beta dt/t, eq. (E11): Coulomb c = 1, beta = 0; 1/r^6 c = sqrt(pi)/2,
  // beta = 5/2.
  const bool coulomb = kernel == Kernel::Coulomb;
  beta_ = coulomb ? 0.0 : 2.5;
  prefactor_ = coulomb ? 1.0 : 0.5 * std::sqrt(units::kPi) * std::pow(tc, beta_);
  // |P_n| <= s^n / n!: keep powers until the first omitted one is below 1e-18 (relative to B_0).
  double bound = 1;
  while (terms_ < kMaxTerms) {
    bound *= s / terms_;
    if (bound < 1e-18) break;
    ++terms_;
  }
  double e = 1;
  for (int m = 0; m < terms_; ++m) {
    expSeries_[m] = e;
    expAbsSum_ += std::abs(e);
    e *= -a * tc / (m + 1);
  }
}

const std::array<double, SmallTSeries::kMaxTerms>& SmallTSeries::coefficients(int l) {
  l = std::abs(l);
  if (l >= terms_) return zeros_;
  if (have_[l]) return p_[l];
  // B_l = e^{-ta} I_l(tb), I_l(tb) = sum_j h^(2j+l) (t/t_c)^(2j+l) / (j! (j+l)!), h = b t_c / 2.
  auto& p = p_[l];
  p.fill(0.0);
  const double h = rhoI_ * rhoJ_ * tc_;
  double c = 1;  // h^l / l!
  for (int i = 1; i <= l; ++i) c *= h / i;
  for (int j = 0; 2 * j + l < terms_; ++j) {
    if (j > 0) c *= h * h / (j * (j + l));
    const int first = 2 * j + l;
    for (int n = first; n < terms_; ++n) p[n] += c * expSeries_[n - first];
  }
  have_[l] = true;
  return p;
}

double SmallTSeries::coefficientBound(int l) const {
  // sum_n |P_n^(l)| <= e^{a t_c} sum_j h^(2j+l) / (j! (j+l)!) <= e^{a t_c} h^l / l! e^{h^2 / (l+1)}
  // (the product of the two series, eq. (E18), with |e^{-ta}| terms summed in absolute value).
  l = std::abs(l);
  if (l >= terms_) return 0.0;
  const double h = rhoI_ * rhoJ_ * tc_;
  double c = 1;
  for (int i = 1; i <= l; ++i) c *= h / i;
  return expAbsSum_ * c * std::exp(h * h / (l + 1));
}

double SmallTSeries::magnitude(int l) const { return prefactor_ * coefficientBound(l); }

double SmallTSeries::derivativeMagnitude(int l) const {
  return prefactor_ * tc_ * std::max(rhoI_, rhoJ_) *
         (2 * coefficientBound(l) + coefficientBound(l - 1) + coefficientBound(l + 1));
}

SmallTIntegrals SmallTSeries::integrals(int l, double q, bool regularised, bool withDerivatives) {
  SmallTIntegrals out;
  l = std::abs(l);
  if (l > terms_) return out;
  const auto& p = coefficients(l);
  // E[i] = E_{beta + l + i}(x): E_{n+beta+1} = E[n-l+1] (value), E_{n+beta} = E[n-l] (d/dq);
  // the derivative series (a factor t) reach one power further, n = terms_.
  static thread_local std::vector<double> e;
  const double x = q * q / (4 * tc_);
  exponentialIntegralSequence(beta_ + l, x, terms_ - l + 2, e);
  for (int n = std::max(l, regularised ? 1 : 0); n < terms_; ++n) out.f += p[n] * e[n - l + 1];
  out.f *= prefactor_;
  if (!withDerivatives) return out;
  if (q != 0) {
    for (int n = l; n < terms_; ++n) out.fQ += p[n] * e[n - l];
    out.fQ *= -prefactor_ * q / (2 * tc_);
  }
  // Eq. (E17) term by term: d B_l / d rho_i = t [-2 rho_i B_l + rho_j (B_{l-1} + B_{l+1})],
  // (l / rho_i) B_l = t rho_j (B_{l-1} - B_{l+1}); a factor t shifts the powers by one.
  const auto& pl = coefficients(l);
  const auto& pm = coefficients(l - 1);
  const auto& pp = coefficients(l + 1);
  for (int n = std::max(l, 1); n <= terms_; ++n) {
    const double en = e[n - l + 1];
    const double sum = pm[n - 1] + pp[n - 1];
    out.fRhoI += (-2 * rhoI_ * pl[n - 1] + rhoJ_ * sum) * en;
    out.fRhoJ += (-2 * rhoJ_ * pl[n - 1] + rhoI_ * sum) * en;
    if (l > 0) {
      const double diff = pm[n - 1] - pp[n - 1];
      out.lOverRhoI += rhoJ_ * diff * en;
      out.lOverRhoJ += rhoI_ * diff * en;
    }
  }
  const double scale = prefactor_ * tc_;
  out.fRhoI *= scale;
  out.fRhoJ *= scale;
  out.lOverRhoI *= scale;
  out.lOverRhoJ *= scale;
  return out;
}

}  // namespace mesochain::ewald::detail
