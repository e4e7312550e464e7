// Lennard-Jones dispersion kernel (Zhechkov et al., JCTC 1, 841 (2005); DFTB+ dispuff.F90).
#include <cmath>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/dispersion_lj.hpp"
#include "skf_test_util.hpp"

using namespace mesochain;
using namespace mesochain::dftb;
using skftest::at;
using skftest::Vd;

TEST(LennardJones, CarbonDefaultsInAtomicUnits) {
  const UffLennardJones lj = UffLennardJones::carbonDefaults();
  EXPECT_NEAR(lj.epsilon(), 0.069 / 627.5094740631, 1e-15);
  EXPECT_NEAR(lj.r0(), 3.80 / 0.529177210903, 1e-12);
  EXPECT_EQ(lj.cutoff(), UffLennardJones::kDefaultCutoffBohr);
}

TEST(LennardJones, MinimumAtR0WithDepthEpsilon) {
  const UffLennardJones lj(1.3e-4, 7.2, 30.0);
  const Vd m = at(lj, 7.2);
  EXPECT_NEAR(m.v, -1.3e-4, 1e-18);
  EXPECT_NEAR(m.d, 0.0, 1e-18);
  EXPECT_GT(at(lj, 7.0).v, m.v);
  EXPECT_GT(at(lj, 7.4).v, m.v);
}

TEST(LennardJones, ShortRangeConstantsOfThePaper) {
  const double eps = 2.0e-4, r0 = 6.5;
  const UffLennardJones lj(eps, r0, 30.0);
  EXPECT_NEAR(lj.switchRadius(), std::pow(2.0, -1.0 / 6.0) * r0, 1e-14);
  EXPECT_NEAR(lj.u0(), 396.0 / 25.0 * eps, 1e-15);
  EXPECT_NEAR(lj.u5(), std::pow(2.0, 5.0 / 6.0) * 672.0 / 25.0 * eps / std::pow(r0, 5), 1e-18);
  EXPECT_NEAR(lj.u10(), -std::pow(2.0, 2.0 / 3.0) * 552.0 / 25.0 * eps / std::pow(r0, 10), 1e-24);
}

TEST(LennardJones, ContinuousAtSwitchUpToSecondDerivative) {
  const UffLennardJones lj = UffLennardJones::carbonDefaults();
  const double rs = lj.switchRadius();
  const double eps = lj.epsilon();
  const double tiny = 1e-9;
  const Vd lo = at(lj, rs - tiny), hi = at(lj, rs + tiny);
  EXPECT_NEAR(lo.v, hi.v, 1e-8 * eps);
  EXPECT_NEAR(lo.d, hi.d, 1e-7 * eps);
  EXPECT_NEAR(at(lj, rs).v, 0.0, 1e-14 * eps);  // r_s is the zero of the Lennard-Jones term
  // Second derivative from one-sided differences of dV/dr on each side.
  const double h = 1e-5;
  const double d2lo = (at(lj, rs - tiny).d - at(lj, rs - h).d) / (h - tiny);
  const double d2hi = (at(lj, rs + h).d - at(lj, rs + tiny).d) / (h - tiny);
  const double d2 = 456.0 * eps / (rs * rs);
  EXPECT_NEAR(d2lo, d2, 1e-3 * d2);
  EXPECT_NEAR(d2hi, d2, 1e-3 * d2);
}

TEST(LennardJones, DerivativeMatchesFiniteDifferences) {
  const UffLennardJones lj = UffLennardJones::carbonDefaults();
  const double h = 1e-6;
  for (double r : {0.5, 2.0, 5.0, lj.switchRadius() - 0.01, lj.switchRadius() + 0.01, lj.r0(),
                   9.0, 15.0, 24.9}) {
    const double fd = (at(lj, r + h).v - at(lj, r - h).v) / (2 * h);
    EXPECT_NEAR(at(lj, r).d, fd, 1e-7 * std::abs(fd) + 1e-8 * lj.epsilon()) << r;  // + FD round-off
  }
}

TEST(LennardJones, ZeroBeyondCutoffAndRejectsBadInput) {
  const UffLennardJones lj(1e-4, 7.0, 20.0);
  EXPECT_LT(at(lj, 19.99).v, 0.0);
  EXPECT_EQ(at(lj, 20.0).v, 0.0);
  EXPECT_EQ(at(lj, 25.0).d, 0.0);
  EXPECT_THROW(UffLennardJones(1e-4, -1.0, 20.0), InputError);
  EXPECT_THROW(UffLennardJones(std::nan(""), 7.0, 20.0), InputError);
}
