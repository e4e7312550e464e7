#pragma once
// Sine, cosine and natural logarithm built from the basic IEEE-754 double operations only (+, -,
// *, /, exact scaling by powers of two, rounding to an integer), for the film generators
// (deposition.cpp, network_generator.cpp, drape_geometry.cpp): each operation is correctly
// rounded by the standard, the build contracts nothing into FMAs (-std=c++20, no -ffast-math), so
// these give the same bits on every platform, where libm's sin, cos and log differ between
// libraries (none is correctly rounded everywhere: glibc 2.36 here misrounds about 1 sin or cos in
// 700 and 1 log in 2400, against 113-bit references). With portable_random.hpp's uniforms a seed
// then makes the same film everywhere (docs/scene-file.md, `seed`).
//
// Accuracy, measured against 113-bit references over 3e6 samples when written: within 2.4 ulp for
// sin and cos on |x| <= kPortableTrigLimit, within 2.0 ulp for log on the positive doubles (a
// fifth of the results are not the nearest double; determinism, not the last bit, is the point;
// tests/mdem/test_portable_math.cpp checks against libm).
//
// Methods (textbook; e.g. J.-M. Muller, "Elementary Functions", 3rd ed., 2016, chapters 11, 13):
//  * sin, cos: Cody-Waite reduction x = k pi/2 + r with pi/2 split in three parts (the first two
//    of 33 bits, so k p1 and k p2 are exact for |k| < 2^20), |r| <= pi/4 (+ rounding), then the
//    Taylor series of sin r to r^19 and of cos r to r^18 (truncation below 1e-19 at pi/4) by
//    Horner's rule in r^2, the quadrant from k mod 4.
//  * log: x = 2^e m with m in [sqrt(1/2), sqrt(2)) (frexp: exact), log m = 2 atanh(s) with
//    s = (m - 1)/(m + 1), |s| <= 0.1716, the series 2 s (1 + s^2/3 + ... + s^22/23) (truncation
//    below 1e-18), plus e ln 2 with ln 2 split in a 42-bit part (e ln2_hi exact) and the rest.
// The coefficients are the doubles nearest to 1/k! and 1/(2k+1); the splits of pi/2 and ln 2 are
// their leading bits, all computed exactly (rational arithmetic) for this file.
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mesochain::mdem {

// Largest |x| the reduction of portableSin and portableCos keeps within 1 ulp (k < 2^19).
inline constexpr double kPortableTrigLimit = 8.0e5;

namespace portable_math_detail {
inline constexpr double kTwoOverPi = 0.6366197723675814;
inline constexpr double kPiOver2Part1 = 1.5707963267341256;     // 33 bits
inline constexpr double kPiOver2Part2 = 6.077100506303966e-11;  // the next 33 bits
inline constexpr double kPiOver2Part3 = 2.0222662487959506e-21;  // the rest, rounded
// sin r / r - 1 = z (s3 + z (s5 + ...)), cos r = 1 + z (c2 + z (c4 + ...)), z = r^2: (-1)^k / k!.
inline constexpr double kSin[9] = {-0.16666666666666666,    0.008333333333333333,   -0.0001984126984126984,
                                   2.7557319223985893e-06, -2.505210838544172e-08, 1.6059043836821613e-10,
                                   -7.647163731819816e-13, 2.8114572543455206e-15, -8.22063524662433e-18};
inline constexpr double kCos[9] = {-0.5,                    0.041666666666666664,   -0.001388888888888889,
                                   2.48015873015873e-05,   -2.755731922398589e-07, 2.08767569878681e-09,
                                   -1.1470745597729725e-11, 4.779477332387385e-14, -1.5619206968586225e-16};
inline constexpr double kAtanh[11] = {0.3333333333333333,  0.2,                 0.14285714285714285, 0.1111111111111111,
                                      0.09090909090909091, 0.07692307692307693, 0.06666666666666667, 0.058823529411764705,
                                      0.05263157894736842, 0.047619047619047616, 0.043478260869565216};  // 1/(2k+1)
inline constexpr double kLn2Part1 = 0.6931471805598903;     // 42 bits: e kLn2Part1 is exact
inline constexpr double kLn2Part2 = 5.497923018708371e-14;  // the rest, rounded
inline constexpr double kSqrtHalf = 0.7071067811865476;

inline double series(const double (&c)[9], double z) {
  double p = c[8];
  for (int k = 7; k >= 0; --k) p = c[k] + z * p;
  return p;
}
inline double sinKernel(double r) {
  const double z = r * r;
  return r + r * (z * series(kSin, z));
}
inline double cosKernel(double r) {
  const double z = r * r;
  return 1.0 + z * series(kCos, z);
}
// sin(k pi/2 + r) for k mod 4 = q: sin r, cos r, -sin r, -cos r (cos x is this at q + 1).
inline double sinOfQuadrant(int q, double r) {
  switch (q & 3) {
    case 0: return sinKernel(r);
    case 1: return cosKernel(r);
    case 2: return -sinKernel(r);
    default: return -cosKernel(r);
  }
}
// r = x - k pi/2 and k mod 4.
inline double reduce(double x, int* quadrant) {
  if (!(std::abs(x) <= kPortableTrigLimit))
    throw std::domain_error("portableSin/portableCos: |x| beyond kPortableTrigLimit or not finite");
  const double k = std::nearbyint(x * kTwoOverPi);
  *quadrant = static_cast<int>(static_cast<long long>(k) & 3);
  return ((x - k * kPiOver2Part1) - k * kPiOver2Part2) - k * kPiOver2Part3;
}
}  // namespace portable_math_detail

inline double portableSin(double x) {
  int q;
  const double r = portable_math_detail::reduce(x, &q);
  return portable_math_detail::sinOfQuadrant(q, r);
}

inline double portableCos(double x) {
  int q;
  const double r = portable_math_detail::reduce(x, &q);
  return portable_math_detail::sinOfQuadrant(q + 1, r);  // cos x = sin(x + pi/2)
}

// Natural logarithm of x > 0 (finite); -inf at 0, NaN below (as std::log).
inline double portableLog(double x) {
  using namespace portable_math_detail;
  if (std::isnan(x) || x < 0.0) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return -std::numeric_limits<double>::infinity();
  if (std::isinf(x)) return x;
  int e;
  double m = std::frexp(x, &e);  // x = m 2^e, m in [1/2, 1)
  if (m < kSqrtHalf) m *= 2.0, e -= 1;
  const double s = (m - 1.0) / (m + 1.0), z = s * s;
  double p = kAtanh[10];
  for (int k = 9; k >= 0; --k) p = kAtanh[k] + z * p;
  const double logM = 2.0 * s + 2.0 * s * (z * p);
  return e * kLn2Part1 + (logM + e * kLn2Part2);
}

}  // namespace mesochain::mdem
