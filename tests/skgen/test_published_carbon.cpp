// The numerical-grid back-end against the published pbc-0-3 C-C table, with the table's own
// recipe (its documentation block: PBE, density superposition, (r/7.0)^2 density and (r/2.7)^2
// wavefunction confinement). The published integrals were computed in a Slater-type basis
// (exponents 0.50 1.14 2.62 6.0), so the exact-grid orbitals differ slightly; the tolerances
// below are the measured agreement of this back-end (tests/data/skgen/pbc-carbon-agreement.json),
// not the Slater-basis targets.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "dftb/skf_file.hpp"
#include "skgen/element_basis.hpp"
#include "pbc_recipe.hpp"

using namespace mesochain::skgen;

TEST(PublishedCarbon, GridBackEndReproducesPbc03) {
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/skgen/pbc-carbon-agreement.json");
  const nlohmann::json tol = nlohmann::json::parse(in);
  const auto t = mesochain::dftb::readSkfFile(
      std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf", true);
  ElementSettings s;
  s.symbol = "C";
  s.xc = XcKind::Pbe;
  s.hubbardXc = XcKind::LdaPw92;  // see Atom.CarbonHubbardUMatchesThePublishedTable
  s.density = Confinement::powerLaw(7.0, 2.0);
  s.shells = {Confinement::powerLaw(2.7, 2.0), Confinement::powerLaw(2.7, 2.0)};
  s.h = 0.008;
  const ElementBasis b = buildElementBasis(s);
  EXPECT_NEAR(b.data.onsite[0], t.onsite[0], tol["onsite_Ha"].get<double>());
  EXPECT_NEAR(b.data.onsite[1], t.onsite[1], tol["onsite_Ha"].get<double>());
  EXPECT_NEAR(b.data.hubbard[1], t.hubbard[1], tol["hubbard_Ha"].get<double>());

  XcFunctional xc(XcKind::Pbe, false);
  TwoCentreQuadrature q;
  q.nXi = q.nEta = 48;
  q.rMax = 20.0;
  // integral order: ss σ, sp σ, ps σ, pp σ, pp π -> extended .skf columns
  const int column[5] = {19, 18, -1, 14, 15};
  for (double d : {1.0, 2.0, 2.7, 4.0, 6.0}) {
    const auto I = twoCentreIntegrals(b.orbitals, b.orbitals, &b.atom, &b.atom, &xc, d, q);
    const int row = static_cast<int>(std::lround(d / t.gridSpacing)) - 1;
    ASSERT_EQ(I.size(), 5u);
    EXPECT_NEAR(I[1].s, -I[2].s, 1e-10);  // homonuclear parity ⟨s|pσ⟩ = −⟨pσ|s⟩
    for (int k = 0; k < 5; ++k) {
      if (column[k] < 0) continue;
      EXPECT_NEAR(I[k].s, t.over(row, column[k]), tol["S"].get<double>())
          << "d=" << d << " l=" << I[k].la << I[k].lb << " m=" << I[k].m;
      EXPECT_NEAR(I[k].h, t.ham(row, column[k]), tol["H_Ha"].get<double>())
          << "d=" << d << " l=" << I[k].la << I[k].lb << " m=" << I[k].m;
    }
  }
}

TEST(PublishedCarbon, SlaterBackEndReproducesPbc03) {
  // The targets with the published table's own basis (its documentation block:
  // exponents 0.50 1.14 2.62 6.0; three powers r^l, r^{l+1}, r^{l+2} per exponent — two powers
  // miss the table by 1e-3 in S). Every 10th tabulated row from 0.40 to 10.40 bohr (the first 19
  // rows of the file are placeholders 1.0).
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/skgen/pbc-carbon-slater-agreement.json");
  const nlohmann::json tol = nlohmann::json::parse(in);
  const auto t = mesochain::dftb::readSkfFile(
      std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf", true);
  ASSERT_EQ(tol["powers"].get<int>(), 3);
  const ElementBasis& b = mesochain::testing::pbcCarbon();  // tests/skgen/pbc_recipe.hpp
  EXPECT_NEAR(b.data.onsite[0], t.onsite[0], tol["onsite_Ha"].get<double>());
  EXPECT_NEAR(b.data.onsite[1], t.onsite[1], tol["onsite_Ha"].get<double>());
  EXPECT_NEAR(b.data.hubbard[1], t.hubbard[1], tol["hubbard_Ha"].get<double>());

  XcFunctional xc(XcKind::Pbe, false);
  TwoCentreQuadrature q;
  q.nXi = q.nEta = 48;
  q.rMax = 20.0;
  const int column[5] = {19, 18, -1, 14, 15};
  double worstS = 0.0, worstH = 0.0;
  for (int row = tol["first_tabulated_row"].get<int>(); row < t.rows(); row += 10) {
    const double d = (row + 1) * t.gridSpacing;
    const auto I = twoCentreIntegrals(b.orbitals, b.orbitals, &b.atom, &b.atom, &xc, d, q);
    ASSERT_EQ(I.size(), 5u);
    for (int k = 0; k < 5; ++k) {
      if (column[k] < 0) continue;
      worstS = std::max(worstS, std::abs(I[k].s - t.over(row, column[k])));
      worstH = std::max(worstH, std::abs(I[k].h - t.ham(row, column[k])));
      EXPECT_NEAR(I[k].s, t.over(row, column[k]), tol["S"].get<double>())
          << "d=" << d << " l=" << I[k].la << I[k].lb << " m=" << I[k].m;
      EXPECT_NEAR(I[k].h, t.ham(row, column[k]), tol["H_Ha"].get<double>())
          << "d=" << d << " l=" << I[k].la << I[k].lb << " m=" << I[k].m;
    }
  }
  RecordProperty("worst_S", std::to_string(worstS));
  RecordProperty("worst_H_Ha", std::to_string(worstH));
}
