// Per-element Lennard-Jones parameters (dftb::DispersionSettings::elements): one element with
// the single parameter set gives today's numbers bit for bit; pairs of different elements use
// DFTB+'s combination rule (geometric means of well depth and distance, DFTB+ dispuff.F90),
// checked against the closed form of the UFF-type potential (Zhechkov et al., JCTC 1, 841
// (2005): the published U0, U5, U10 inside r_s = 2^(-1/6) r0) on a molecule, for the cutoff and
// the Ewald sum; an element without parameters is an error naming it.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "dftb/charge_cache.hpp"
#include "dftb/term_registry.hpp"
#include "scc_support.hpp"
#include "support.hpp"

using namespace mesochain;
using namespace mesochain::dftb;

namespace {
TermOutput evaluateDispersion(const std::shared_ptr<const ParameterSet>& params, const CalculatorSettings& s,
                              const objective::ObjectiveCell& cell) {
  const TermBuild b{params, s, std::make_shared<ChargeCache>(), {}};
  const auto term = findTerm("dispersion")->make(b);
  TermOutput out;
  term->evaluate(cell, {true, true}, out);
  return out;
}

CalculatorSettings single(bool ewald) {
  CalculatorSettings s;
  s.dispersion.enabled = true;
  s.dispersion.epsilon = 0.069 * units::kKcalPerMolInHartree;
  s.dispersion.r0 = 3.80 * units::kAngstromInBohr;
  s.dispersion.cutoff = 20.0;
  s.dispersion.ewald = ewald;
  s.dispersion.ewaldTolerance = 1e-10;
  return s;
}

// The UFF-type pair potential written out from the paper's constants.
double closedForm(double eps, double r0, double r) {
  const double rs = std::pow(2.0, -1.0 / 6.0) * r0;
  if (r >= rs) return eps * (std::pow(r0 / r, 12) - 2 * std::pow(r0 / r, 6));
  const double u0 = 396.0 / 25.0 * eps;
  const double u5 = std::pow(2.0, 5.0 / 6.0) * 672.0 / 25.0 * eps / std::pow(r0, 5);
  const double u10 = -std::pow(2.0, 2.0 / 3.0) * 552.0 / 25.0 * eps / std::pow(r0, 10);
  return u0 - u5 * std::pow(r, 5) - u10 * std::pow(r, 10);
}
}  // namespace

TEST(DispersionElements, OneElementGivesTodaysNumbersExactly) {
  objective::ObjectiveCell cell = mesochain::testing::armchairHelical(4);
  mesochain::testing::distort(cell, 0.06);
  const auto params = mesochain::testing::carbonParameters();
  for (bool ewald : {false, true}) {
    SCOPED_TRACE(ewald ? "ewald" : "cutoff");
    const CalculatorSettings a = single(ewald);
    CalculatorSettings b = a;
    b.dispersion.elements = {"C"};
    b.dispersion.elementEpsilon = {a.dispersion.epsilon};
    b.dispersion.elementR0 = {a.dispersion.r0};
    TermOutput ra = evaluateDispersion(params, a, cell), rb = evaluateDispersion(params, b, cell);
    EXPECT_EQ(ra.energies["dispersion"], rb.energies["dispersion"]);
    EXPECT_NE(ra.energies["dispersion"], 0.0);
    EXPECT_TRUE(ra.gradient == rb.gradient);
    EXPECT_EQ(ra.dEdTranslation, rb.dEdTranslation);
    EXPECT_EQ(ra.dEdTwist, rb.dEdTwist);
  }
}

TEST(DispersionElements, PairsCombineByGeometricMeans) {
  // C at the origin, H at 5 and 7 Bohr: C-H at 5 Bohr lies inside r_s (polynomial), the others
  // outside.
  objective::ObjectiveCell mol;
  mol.addAtom("C", {0.0, 0.0, 0.0});
  mol.addAtom("H", {5.0, 0.0, 0.0});
  mol.addAtom("H", {0.0, 7.0, 0.0});
  const double eC = 2e-4, rC = 7.0, eH = 8e-5, rH = 5.5;
  const double eCH = std::sqrt(eC * eH), rCH = std::sqrt(rC * rH);
  ASSERT_LT(5.0, std::pow(2.0, -1.0 / 6.0) * rCH);
  const double expected = closedForm(eCH, rCH, 5.0) + closedForm(eCH, rCH, 7.0) +
                          closedForm(eH, rH, std::sqrt(74.0));
  for (bool ewald : {false, true}) {
    SCOPED_TRACE(ewald ? "ewald" : "cutoff");
    CalculatorSettings s = single(ewald);
    s.dispersion.cutoff = 40.0;
    // As the readers leave them: the one-set values unused.
    s.dispersion.epsilon = s.dispersion.r0 = 0.0;
    // Listed in another order than the parameter set's species (C, H).
    s.dispersion.elements = {"H", "C"};
    s.dispersion.elementEpsilon = {eH, eC};
    s.dispersion.elementR0 = {rH, rC};
    TermOutput out = evaluateDispersion(mesochain::testing::chParameters(), s, mol);
    EXPECT_NEAR(out.energies["dispersion"], expected, 1e-12 * std::abs(expected));
    // Forces balance on a molecule.
    EXPECT_LT(out.gradient.rowwise().sum().cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(DispersionElements, AnElementWithoutParametersIsAnError) {
  CalculatorSettings s = single(false);
  s.dispersion.elements = {"C"};
  s.dispersion.elementEpsilon = {1e-4};
  s.dispersion.elementR0 = {7.0};
  try {
    evaluateDispersion(mesochain::testing::chParameters(), s, mesochain::testing::helicalChUnit());
    FAIL() << "no error for H without parameters";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no Lennard-Jones parameters for H"), std::string::npos) << e.what();
  }
  s.dispersion.elementR0.clear();
  EXPECT_THROW(validate(s.dispersion), InputError);
}
