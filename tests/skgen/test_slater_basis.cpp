// Slater-type-function back-end: exact hydrogen-like states when the basis holds them, the
// analytic kinetic term against finite differences, the variational bound of a finite basis.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "skgen/atom.hpp"
#include "skgen/slater_basis.hpp"

using namespace mesochain::skgen;

TEST(SlaterBasis, HydrogenLikeStatesAreExactWhenTheBasisHoldsThem) {
  // e^{-r} (1s), (1 − r/2) e^{-r/2} (2s) and r e^{-r/2} (2p) lie in span{r^{l+i} e^{-α r}},
  // α ∈ {0.5, 1}, i = 0, 1: the eigenvalues are −1/2, −1/8, −1/8 up to the potential quadrature.
  const LogGrid g = LogGrid::make(1e-7, 80.0, 0.004);
  std::vector<double> v(g.size());
  for (int i = 0; i < g.size(); ++i) v[i] = -1.0 / g.r[i];
  const SlaterBasis basis{{0.5, 1.0}, 2};
  const auto s = SlaterRadialSolver(basis, g, 0).solve(v, 2);
  EXPECT_NEAR(s[0].energy, -0.5, 1e-11);
  EXPECT_NEAR(s[1].energy, -0.125, 1e-11);
  const auto p = SlaterRadialSolver(basis, g, 1).solve(v, 1);
  EXPECT_NEAR(p[0].energy, -0.125, 1e-11);
  // the 1s function is 2 e^{-r}, outer lobe positive
  for (double r : {0.1, 1.0, 4.0})
    EXPECT_NEAR(evaluateSlater(s[0].terms, 0, r).R, 2.0 * std::exp(-r), 1e-9) << r;
}

TEST(SlaterBasis, SmallerBasisGivesAVariationalUpperBound) {
  const LogGrid g = LogGrid::make(1e-7, 80.0, 0.004);
  std::vector<double> v(g.size());
  for (int i = 0; i < g.size(); ++i) v[i] = -1.0 / g.r[i];
  // no exponent 1: the 1s level lies above −1/2 and approaches it as powers are added
  double last = 0.0;
  for (int powers = 1; powers <= 4; ++powers) {
    const double e = SlaterRadialSolver({{0.7, 1.6}, powers}, g, 0).solve(v, 1)[0].energy;
    EXPECT_GT(e, -0.5);
    if (powers > 1) {
      EXPECT_LT(e, last);
    }
    last = e;
  }
  EXPECT_NEAR(last, -0.5, 1e-5);
}

TEST(SlaterBasis, KineticTermMatchesFiniteDifferences) {
  // t = −½ [R'' + 2R'/r − l(l+1)R/r²] and R' against central differences of R.
  for (int l = 0; l <= 1; ++l) {
    const std::vector<SlaterTerm> terms = {
        {0.8, l, 0.5}, {-1.3, l + 1, 1.14}, {0.4, l + 2, 2.62}, {2.1, l, 6.0}};
    for (double r : {0.05, 0.4, 1.3, 3.0, 7.5}) {
      const double hd = 1e-4 * r;
      const double Rm = evaluateSlater(terms, l, r - hd).R, R0 = evaluateSlater(terms, l, r).R,
                   Rp = evaluateSlater(terms, l, r + hd).R;
      const double d1 = (Rp - Rm) / (2.0 * hd), d2 = (Rp - 2.0 * R0 + Rm) / (hd * hd);
      const SlaterValue sv = evaluateSlater(terms, l, r);
      EXPECT_NEAR(sv.dR, d1, 1e-7 * (1.0 + std::abs(d1))) << "l=" << l << " r=" << r;
      const double t = -0.5 * (d2 + 2.0 * d1 / r - l * (l + 1.0) * R0 / (r * r));
      EXPECT_NEAR(sv.t, t, 2e-5 * (1.0 + std::abs(t))) << "l=" << l << " r=" << r;
    }
  }
}

TEST(SlaterBasis, CarbonLdaApproachesNistFromAbove) {
  // A finite basis bounds the Kohn-Sham total energy from above (variational principle, exact
  // quadrature); an even-tempered set of Slater functions comes within 1e-3 Ha of the NIST LDA
  // total energy (the grid back-end's exact reference).
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/skgen/nist-carbon.json");
  const nlohmann::json ref = nlohmann::json::parse(in);
  AtomSettings s;
  s.name = "C";
  s.z = 6;
  s.shells = {{1, 0, {1.0, 1.0}}, {2, 0, {1.0, 1.0}}, {2, 1, {1.0, 1.0}}};
  s.xc = XcKind::LdaVwn;
  s.h = 0.008;
  s.slater = {{0.5, 1.14, 2.62, 6.0}, 3};  // the pbc-0-3 carbon set
  const double ePublishedSet = solveAtom(s).energies.total;
  s.slater = {{0.4, 0.8, 1.6, 3.2, 6.4, 12.8}, 3};
  const AtomSolution a = solveAtom(s);
  const double nist = ref["LDA"]["Etot"].get<double>();
  EXPECT_GT(ePublishedSet, nist);
  EXPECT_GT(a.energies.total, nist);
  EXPECT_LT(a.energies.total, ePublishedSet);
  EXPECT_NEAR(a.energies.total, nist, 1e-3);
  EXPECT_NEAR(a.shell(2, 1).energy[0], ref["LDA"]["2p"].get<double>(), 1e-3);
}
