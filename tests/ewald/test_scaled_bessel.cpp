// Scaled modified Bessel functions: against std::cyl_bessel_i where it does not overflow, the
// large-argument asymptotic series where it does, and the recurrence itself at large orders.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ewald/scaled_bessel.hpp"

using mesochain::ewald::scaledBesselISequence;

TEST(ScaledBessel, MatchesStandardLibraryForModerateArguments) {
  std::vector<double> ie;
  for (double x : {1e-8, 0.3, 2.0, 17.5, 120.0}) {
    scaledBesselISequence(x, 60, ie);
    for (int l = 0; l <= 60; ++l) {
      const double ref = std::cyl_bessel_i(static_cast<double>(l), x) * std::exp(-x);
      if (ref < 1e-290) continue;
      EXPECT_NEAR(ie[l], ref, 1e-13 * ref + 1e-300) << "x " << x << " l " << l;
    }
  }
}

TEST(ScaledBessel, LargeArgumentsWhereUnscaledValuesOverflow) {
  // Hankel's expansion e^{-x} I_l(x) ~ (2 pi x)^{-1/2} (1 - (4l^2-1)/(8x) + (4l^2-1)(4l^2-9)/(2!(8x)^2) ...)
  std::vector<double> ie;
  const double x = 5000.0;
  scaledBesselISequence(x, 30, ie);
  for (int l : {0, 1, 7, 30}) {
    const double mu = 4.0 * l * l;
    double term = 1, sum = 1;
    for (int k = 1; k < 12; ++k) {
      term *= -(mu - (2 * k - 1) * (2 * k - 1)) / (k * 8 * x);
      sum += term;
    }
    EXPECT_NEAR(ie[l], sum / std::sqrt(2 * M_PI * x), 1e-14 / std::sqrt(x)) << l;
  }
  EXPECT_TRUE(std::isfinite(ie[30]));
}

TEST(ScaledBessel, RecurrenceHoldsAtLargeOrders) {
  std::vector<double> ie;
  const double x = 300.0;
  scaledBesselISequence(x, 400, ie);
  for (int l = 1; l < 399; l += 37)
    EXPECT_NEAR(ie[l - 1] - ie[l + 1], 2.0 * l / x * ie[l], 1e-12 * ie[l - 1] + 1e-300) << l;
  scaledBesselISequence(0.0, 5, ie);
  EXPECT_EQ(ie[0], 1.0);
  EXPECT_EQ(ie[3], 0.0);
}
