// parallel::ExactSum: sums that do not depend on the order or grouping of their terms (what
// makes a k sum split over ranks and threads the same bits as the serial loop), checked against
// sums known exactly; and the balanced assignment of k-points to ranks.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "parallel/exact_sum.hpp"
#include "parallel/work_split.hpp"

using mesochain::parallel::ExactSum;
using mesochain::parallel::balancedOwners;

TEST(ExactSum, IndependentOfOrderAndGrouping) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> x(5000);
  for (double& v : x) v = u(rng) * std::pow(10.0, static_cast<int>(u(rng) * 6));
  ExactSum forward(1);
  for (double v : x) forward.add(0, &v, 1);
  // Shuffled, and split into 7 partial sums combined afterwards.
  std::shuffle(x.begin(), x.end(), rng);
  std::vector<ExactSum> parts(7, ExactSum(1));
  for (std::size_t i = 0; i < x.size(); ++i) parts[i % 7].add(0, &x[i], 1);
  ExactSum grouped(1);
  for (const ExactSum& p : parts) grouped.add(p);
  EXPECT_EQ(forward.value(0), grouped.value(0));  // the same bits
  // The naive double sums of the two orders differ (so the test could fail).
  double a = 0, b = 0;
  for (double v : x) a += v;
  std::reverse(x.begin(), x.end());
  for (double v : x) b += v;
  EXPECT_NE(a, b);
  EXPECT_NEAR(forward.value(0), a, 1e-9 * std::abs(a) + 1e-9);
}

TEST(ExactSum, CancellationIsExact) {
  // 1e8 + 1e-8 - 1e8 = 1e-8 exactly in the accumulator (a double sum gives 0 or noise);
  // double(0.1) added ten times is 1 + 5.55e-17 exactly, which rounds to 1.0 (the naive double
  // sum gives 0.9999999999999999).
  const double terms[] = {1e8, 1e-8, -1e8};
  ExactSum s(2);
  for (double t : terms) s.add(0, &t, 1);
  EXPECT_EQ(s.value(0), 1e-8);
  for (int i = 0; i < 10; ++i) {
    const double t = 0.1;
    s.add(1, &t, 1);
  }
  EXPECT_EQ(s.value(1), 1.0);
  double naive = 0;
  for (int i = 0; i < 10; ++i) naive += 0.1;
  EXPECT_NE(naive, 1.0);
  const double negative[] = {-3.25, 1.0, -0.5};
  ExactSum n(3);
  n.add(0, negative, 3);
  EXPECT_EQ(n.value(0), -3.25);
  EXPECT_EQ(n.value(1), 1.0);
  EXPECT_EQ(n.value(2), -0.5);
}

TEST(ExactSum, RefusesTermsOutOfRange) {
  ExactSum s(1);
  const double big = 1e9, inf = INFINITY, nan = NAN;
  EXPECT_THROW(s.add(0, &big, 1), mesochain::NumericalError);
  EXPECT_THROW(s.add(0, &inf, 1), mesochain::NumericalError);
  EXPECT_THROW(s.add(0, &nan, 1), mesochain::NumericalError);
}

TEST(WorkSplit, BalancesCostAndCoversEveryItem) {
  // Two real points (cost 1) and nine complex ones (cost 4) over 2 ranks: loads 18 and 20.
  std::vector<double> cost{1, 4, 4, 4, 4, 4, 4, 4, 4, 4, 1};
  const std::vector<int> owner = balancedOwners(cost, 2);
  double load[2] = {0, 0};
  for (std::size_t i = 0; i < cost.size(); ++i) {
    ASSERT_GE(owner[i], 0);
    ASSERT_LT(owner[i], 2);
    load[owner[i]] += cost[i];
  }
  EXPECT_EQ(std::max(load[0], load[1]), 20.0);
  // More ranks than items: every item has exactly one owner, some ranks none.
  const std::vector<int> few = balancedOwners({4, 4}, 3);
  EXPECT_NE(few[0], few[1]);
  // One rank owns everything.
  for (int r : balancedOwners(cost, 1)) EXPECT_EQ(r, 0);
}
