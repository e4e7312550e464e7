// Interpolation of integral tables (DFTB+ "new" scheme: 8-point polynomial, 1 Bohr quintic tail).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "dftb/sk_grid.hpp"
#include "dftb/skf_file.hpp"
#include "skf_test_util.hpp"

using namespace mesochain::dftb;
using namespace skftest;

namespace {

struct Eval {
  std::vector<double> v, d;
};
Eval eval(const SkGrid& g, double r) {
  Eval e{std::vector<double>(g.columns()), std::vector<double>(g.columns())};
  g.evaluate(r, e.v.data(), e.d.data());
  return e;
}

SkGrid carbonHam() {
  const SkfTable t = readSkfFile(pbc("C-C.skf"), true);
  return SkGrid(t.gridSpacing, t.ham, t.path);
}

}  // namespace

TEST(SkGrid, CutoffIsLastRowPlusOneBohr) {
  const SkGrid g = carbonHam();
  EXPECT_EQ(g.rows(), 519);
  EXPECT_NEAR(g.cutoff(), 519 * 0.02 + 1.0, 1e-12);  // 11.38 Bohr
}

TEST(SkGrid, ReproducesTableAtGridPoints) {
  const SkfTable t = readSkfFile(pbc("C-C.skf"), true);
  const SkGrid g(t.gridSpacing, t.ham, t.path);
  double worst = 0.0;
  for (int i = 1; i <= g.rows(); ++i) {
    const Eval e = eval(g, i * t.gridSpacing);
    for (int c = 0; c < g.columns(); ++c) worst = std::max(worst, std::abs(e.v[c] - t.ham(i - 1, c)));
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(SkGrid, ExactForPolynomialsOfDegreeSeven) {
  // Any 8-point interpolant reproduces a degree-7 polynomial; the tail must then start with the
  // polynomial's own value and slopes.
  const int n = 40;
  const double h = 0.05;
  auto p = [](double r) { return 0.3 - 0.2 * r + 0.05 * std::pow(r, 3) - 0.001 * std::pow(r, 7); };
  auto dp = [](double r) { return -0.2 + 0.15 * r * r - 0.007 * std::pow(r, 6); };
  Eigen::MatrixXd tab(n, 1);
  for (int i = 0; i < n; ++i) tab(i, 0) = p((i + 1) * h);
  const SkGrid g(h, tab, "poly");
  for (double r : {0.01, 0.07, 0.333, 1.0, 1.51, 1.97, 2.0 - 1e-12}) {
    const Eval e = eval(g, r);
    EXPECT_NEAR(e.v[0], p(r), 1e-11 * (1 + std::abs(p(r)))) << r;
    EXPECT_NEAR(e.d[0], dp(r), 1e-9 * (1 + std::abs(dp(r)))) << r;
  }
  const Eval atEnd = eval(g, n * h);
  EXPECT_NEAR(atEnd.v[0], p(n * h), 1e-11 * std::abs(p(n * h)));
  EXPECT_NEAR(atEnd.d[0], dp(n * h), 1e-9 * std::abs(dp(n * h)));
}

TEST(SkGrid, StencilIsFourBelowAndFourAbove) {
  // Only row k is non-zero. r in [i h, (i+1) h) uses rows i-3 .. i+4 (clamped to the table), so
  // row k contributes exactly for k-4 <= i <= k+3.
  const int n = 60, k = 30;
  const double h = 0.1;
  Eigen::MatrixXd tab = Eigen::MatrixXd::Zero(n, 1);
  tab(k - 1, 0) = 1.0;
  const SkGrid g(h, tab, "spike");
  for (int i = 1; i < n; ++i) {
    const double r = (i + 0.5) * h;
    const bool uses = (i >= k - 4 && i <= k + 3);
    EXPECT_EQ(eval(g, r).v[0] != 0.0, uses) << "i = " << i;
  }
  // Near the origin the stencil is rows 1..8: a spike at row 8 matters below r = h.
  Eigen::MatrixXd tab2 = Eigen::MatrixXd::Zero(n, 1);
  tab2(7, 0) = 1.0;
  const SkGrid g2(h, tab2, "spike8");
  EXPECT_NE(eval(g2, 0.05).v[0], 0.0);
  tab2.setZero();
  tab2(8, 0) = 1.0;  // row 9 is outside rows 1..8
  EXPECT_EQ(eval(SkGrid(h, tab2, "spike9"), 0.05).v[0], 0.0);
}

TEST(SkGrid, DerivativeMatchesFiniteDifferences) {
  const SkGrid g = carbonHam();
  const double end = g.rows() * g.spacing();
  const double step = 1e-5;
  for (double r : {0.013, 1.5, 2.6613, 2.67, 5.0, end - 0.07, end - 0.013, end - 1e-4, end + 1e-4,
                   end + 0.3, end + 0.77, g.cutoff() - 0.01}) {
    const Eval e = eval(g, r), p = eval(g, r + step), m = eval(g, r - step);
    for (int c = 0; c < g.columns(); ++c) {
      const double fd = (p.v[c] - m.v[c]) / (2 * step);
      EXPECT_NEAR(e.d[c], fd, 1e-7 * (1 + std::abs(fd))) << "r = " << r << " column " << c;
    }
  }
}

TEST(SkGrid, ContinuousAtTableEndAndZeroBeyondCutoff) {
  const SkGrid g = carbonHam();
  const double end = g.rows() * g.spacing();
  const double eps = 1e-10;
  const Eval lo = eval(g, end - eps), hi = eval(g, end + eps);
  const Eval lo2 = eval(g, end - 1e-4), hi2 = eval(g, end + 1e-4);
  for (int c = 0; c < g.columns(); ++c) {
    EXPECT_NEAR(lo.v[c], hi.v[c], 1e-14) << c;
    EXPECT_NEAR(lo.d[c], hi.d[c], 1e-12) << c;
    // Second derivative: one-sided differences of d/dr on each side agree.
    const double d2lo = (lo.d[c] - lo2.d[c]) / (1e-4 - eps);
    const double d2hi = (hi2.d[c] - hi.d[c]) / (1e-4 - eps);
    EXPECT_NEAR(d2lo, d2hi, 1e-6) << c;
  }
  // pp_sigma of carbon is not small at the table end; the tail must carry it to zero.
  EXPECT_GT(std::abs(lo.v[kSkfPpSigma]), 1e-6);
  const Eval nearCut = eval(g, g.cutoff() - 1e-3);
  EXPECT_LT(std::abs(nearCut.v[kSkfPpSigma]), 1e-6 * std::abs(lo.v[kSkfPpSigma]));
  for (double r : {g.cutoff(), g.cutoff() + 1e-9, g.cutoff() + 3.0}) {
    const Eval e = eval(g, r);
    for (int c = 0; c < g.columns(); ++c) {
      EXPECT_EQ(e.v[c], 0.0);
      EXPECT_EQ(e.d[c], 0.0);
    }
  }
}

TEST(SkGrid, TooShortTableIsInputError) {
  const std::string msg =
      inputErrorOf([] { SkGrid(0.1, Eigen::MatrixXd::Ones(8, 2), "short.skf"); });
  EXPECT_NE(msg.find("short.skf"), std::string::npos) << msg;
}
