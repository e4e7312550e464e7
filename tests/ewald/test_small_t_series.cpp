// The closed-form small-t part of the splitting integral (docs/ewald.md, eqs. (E18)-(E20)):
// generalised exponential integrals against std::expint and quadrature, and the Taylor-series
// integrals F_lk on [0, t_c] against quadrature of B_l(t) = e^{-ta} I_l(tb) (std::cyl_bessel_i),
// their derivatives against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "ewald/exponential_integral.hpp"
#include "ewald/helical_reciprocal.hpp"
#include "ewald/small_t_series.hpp"

using namespace mesochain;
using ewald::Kernel;
using ewald::detail::SmallTSeries;

namespace {

// int_{-inf}^{0} f(u) du for f decaying at least like e^{u} as u -> -inf: 20-node Gauss-Legendre
// on panels of width 0.25 over [-80, 0].
double integrateLogScale(const std::function<double(double)>& f) {
  std::vector<double> x, w;
  ewald::detail::gaussLegendre(20, x, w);
  double sum = 0;
  for (double u0 = -80; u0 < 0; u0 += 0.25)
    for (size_t i = 0; i < x.size(); ++i) sum += 0.125 * w[i] * f(u0 + 0.125 * (x[i] + 1));
  return sum;
}

// E_nu(x) = int_0^1 s^(nu-2) e^{-x/s} ds = int_{-inf}^0 s^(nu-1) e^{-x/s} du, s = e^u.
double exponentialIntegralByQuadrature(double nu, double x) {
  return integrateLogScale([&](double u) {
    const double s = std::exp(u);
    return std::pow(s, nu - 1) * std::exp(-x / s);
  });
}

}  // namespace

TEST(ExponentialIntegral, FirstOrderMatchesStandardLibrary) {
  std::vector<double> e;
  for (double x : {1e-9, 1e-3, 0.3, 0.999999, 1.0, 1.000001, 2.5, 10.0, 40.0}) {
    ewald::exponentialIntegralSequence(0.0, x, 4, e);
    const double e1 = -std::expint(-x);
    EXPECT_NEAR(e[0], std::exp(-x) / x, 1e-15 * e[0]) << x;
    EXPECT_NEAR(e[1], e1, 5e-15 * e1) << x;  // libstdc++'s expint is good to ~2e-15 here
    // E_2 = e^{-x} - x E_1, E_3 = (e^{-x} - x E_2) / 2 (A&S 5.1.14), summed in long double.
    const long double e2 = std::exp(-static_cast<long double>(x)) - x * static_cast<long double>(e1);
    EXPECT_NEAR(e[2], static_cast<double>(e2), 1e-14 * e[2]) << x;
  }
}

TEST(ExponentialIntegral, IntegerAndHalfIntegerOrdersMatchQuadrature) {
  std::vector<double> e;
  for (double nu0 : {0.0, 2.5})
    for (double x : {1e-6, 0.2, 0.9, 1.1, 3.7, 12.0, 30.0}) {
      const int count = 26;
      ewald::exponentialIntegralSequence(nu0, x, count, e);
      for (int i = 0; i < count; ++i) {
        const double nu = nu0 + i;
        if (nu < 2) continue;  // the quadrature's integrand is singular at s = 0 below nu = 2
        const double ref = exponentialIntegralByQuadrature(nu, x);
        EXPECT_NEAR(e[i], ref, 1e-13 * ref) << "nu " << nu << " x " << x;
      }
    }
}

TEST(ExponentialIntegral, SeriesAndContinuedFractionAgreeAtTheSwitch) {
  std::vector<double> below, above;
  for (double nu0 : {0.0, 2.5}) {
    ewald::exponentialIntegralSequence(nu0, 1.0, 20, below);
    ewald::exponentialIntegralSequence(nu0, std::nextafter(1.0, 2.0), 20, above);
    for (int i = 0; i < 20; ++i) EXPECT_NEAR(below[i], above[i], 1e-14 * below[i]) << i;
  }
  ewald::exponentialIntegralSequence(2.5, 0.0, 3, below);
  EXPECT_DOUBLE_EQ(below[0], 1 / 1.5);
  EXPECT_DOUBLE_EQ(below[2], 1 / 3.5);
}

namespace {

// Reference: int_0^{t_c} c t^beta (B_l(t) [- 1]) e^{-q^2/(4t)} dt / t by quadrature in ln t.
double seriesReference(Kernel k, double tc, double ri, double rj, int l, double q, bool reg) {
  const double a = ri * ri + rj * rj, b = 2 * ri * rj;
  const bool coulomb = k == Kernel::Coulomb;
  return integrateLogScale([&](double u) {
    const double t = tc * std::exp(u);
    const double bl = std::exp(-t * a) * std::cyl_bessel_i(static_cast<double>(l), t * b);
    const double w = coulomb ? 1.0 : 0.5 * std::sqrt(M_PI) * std::pow(t, 2.5);
    return w * ((reg ? bl - 1 : bl) * std::exp(-q * q / (4 * t)));
  });
}

}  // namespace

