// Tick placement of plot axes: the 1-2-5 rule on linear axes, whole decades on log axes.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "common/plot/ticks.hpp"

using namespace mesochain::plot;

TEST(PlotTicks, NiceStepIsTheSmallestOneTwoFiveNumberNotBelowTheRawStep) {
  EXPECT_DOUBLE_EQ(niceStep(1.0), 1.0);
  EXPECT_DOUBLE_EQ(niceStep(1.3), 2.0);
  EXPECT_DOUBLE_EQ(niceStep(3.0), 5.0);
  EXPECT_DOUBLE_EQ(niceStep(7.0), 10.0);
  EXPECT_DOUBLE_EQ(niceStep(0.0021), 0.005);
  EXPECT_DOUBLE_EQ(niceStep(4.2e7), 5e7);
  // Property over many scales: result >= raw, mantissa in {1, 2, 5}, and the next smaller
  // 1-2-5 number would be below raw.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-12, 12);
  for (int i = 0; i < 2000; ++i) {
    const double raw = std::pow(10.0, exponent(rng));
    const double s = niceStep(raw);
    ASSERT_GE(s, raw * (1 - 1e-12));
    const double mantissa = s / std::pow(10.0, std::floor(std::log10(s) + 1e-12));
    ASSERT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9) << s;
    const double smaller = std::abs(mantissa - 1) < 1e-9 ? 0.5 * s : (std::abs(mantissa - 2) < 1e-9 ? 0.5 * s : 0.4 * s);
    ASSERT_LT(smaller, raw) << raw;
  }
}

TEST(PlotTicks, LinearAxisWidensToWholeSteps) {
  const AxisTicks t = linearTicks(0.3, 9.7, 6);
  EXPECT_DOUBLE_EQ(t.lo, 0.0);
  EXPECT_DOUBLE_EQ(t.hi, 10.0);
  ASSERT_EQ(t.major.size(), 6u);
  const std::vector<std::string> labels{"0", "2", "4", "6", "8", "10"};
  EXPECT_EQ(t.labels, labels);
  for (std::size_t i = 0; i < t.major.size(); ++i) EXPECT_NEAR(t.major[i], 2.0 * i, 1e-12);
}

TEST(PlotTicks, LinearLabelsAroundZeroHaveNoRoundingNoise) {
  const AxisTicks t = linearTicks(-0.013, 0.047, 6);
  EXPECT_NEAR(t.lo, -0.02, 1e-15);
  EXPECT_NEAR(t.hi, 0.05, 1e-15);
  const std::vector<std::string> labels{"-0.02", "-0.01", "0", "0.01", "0.02", "0.03", "0.04", "0.05"};
  EXPECT_EQ(t.labels, labels);
  EXPECT_EQ(formatTick(0.1 + 0.2, 0.1), "0.3");
  EXPECT_EQ(formatTick(-3.0000000000000004e-17, 0.1), "0");
}

TEST(PlotTicks, LargeAndSmallValuesUseShortExponents) {
  const AxisTicks t = linearTicks(0, 3e6, 6);
  const std::vector<std::string> labels{"0", "5e5", "1e6", "1.5e6", "2e6", "2.5e6", "3e6"};
  EXPECT_EQ(t.labels, labels);
  EXPECT_EQ(formatTick(2.5e-7, 5e-8), "2.5e-7");
  // Round magnitudes between 1e-3 and 1e5 are written out, not as 4e1 or 2e3.
  EXPECT_EQ(formatTick(40.0, 20.0), "40");
  EXPECT_EQ(formatTick(-2000.0, 1000.0), "-2000");
  EXPECT_EQ(formatTick(0.005, 0.005), "0.005");
  EXPECT_EQ(formatTick(2e6, 1e6), "2e6");
  EXPECT_EQ(formatTick(1.0, 0.5), "1");
  EXPECT_EQ(formatTick(2.5, 0.5), "2.5");
}

TEST(PlotTicks, ConstantDataGetsARangeAroundIt) {
  const AxisTicks t = linearTicks(5, 5, 5);
  EXPECT_LT(t.lo, 5.0);
  EXPECT_GT(t.hi, 5.0);
  const AxisTicks z = linearTicks(0, 0, 5);
  EXPECT_LE(z.lo, -1.0);
  EXPECT_GE(z.hi, 1.0);
}

TEST(PlotTicks, LogAxisCoversTheDataWithAMarginAndLabelsDecades) {
  const AxisTicks t = logTicks(3e-5, 0.2, 6);
  // 3.82 decades of data, 5% of that on each side.
  const double pad = 0.05 * std::log10(0.2 / 3e-5);
  EXPECT_NEAR(std::log10(t.lo), std::log10(3e-5) - pad, 1e-12);
  EXPECT_NEAR(std::log10(t.hi), std::log10(0.2) + pad, 1e-12);
  const std::vector<std::string> labels{"10^{-4}", "10^{-3}", "10^{-2}", "10^{-1}"};
  EXPECT_EQ(t.labels, labels);
  // Minor ticks: 2..9 x 10^k inside the range: 2e-5..9e-5, three full decades, 2e-1 and 3e-1.
  EXPECT_EQ(t.minor.size(), 8u + 3u * 8u + 2u);
  for (double m : t.minor) {
    EXPECT_GE(m, t.lo);
    EXPECT_LE(m, t.hi);
  }
}

TEST(PlotTicks, NarrowLogDataGetsWholeDecades) {
  const AxisTicks one = logTicks(2, 8, 6);  // inside one decade
  EXPECT_DOUBLE_EQ(one.lo, 1.0);
  EXPECT_DOUBLE_EQ(one.hi, 10.0);
  const std::vector<std::string> labels{"10^{0}", "10^{1}"};
  EXPECT_EQ(one.labels, labels);
  const AxisTicks same = logTicks(0.05, 0.05, 6);
  EXPECT_DOUBLE_EQ(same.lo, 0.01);
  EXPECT_DOUBLE_EQ(same.hi, 0.1);
}

TEST(PlotTicks, ManyDecadesAreLabelledInNiceSteps) {
  const AxisTicks t = logTicks(1e-20, 1.0, 6);
  // 20 decades for about 6 intervals: every 5th power of ten labelled, the others minor.
  const std::vector<std::string> labels{"10^{-20}", "10^{-15}", "10^{-10}", "10^{-5}", "10^{0}"};
  EXPECT_EQ(t.labels, labels);
  // The 5% margin is a whole decade here: 10^-21 .. 10^1, 23 powers of ten, 5 of them labelled.
  EXPECT_EQ(t.minor.size(), 18u);
  EXPECT_LT(t.lo, 1e-20);
  EXPECT_GT(t.hi, 1.0);
}
