#include "parallel/exact_sum.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace mesochain::parallel {

namespace {
constexpr int kLimbBits = 40;
constexpr double kMax = 536870912.0;  // 2^29
}  // namespace

void ExactSum::add(std::size_t offset, const double* x, std::size_t count) {
  // Scaling by a power of two is exact in this range, and so is y - (integer part of y); the
  // integer parts are taken by truncation toward zero (one instruction each, no libm call). The
  // only rounding is the truncation of the last limb at 2^-90, a function of the term alone.
  constexpr double kTop = 1024.0;              // 2^10
  constexpr double kLimb = 1099511627776.0;    // 2^40
  std::int64_t* l = limbs_.data() + 3 * offset;
  for (std::size_t i = 0; i < count; ++i, l += 3) {
    const double v = x[i];
    if (v == 0.0) continue;
    if (!(std::abs(v) < kMax))
      throw NumericalError("exact sum: a term " + std::to_string(v) +
                           " that is not finite or not below 2^29 in magnitude");
    const double y2 = v * kTop;  // integer part: l2, |l2| < 2^39
    const auto t2 = static_cast<std::int64_t>(y2);
    const double y1 = (y2 - static_cast<double>(t2)) * kLimb;
    const auto t1 = static_cast<std::int64_t>(y1);
    const double y0 = (y1 - static_cast<double>(t1)) * kLimb;
    l[0] += static_cast<std::int64_t>(y0);
    l[1] += t1;
    l[2] += t2;
  }
}

void ExactSum::add(const ExactSum& other) {
  for (std::size_t i = 0; i < limbs_.size(); ++i) limbs_[i] += other.limbs_[i];
}

double ExactSum::value(std::size_t e) const {
  std::int64_t l0 = limbs_[3 * e], l1 = limbs_[3 * e + 1], l2 = limbs_[3 * e + 2];
  // Carries (arithmetic shift: floor division by 2^40), so that 0 <= l0, l1 < 2^40.
  std::int64_t c = l0 >> kLimbBits;
  l0 -= c * (std::int64_t{1} << kLimbBits);
  l1 += c;
  c = l1 >> kLimbBits;
  l1 -= c * (std::int64_t{1} << kLimbBits);
  l2 += c;
  return std::ldexp(static_cast<double>(l2), -10) +
         (std::ldexp(static_cast<double>(l1), -50) + std::ldexp(static_cast<double>(l0), -90));
}

void ExactSum::values(double* out) const {
  for (std::size_t e = 0; e < size(); ++e) out[e] = value(e);
}

}  // namespace mesochain::parallel