TEST(SmallTSeries, IntegralsMatchQuadrature) {
  struct Case {
    double ri, rj;
  };
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth})
    for (Case c : {Case{7.7, 7.7}, Case{3.1, 0.0}, Case{2.0, 5.5}, Case{0.2, 0.3}})
      for (double tcScale : {1.0, 0.3}) {
        const double s = (c.ri + c.rj) * (c.ri + c.rj);
        const double tc = tcScale / s;
        SmallTSeries series(k, tc, c.ri, c.rj);
        for (int l : {0, 1, 2, 5})
          for (double q : {0.0, 1e-7, 0.05, 0.3, 0.8}) {
            const bool reg = k == Kernel::Coulomb && l == 0 && q == 0;
            if (k == Kernel::Coulomb && l == 0 && !reg && q < 1e-3) continue;  // ln-divergent
            const double ref = seriesReference(k, tc, c.ri, c.rj, l, q, reg);
            const double v = series.integrals(l, q, reg, false).f;
            const double scale = std::abs(seriesReference(k, tc, c.ri, c.rj, 0, 0, k == Kernel::Coulomb));
            EXPECT_NEAR(v, ref, 1e-13 * scale + 1e-15 * std::abs(ref))
                << "rho " << c.ri << " " << c.rj << " l " << l << " q " << q;
          }
      }
}

TEST(SmallTSeries, DerivativesMatchFiniteDifferences) {
  const double tc = 0.8 / 100.0;  // t_c (rho_i + rho_j)^2 <= 1 for the displaced radii too
  const double h = 1e-4;
  // Fourth-order central differences (truncation ~h^4 f^(5)).
  auto diff = [h](const std::function<double(double)>& g, double x) {
    return (-g(x + 2 * h) + 8 * g(x + h) - 8 * g(x - h) + g(x - 2 * h)) / (12 * h);
  };
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth})
    for (double ri : {0.0, 4.0})
      for (int l : {0, 1, 3})
        for (double q : {0.0, 0.4}) {
          const double rj = 5.0;
          const bool reg = k == Kernel::Coulomb && l == 0 && q == 0;
          auto f = [&](double a, double b, double qq) {
            return SmallTSeries(k, tc, a, b).integrals(l, qq, reg, false).f;
          };
          const auto d = SmallTSeries(k, tc, ri, rj).integrals(l, q, reg, true);
          // Absolute floor: the scale of the problem, the l = 0 integral at these radii.
          const double base = std::abs(SmallTSeries(k, tc, ri, rj).integrals(0, 0, k == Kernel::Coulomb, false).f);
          // roundoff of the differences: ~1e-16 f / h
          auto tol = [&](double ref) { return 1e-8 * std::abs(ref) + 1e-11 * base; };
          const std::string where = "l " + std::to_string(l) + " q " + std::to_string(q) +
                                    " rho_i " + std::to_string(ri);
          if (ri > 0) {
            const double fd = diff([&](double x) { return f(x, rj, q); }, ri);
            EXPECT_NEAR(d.fRhoI, fd, tol(fd)) << where;
            EXPECT_NEAR(d.lOverRhoI, l / ri * f(ri, rj, q), 1e-12 * std::abs(d.lOverRhoI) + 1e-15 * base);
          } else {  // on the axis B_l depends on rho_i^l times a series in rho_i^2: odd extension
            const double sign = l % 2 == 0 ? 1.0 : -1.0;
            const double fd = diff([&](double x) { return (x < 0 ? sign : 1.0) * f(std::abs(x), rj, q); }, 0.0);
            EXPECT_NEAR(d.fRhoI, fd, tol(fd)) << where;
          }
          const double fdJ = diff([&](double x) { return f(ri, x, q); }, rj);
          EXPECT_NEAR(d.fRhoJ, fdJ, tol(fdJ)) << where;
          EXPECT_NEAR(d.lOverRhoJ, l / rj * f(ri, rj, q), 1e-12 * std::abs(d.lOverRhoJ) + 1e-15 * base);
          if (q > 0) {
            const double fdQ = diff([&](double x) { return f(ri, rj, x); }, q);
            EXPECT_NEAR(d.fQ, fdQ, tol(fdQ)) << where;
          }
        }
}

TEST(SmallTSeries, RefusesACutoffBeyondItsConvergenceRange) {
  EXPECT_THROW(SmallTSeries(Kernel::Coulomb, 0.1, 3.0, 3.0), NumericalError);
}
