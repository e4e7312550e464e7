// portable_math.hpp: sine, cosine and logarithm from IEEE-754 basic operations, for the film
// generators (the same film from a seed on every platform).
#include "mdem/contacts/portable_math.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

namespace mesochain::mdem {
namespace {

// |a - b| in units in the last place of b.
double ulps(double a, double b) {
  const double u = std::nextafter(std::abs(b), INFINITY) - std::abs(b);
  return std::abs(a - b) / u;
}

// Against libm (itself within 1 ulp of the exact value): measured against 113-bit references
// when written, the functions are within 2.4 ulp (sin, cos) and 2.0 ulp (log) over 3e6 samples;
// libm's own error adds at most 1.
TEST(MdemPortableMath, AgreesWithLibmWithinAFewUlps) {
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> small(-7.0, 7.0), large(-kPortableTrigLimit, kPortableTrigLimit);
  double worstSin = 0.0, worstCos = 0.0, worstLog = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = i % 4 == 0 ? large(g) : small(g);
    worstSin = std::max(worstSin, ulps(portableSin(x), std::sin(x)));
    worstCos = std::max(worstCos, ulps(portableCos(x), std::cos(x)));
    // Logarithms over the whole positive range: random bit patterns (subnormals included), and
    // values in (0, 1] as Box-Muller takes them.
    double y = std::bit_cast<double>(g() & 0x7fefffffffffffffULL);
    if (i % 2) y = 1.0 - std::generate_canonical<double, 53>(g);
    if (y > 0.0) worstLog = std::max(worstLog, ulps(portableLog(y), std::log(y)));
  }
  EXPECT_LT(worstSin, 3.5);
  EXPECT_LT(worstCos, 3.5);
  EXPECT_LT(worstLog, 3.0);
  // Near the zeros of sin and cos the absolute error is what counts: within 1e-16 of the
  // reduction's accuracy at pi and pi/2 (the ulp of the tiny result is not the measure there).
  EXPECT_NEAR(portableSin(3.141592653589793), std::sin(3.141592653589793), 1e-31);
  EXPECT_NEAR(portableCos(1.5707963267948966), std::cos(1.5707963267948966), 1e-31);
}

TEST(MdemPortableMath, ExactValuesAndSymmetries) {
  EXPECT_EQ(portableSin(0.0), 0.0);
  EXPECT_EQ(portableCos(0.0), 1.0);
  EXPECT_EQ(portableLog(1.0), 0.0);
  EXPECT_EQ(portableLog(0.0), -INFINITY);
  EXPECT_TRUE(std::isnan(portableLog(-1.0)));
  // sin is odd and cos even bit for bit (every step of the reduction and the series is), and
  // log of a power of two is n ln 2 within an ulp.
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> x(-100.0, 100.0);
  for (int i = 0; i < 10000; ++i) {
    const double v = x(g);
    EXPECT_EQ(portableSin(-v), -portableSin(v)) << v;
    EXPECT_EQ(portableCos(-v), portableCos(v)) << v;
    const double s = portableSin(v), c = portableCos(v);
    EXPECT_NEAR(s * s + c * c, 1.0, 8e-16) << v;
  }
  for (int n = -1074; n <= 1023; n += 7)
    EXPECT_LE(ulps(portableLog(std::ldexp(1.0, n)), n * 0.69314718055994530942), 1.0) << n;
  EXPECT_THROW(portableSin(1e6), std::domain_error);
  EXPECT_THROW(portableCos(NAN), std::domain_error);
}

// The point of these functions: the same bits on every platform. These are the bits this
// implementation gives (IEEE-754 double, round to nearest, no FMA contraction); a platform or
// compiler setting that changes them (an -ffp-contract=fast build, x87 extended precision) would
// also change every generated film, which CliDem.QuarterFilmRegeneratesTheCommittedBenchFilm
// checks on a whole film.
TEST(MdemPortableMath, SameBitsAsWritten) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(portableSin(1.0)), std::bit_cast<std::uint64_t>(0.8414709848078965));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(portableCos(1.0)), std::bit_cast<std::uint64_t>(0.54030230586813977));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(portableLog(2.0)), std::bit_cast<std::uint64_t>(0.69314718055994529));
}

}  // namespace
}  // namespace mesochain::mdem
