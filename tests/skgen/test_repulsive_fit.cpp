// Repulsive fit: a known smooth repulsive is recovered from a synthetic dimer curve
// E_ref = E_el + R + const, the spline block is continuous (C2 at the knots, head matching at
// r_min, zero with zero slope and curvature at the cutoff) and survives writing and reading.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/errors.hpp"
#include "dftb/repulsive.hpp"
#include "pbc_recipe.hpp"
#include "skgen/repulsive_fit.hpp"

using namespace mesochain;
using namespace mesochain::skgen;

namespace {
constexpr double kCut = 3.5;
double knownRepulsive(double r) { return 0.08 * std::pow(kCut - r, 4) * std::exp(-0.3 * r); }

void value(const dftb::SplineRepulsiveData& s, double r, double& v, double& dv) {
  dftb::SplineRepulsive(s).evaluate(r, v, dv);
}
}  // namespace

TEST(RepulsiveFit, SplineRecoversASmoothRepulsiveWithASmoothCutoff) {
  std::vector<double> r, y;
  for (double x = 1.2; x <= 4.0; x += 0.02) {
    r.push_back(x);
    y.push_back(x < kCut ? knownRepulsive(x) : 0.0);
  }
  auto fitError = [&](int intervals) {
    const dftb::SplineRepulsiveData f = fitRepulsiveSpline(r, y, kCut, intervals, "test", "fit");
    double worst = 0.0, v, dv;
    for (double x = 1.2; x < kCut; x += 0.0037) {
      value(f, x, v, dv);
      worst = std::max(worst, std::abs(v - knownRepulsive(x)));
    }
    return worst;
  };
  // cubic-spline bound (5/384) h⁴ max|R| ≈ 3e-6 for h = 2.3/20 (max|R| < 1.4 Ha/bohr⁴),
  // and the O(h⁴) convergence when the intervals are doubled
  const double e20 = fitError(20), e40 = fitError(40);
  EXPECT_LT(e20, 5e-6);
  EXPECT_LT(e40, e20 / 10.0);
  const dftb::SplineRepulsiveData s = fitRepulsiveSpline(r, y, kCut, 20, "test", "fit");
  // C2 at the knots: the left polynomial at its end equals the right one at its start
  for (std::size_t k = 0; k + 1 < s.start.size(); ++k) {
    const double x = s.end[k] - s.start[k];
    const auto& c = s.coeffs[k];
    const double f = c[0] + x * (c[1] + x * (c[2] + x * c[3]));
    const double f1 = c[1] + x * (2 * c[2] + 3 * x * c[3]);
    const double f2 = 2 * c[2] + 6 * x * c[3];
    const auto& n = s.coeffs[k + 1];
    EXPECT_NEAR(f, n[0], 1e-12);
    EXPECT_NEAR(f1, n[1], 1e-10);
    EXPECT_NEAR(f2, 2 * n[2], 1e-8);
  }
  // smooth cutoff: value, slope and curvature vanish at r_c
  const auto& last = s.coeffs.back();
  const double x = s.end.back() - s.start.back();
  EXPECT_NEAR(last[0] + x * (last[1] + x * (last[2] + x * last[3])), 0.0, 1e-12);
  EXPECT_NEAR(last[1] + x * (2 * last[2] + 3 * x * last[3]), 0.0, 1e-11);
  EXPECT_NEAR(2 * last[2] + 6 * x * last[3], 0.0, 1e-9);
  // head: continuous value and slope at r_min (reader evaluates the head below start.front())
  double vh, dvh, vs, dvs;
  value(s, s.start.front() - 1e-9, vh, dvh);
  value(s, s.start.front(), vs, dvs);
  EXPECT_NEAR(vh, vs, 1e-8);
  EXPECT_NEAR(dvh, dvs, 1e-6);
  value(s, 0.5, vh, dvh);
  EXPECT_GT(vh, vs);  // repulsive head grows inwards
}

TEST(RepulsiveFit, NonRepulsiveTargetIsAClearError) {
  std::vector<double> r, y;
  for (double x = 1.2; x <= 4.0; x += 0.05) {
    r.push_back(x);
    y.push_back(x < kCut ? -knownRepulsive(x) : 0.0);  // attractive
  }
  EXPECT_THROW(fitRepulsiveSpline(r, y, kCut, 10, "test", "fit"), InputError);
  EXPECT_THROW(fitRepulsiveSpline(r, y, kCut, 200, "test", "fit"), InputError);  // too few points
}

TEST(RepulsiveFit, DimerCurveGivesBackTheRepulsive) {
  // synthetic reference: E_ref = E_el + R + 0.3 Ha; the fit must return R (the constant drops)
  const ElementBasis& h = mesochain::testing::pbcHydrogen();
  TwoCentreQuadrature q;
  q.nXi = q.nEta = 32;
  const std::string path = mesochain::testing::tempPath("hh-curve.csv");
  {
    std::ofstream out(path);
    out << "r_bohr,energy_hartree\n";
    for (double x = 1.0; x <= 4.01; x += 0.1)
      out << x << "," << dimerElectronicEnergy(h, h, XcKind::Pbe, q, x) +
                             (x < kCut ? knownRepulsive(x) : 0.0) + 0.3
          << "\n";
  }
  const DimerCurve c = readDimerCurve(path);
  const auto s = fitRepulsive(h, h, XcKind::Pbe, q, c, kCut, 8, "repulsive.H-H");
  double worst = 0.0, v, dv;
  for (double x = 1.0; x < kCut; x += 0.05) {
    value(s, x, v, dv);
    worst = std::max(worst, std::abs(v - knownRepulsive(x)));
  }
  EXPECT_LT(worst, 2e-4);  // cubic spline of 8 intervals through 25 points of a smooth curve
  // the H2 electronic energy is bonding: 2 ε_σ below the atoms' 2 ε_s near 1.4 bohr
  EXPECT_LT(dimerElectronicEnergy(h, h, XcKind::Pbe, q, 1.4), 2 * h.data.onsite[0] - 0.2);
}

TEST(RepulsiveFit, BadCurveFilesAreClearErrors) {
  const std::string path = mesochain::testing::tempPath("bad-curve.csv");
  std::ofstream(path) << "r,E\n1,2\n";
  EXPECT_THROW(readDimerCurve(path), InputError);
  std::ofstream(path) << "r_bohr,energy_hartree\n1,2\n0.5,3\n";
  EXPECT_THROW(readDimerCurve(path), InputError);
  EXPECT_THROW(readDimerCurve(path + ".missing"), InputError);
}
