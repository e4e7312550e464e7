#include "ewald/exponential_integral.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace mesochain::ewald {

namespace {

constexpr double kEulerGamma = 0.57721566490153286061;

// Power series of E_nu(x) for 0 < x <= 1, nu >= 1 (Abramowitz & Stegun 5.1.12 for integer
// orders; for non-integer orders E_nu(x) = Gamma(1 - nu) x^(nu-1) - sum_k (-x)^k / ((k+1-nu) k!)).
double seriesAt(double nu, double x) {
  const double n = std::round(nu);
  const bool integer = std::abs(nu - n) < 1e-12;
  double sum = 0, term = 1;  // term = (-x)^k / k!
  for (int k = 0; k < 60; ++k) {
    if (k > 0) term *= -x / k;
    if (integer && k == static_cast<int>(n) - 1) continue;
    const double add = term / (k + 1 - nu);
    sum -= add;
    if (k > 2 && std::abs(add) < 1e-18 * std::abs(sum)) break;
  }
  if (integer) {
    double psi = -kEulerGamma;  // digamma(n)
    double power = 1;           // (-x)^(n-1) / (n-1)!
    for (int m = 1; m < static_cast<int>(n); ++m) psi += 1.0 / m, power *= -x / m;
    return sum + power * (psi - std::log(x));
  }
  return sum + std::tgamma(1 - nu) * std::pow(x, nu - 1);
}

// Continued fraction E_nu(x) = e^{-x} / (x + nu - 1 nu / (x + nu + 2 - 2 (nu+1) / (x + nu + 4 - ...)))
// (A&S 5.1.22, even form) evaluated by the modified Lentz method; fast for x > 1.
double continuedFractionAt(double nu, double x) {
  constexpr double tiny = 1e-300;
  double b = x + nu;
  double c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double a = -static_cast<double>(i) * (nu - 1 + i);
    b += 2;
    d = a * d + b;
    if (std::abs(d) < tiny) d = tiny;
    d = 1 / d;
    c = b + a / c;
    if (std::abs(c) < tiny) c = tiny;
    const double delta = c * d;
    h *= delta;
    if (std::abs(delta - 1) < 1e-16) return h * std::exp(-x);
  }
  throw NumericalError("exponential integral: continued fraction did not converge");
}

}  // namespace

void exponentialIntegralSequence(double nu0, double x, int count, std::vector<double>& out) {
  out.resize(static_cast<size_t>(std::max(count, 0)));
  if (count <= 0) return;
  if (x == 0) {
    for (int i = 0; i < count; ++i) {
      const double nu = nu0 + i;
      out[i] = nu > 1 ? 1 / (nu - 1) : std::numeric_limits<double>::infinity();
    }
    return;
  }
  const double ex = std::exp(-x);
  int start = 0;
  if (x <= 1) {
    // Lowest order >= 1 from the series; E_nu for nu < 1 from the downward recurrence.
    start = std::min(count - 1, std::max(0, static_cast<int>(std::ceil(1 - nu0 - 1e-12))));
    out[start] = nu0 + start >= 1 ? seriesAt(nu0 + start, x) : continuedFractionAt(nu0 + start, x);
  } else {
    start = std::clamp(static_cast<int>(std::lround(x - nu0)), 0, count - 1);
    out[start] = continuedFractionAt(nu0 + start, x);
  }
  for (int i = start - 1; i >= 0; --i) out[i] = (ex - (nu0 + i) * out[i + 1]) / x;
  for (int i = start; i + 1 < count; ++i) out[i + 1] = (ex - x * out[i]) / (nu0 + i);
}

}  // namespace mesochain::ewald
