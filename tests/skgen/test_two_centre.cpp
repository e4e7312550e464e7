// Two-centre integrals: closed forms for Slater-type orbitals and grid convergence.
#include <gtest/gtest.h>

#include <cmath>

#include "skgen/two_centre.hpp"

using namespace mesochain::skgen;

namespace {
// Normalised Slater function R(r) = N r^(n-1) e^(-ζ r) on a fine log grid.
TwoCentreOrbital slater(int n, int l, double zeta) {
  TwoCentreOrbital o;
  o.l = l;
  o.grid = LogGrid::make(1e-6, 60.0, 0.002);
  const double norm = std::sqrt(std::pow(2.0 * zeta, 2 * n + 1) / std::tgamma(2.0 * n + 1.0));
  o.radial.resize(o.grid.size());
  for (int i = 0; i < o.grid.size(); ++i) {
    const double r = o.grid.r[i];
    o.radial[i] = norm * std::pow(r, n - 1) * std::exp(-zeta * r);
  }
  o.potential.assign(o.grid.size(), 0.0);
  return o;
}
}  // namespace

TEST(GaussLegendre, IntegratesPolynomialsExactly) {
  std::vector<double> x, w;
  gaussLegendre(7, x, w);
  for (int k = 0; k <= 13; ++k) {
    double s = 0.0;
    for (int i = 0; i < 7; ++i) s += w[i] * std::pow(x[i], k);
    EXPECT_NEAR(s, k % 2 ? 0.0 : 2.0 / (k + 1), 1e-14) << k;
  }
}

TEST(TwoCentre, OverlapOfTwo1sSlaterOrbitalsIsTheClosedForm) {
  // S(R) = e^(-R) (1 + R + R²/3) for ζ = 1 (Mulliken, Rieke, Orloff, Orloff 1949)
  const std::vector<TwoCentreOrbital> a = {slater(1, 0, 1.0)};
  TwoCentreQuadrature q;
  q.rMax = 45.0;
  for (double d : {0.3, 1.0, 2.5, 6.0}) {
    const auto I = twoCentreIntegrals(a, a, nullptr, nullptr, nullptr, d, q);
    ASSERT_EQ(I.size(), 1u);
    EXPECT_NEAR(I[0].s, std::exp(-d) * (1.0 + d + d * d / 3.0), 1e-10) << "d=" << d;
  }
}

TEST(TwoCentre, OverlapOf1sAnd2pSlaterOrbitalsHasTheSlaterKosterSign) {
  // Parity: ⟨s_A|pσ_B⟩ = −⟨pσ_A|s_B⟩, negative at bonding distances (the .skf convention); only
  // the σ integral exists between s and p.
  const std::vector<TwoCentreOrbital> s = {slater(1, 0, 1.0)};
  const std::vector<TwoCentreOrbital> p = {slater(2, 1, 1.0)};
  TwoCentreQuadrature q;
  const auto sp = twoCentreIntegrals(s, p, nullptr, nullptr, nullptr, 2.0, q);
  const auto ps = twoCentreIntegrals(p, s, nullptr, nullptr, nullptr, 2.0, q);
  ASSERT_EQ(sp.size(), 1u);
  EXPECT_LT(sp[0].s, -0.1);
  EXPECT_NEAR(sp[0].s, -ps[0].s, 1e-12);
}

TEST(TwoCentre, OverlapConvergesWithTheQuadrature) {
  const std::vector<TwoCentreOrbital> p = {slater(2, 1, 1.6)};
  double prev = 0.0, diff[3];
  for (int k = 0; k < 4; ++k) {
    TwoCentreQuadrature q;
    q.nXi = q.nEta = 12 << k;
    const auto I = twoCentreIntegrals(p, p, nullptr, nullptr, nullptr, 2.7, q);
    if (k > 0) diff[k - 1] = std::abs(I[0].s - prev);
    prev = I[0].s;
  }
  EXPECT_LT(diff[2], diff[0]);
  EXPECT_LT(diff[2], 1e-10);
}
