// The energy-curve fitter: recovers known stiffnesses from synthetic curves (exact, anharmonic,
// noisy, shifted minimum, one-sided), finds the quadratic window, and refuses curves that have
// too few points or no quadratic regime with a message naming the source.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "beam/curve_fit.hpp"
#include "common/errors.hpp"

namespace mesochain::beam {
namespace {

// U = u0 + 1/2 k (x - x0)^2 + q (x - x0)^4 + noise, at x = step * j, j = -m..m.
std::vector<CurvePoint> curve(double k, double q, double noise, unsigned seed, int m, double step,
                              double x0 = 0.0, bool oneSided = false) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<CurvePoint> p;
  for (int j = oneSided ? 0 : -m; j <= m; ++j) {
    const double x = step * j;
    const double d = x - x0;
    p.push_back({x, -42.0 + 0.5 * k * d * d + q * d * d * d * d + noise * gauss(rng)});
  }
  return p;
}

FitOptions options(const std::string& source = "synthetic.json") {
  FitOptions o;
  o.source = source;
  o.quantity = "C";
  return o;
}

TEST(BeamCurveFit, ExactParabolaUsesEveryPoint) {
  const auto p = curve(3.0, 0.0, 0.0, 0, 6, 0.002);
  const QuadraticFit f = fitQuadraticRegime(p, options());
  EXPECT_NEAR(f.stiffness / 3.0, 1.0, 1e-9);
  EXPECT_NEAR(f.energy0, -42.0, 1e-12);
  EXPECT_EQ(f.pointsUsed, 13);
  EXPECT_NEAR(f.windowHalfWidth, 0.012, 1e-15);
  EXPECT_TRUE(f.regimeVerified);
  EXPECT_LT(f.uncertainty, 1e-8);
}

// Exact quartic anharmonicity: the window stops where the quartic energy at the edge reaches
// the tolerance (2 |q| X^2 / k = tol), give or take one step of the grid.
TEST(BeamCurveFit, FindsTheQuadraticWindowOfAnAnharmonicCurve) {
  const double k = 3.0, q = -500.0, step = 0.001;
  const auto p = curve(k, q, 0.0, 0, 20, step);
  FitOptions o = options();
  const QuadraticFit f = fitQuadraticRegime(p, o);
  const double edge = std::sqrt(o.relativeTolerance * k / (2.0 * std::abs(q)));  // 0.00775
  EXPECT_LE(f.windowHalfWidth, edge + 1e-12);
  EXPECT_GE(f.windowHalfWidth, edge - 2.0 * step);
  EXPECT_LT(f.windowHalfWidth, 0.02);  // the anharmonic tail is left out
  EXPECT_FALSE(f.note.empty());
  // The truncation bias is within the reported uncertainty (and well inside the tolerance).
  EXPECT_LE(std::abs(f.stiffness - k), f.uncertainty);
  EXPECT_LT(std::abs(f.stiffness - k), o.relativeTolerance * k);
  EXPECT_GT(f.truncationError, 0.0);
}

// Noise and anharmonicity together, several seeds: the error is within two reported standard
// uncertainties for almost all seeds and within three for all.
TEST(BeamCurveFit, RecoversStiffnessWithinItsUncertaintyUnderNoise) {
  const double k = 3.0, q = -500.0;
  int within2 = 0;
  const int seeds = 20;
  for (int s = 1; s <= seeds; ++s) {
    const auto p = curve(k, q, 2e-8, s, 20, 0.001);
    const QuadraticFit f = fitQuadraticRegime(p, options());
    EXPECT_GT(f.uncertainty, 0.0);
    EXPECT_LE(std::abs(f.stiffness - k), 3.0 * f.uncertainty) << "seed " << s;
    if (std::abs(f.stiffness - k) <= 2.0 * f.uncertainty) ++within2;
    EXPECT_LT(f.uncertainty, 0.05 * k) << "seed " << s;  // the uncertainty is informative
    EXPECT_LT(f.windowHalfWidth, 0.02) << "seed " << s;
  }
  EXPECT_GE(within2, seeds - 2);
}

// A minimum away from x = 0 (e.g. an intrinsic twist): with the linear term the stiffness and
// the slope b = -k x0 are recovered; without it the fit is biased (and the option matters).
TEST(BeamCurveFit, LinearTermHandlesAShiftedMinimum) {
  const double k = 0.8, x0 = 0.003;
  const auto p = curve(k, 0.0, 1e-10, 7, 8, 0.002, x0);
  FitOptions o = options();
  o.linearTerm = true;
  const QuadraticFit f = fitQuadraticRegime(p, o);
  EXPECT_NEAR(f.stiffness / k, 1.0, 1e-4);
  EXPECT_LE(std::abs(f.stiffness - k), 3.0 * f.uncertainty + 1e-12);
  EXPECT_NEAR(f.slope / (-k * x0), 1.0, 1e-3);
  EXPECT_LE(std::abs(f.slope + k * x0), 3.0 * f.slopeError);
}

// Bending rings sample only x >= 0; the even model needs no mirror points.
TEST(BeamCurveFit, OneSidedCurve) {
  const double k = 250.0;
  const auto p = curve(k, 0.0, 1e-9, 3, 6, 0.004, 0.0, true);
  const QuadraticFit f = fitQuadraticRegime(p, options());
  EXPECT_LE(std::abs(f.stiffness - k), 3.0 * f.uncertainty);
  EXPECT_NEAR(f.stiffness / k, 1.0, 1e-3);
  EXPECT_EQ(f.pointsUsed, 7);
}

void expectRefused(const std::vector<CurvePoint>& p, const FitOptions& o,
                   std::initializer_list<const char*> fragments) {
  try {
    fitQuadraticRegime(p, o);
    ADD_FAILURE() << "curve was not refused";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(o.source), std::string::npos) << msg;
    for (const char* f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << msg << " lacks " << f;
  }
}

TEST(BeamCurveFit, RefusesTooFewPoints) {
  expectRefused({{0.0, 1.0}, {0.01, 1.0001}}, options("two.json"), {"too few points (2)", "at least 3"});
  FitOptions o = options("three.json");
  o.linearTerm = true;
  expectRefused({{-0.01, 1.0001}, {0.0, 1.0}, {0.01, 1.0001}}, o, {"too few points (3)", "at least 4"});
}

TEST(BeamCurveFit, RefusesANonConvexCurve) {
  // Double well U = -x^2 + x^4: a maximum at x = 0.
  std::vector<CurvePoint> p;
  for (int j = -5; j <= 5; ++j) {
    const double x = 0.1 * j;
    p.push_back({x, -x * x + x * x * x * x});
  }
  expectRefused(p, options("well.json"), {"no quadratic regime", "not convex"});
}

TEST(BeamCurveFit, RefusesACurveWithoutQuadraticRegime) {
  // U = |x|^3 sampled coarsely: the apparent stiffness doubles from window to window.
  std::vector<CurvePoint> p;
  for (int j = -6; j <= 6; ++j) {
    const double x = 0.01 * j;
    p.push_back({x, 5.0 * std::abs(x * x * x)});
  }
  expectRefused(p, options("cubic.json"), {"no quadratic regime", "smaller deformations"});
}

TEST(BeamCurveFit, RefusesNonFiniteEnergies) {
  auto p = curve(1.0, 0.0, 0.0, 0, 3, 0.01);
  p[2].energy = std::nan("");
  expectRefused(p, options("nan.json"), {"non-finite"});
}

}  // namespace
}  // namespace mesochain::beam
