#include "common/plot/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace mesochain::plot {

double niceStep(double raw) {
  if (!(raw > 0) || !std::isfinite(raw)) throw std::invalid_argument("niceStep: raw step must be positive and finite");
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw * (1 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

std::string formatTick(double value, double step) {
  if (std::abs(value) < 1e-9 * step) return "0";
  // Plain decimals for magnitudes people read at a glance (40, 2000, 0.005); the exponent form
  // only outside [1e-3, 1e5) where plain digits get long.
  if (std::abs(value) >= 1e-3 && std::abs(value) < 1e5 && step >= 1e-4) {
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    std::string plain = fmt::format("{:.{}f}", value, decimals);
    if (plain.find('.') != std::string::npos) {  // 1.0 -> 1, 2.50 -> 2.5
      plain.erase(plain.find_last_not_of('0') + 1);
      if (plain.back() == '.') plain.pop_back();
    }
    return plain;
  }
  const int digits =
      static_cast<int>(std::floor(std::log10(std::abs(value))) - std::floor(std::log10(step) + 1e-9)) + 1;
  std::string s = fmt::format("{:.{}g}", value, std::clamp(digits, 1, 15));
  // 1.5e-05 -> 1.5e-5, 2e+06 -> 2e6
  const auto e = s.find('e');
  if (e != std::string::npos) {
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    s = mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  return s;
}

AxisTicks linearTicks(double dataMin, double dataMax, int target) {
  if (!std::isfinite(dataMin) || !std::isfinite(dataMax) || dataMin > dataMax)
    throw std::invalid_argument("linearTicks: need finite dataMin <= dataMax");
  if (dataMax == dataMin) {
    const double pad = dataMin == 0 ? 1.0 : 0.1 * std::abs(dataMin);
    dataMin -= pad;
    dataMax += pad;
  }
  const double step = niceStep((dataMax - dataMin) / std::max(1, target));
  const long first = static_cast<long>(std::floor(dataMin / step + 1e-9));
  const long last = static_cast<long>(std::ceil(dataMax / step - 1e-9));
  AxisTicks t;
  t.lo = first * step;
  t.hi = last * step;
  for (long k = first; k <= last; ++k) {
    t.major.push_back(k * step);
    t.labels.push_back(formatTick(k * step, step));
  }
  return t;
}

AxisTicks logTicks(double dataMin, double dataMax, int target) {
  if (!(dataMin > 0) || !(dataMax >= dataMin) || !std::isfinite(dataMax))
    throw std::invalid_argument("logTicks: need 0 < dataMin <= dataMax, finite");
  // The data range plus 5% of its span in decades (at least 0.05 decade) on each side...
  const double a = std::log10(dataMin), b = std::log10(dataMax);
  const double pad = std::max(0.05, 0.05 * (b - a));
  double lo = a - pad, hi = b + pad;
  // ...unless that would show fewer than two labelled decades: then whole decades.
  if (std::floor(hi) - std::ceil(lo) < 1) {
    lo = std::floor(a + 1e-12);
    hi = std::max(lo + 1, std::ceil(b - 1e-12));
  }
  const int first = static_cast<int>(std::ceil(lo - 1e-12)), last = static_cast<int>(std::floor(hi + 1e-12));
  const int decades = last - first;
  const int every = decades <= std::max(1, target)
                        ? 1
                        : static_cast<int>(niceStep(static_cast<double>(decades) / std::max(1, target)));
  AxisTicks t;
  t.lo = std::pow(10.0, lo);
  t.hi = std::pow(10.0, hi);
  for (int k = first - 1; k <= last; ++k) {
    const double decade = std::pow(10.0, k);
    if (k >= first && ((k % every) + every) % every == 0) {
      t.major.push_back(decade);
      t.labels.push_back(fmt::format("10^{{{}}}", k));
    } else if (k >= first) {
      t.minor.push_back(decade);
    }
    if (every == 1)
      for (int m = 2; m <= 9; ++m)
        if (m * decade >= t.lo && m * decade <= t.hi) t.minor.push_back(m * decade);
  }
  return t;
}

}  // namespace mesochain::plot
