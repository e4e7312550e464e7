// SCC-DFTB: side by side with DFTB+ 25.1 (SCC = Yes, no third order) on molecules; a ring cell
// against the same structure written out explicitly; finite-difference gradients; and the
// failure reports (non-convergence, tolerances too tight, screw cells before the Ewald sum).
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "scc_support.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using nlohmann::json;

namespace {
json reference(const std::string& name) {
  std::ifstream f(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/" + name + "/reference.json");
  EXPECT_TRUE(f.good()) << name;
  return json::parse(f);
}

json tolerances() {
  std::ifstream f(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/tolerances_scc.json");
  return json::parse(f);
}

ObjectiveCell molecule(const json& ref) {
  ObjectiveCell cell;
  const auto& g = ref["geometry"];
  for (size_t a = 0; a < g["species"].size(); ++a) {
    const auto& x = g["coords_bohr_as_used"][a];
    cell.addAtom(g["species"][a].get<std::string>(),
                 Eigen::Vector3d(x[0].get<double>(), x[1].get<double>(), x[2].get<double>()));
  }
  return cell;
}

void compareWithDftbplus(const std::string& name) {
  const json ref = reference(name), tol = tolerances();
  const ObjectiveCell cell = molecule(ref);
  const auto calc = mesochain::testing::sccCalculator(ref["temperature_K"].get<double>());
  const dftb::Result r = calc.evaluate(cell, {true, false});
  EXPECT_EQ(r.extras.at("scc_converged"), 1.0);
  EXPECT_NEAR(r.freeEnergy, ref["mermin_energy"].get<double>(), tol["mermin_free_energy"]);
  const auto& e = ref["detailed_out_energies"];
  EXPECT_NEAR(r.energies.at("scc_coulomb"), e["Energy SCC"].get<double>(), tol["scc_energy"]);
  EXPECT_NEAR(r.energies.at("h0"), e["Energy H0"].get<double>(), tol["h0_energy"]);
  EXPECT_NEAR(r.energies.at("band"), e["Band energy"].get<double>(), tol["band_energy"]);
  EXPECT_NEAR(r.energies.at("repulsive"), e["Repulsive energy"].get<double>(), tol["repulsive_energy"]);
  const auto& q = r.series.at("mulliken_charges");
  ASSERT_EQ(q.size(), ref["gross_atomic_charges"].size());
  for (size_t a = 0; a < q.size(); ++a)
    EXPECT_NEAR(q[a], ref["gross_atomic_charges"][a].get<double>(), tol["charges"]) << a;
  for (int a = 0; a < cell.atomCount(); ++a)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(-r.gradient(k, a), ref["forces_richardson"][a][k].get<double>(), tol["forces"])
          << "atom " << a << " component " << k;
}

double fd(const dftb::Calculator& calc, ObjectiveCell cell, int a, int k, double h) {
  cell.positions(k, a) += h;
  const double ep = calc.evaluate(cell, {}).freeEnergy;
  cell.positions(k, a) -= 2 * h;
  return (ep - calc.evaluate(cell, {}).freeEnergy) / (2 * h);
}
}  // namespace

TEST(Scc, DistortedEthyleneMatchesDftbplus) { compareWithDftbplus("c2h4_scc"); }

TEST(Scc, DistortedBenzeneMatchesDftbplus) { compareWithDftbplus("benzene_c6"); }

TEST(Scc, RingCellEqualsExplicitCopies) {
  // One CH unit + C_6 against the 12-atom molecule: energies per cell x 6, charges per atom.
  const auto unit = mesochain::testing::benzeneUnit();
  const auto mol = mesochain::testing::explicitCopies(unit);
  const auto calc = mesochain::testing::sccCalculator(300.0);
  const dftb::Result ru = calc.evaluate(unit, {true, false});
  const dftb::Result rm = calc.evaluate(mol, {true, false});
  EXPECT_NEAR(6 * ru.freeEnergy, rm.freeEnergy, 1e-9);
  EXPECT_NEAR(6 * ru.energies.at("scc_coulomb"), rm.energies.at("scc_coulomb"), 1e-9);
  const auto& qu = ru.series.at("mulliken_charges");
  const auto& qm = rm.series.at("mulliken_charges");
  EXPECT_GT(std::abs(qu[0]), 0.01);  // real charge transfer C <- H
  for (int c = 0; c < 6; ++c)
    for (int a = 0; a < 2; ++a) EXPECT_NEAR(qu[a], qm[2 * c + a], 1e-9);
  // The gradient of the unit is the gradient of the molecule's first copy (symmetric images).
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(ru.gradient(k, a), rm.gradient(k, a), 1e-8);
}

TEST(Scc, GradientOfRingCellMatchesFiniteDifferences) {
  auto unit = mesochain::testing::benzeneUnit();
  unit.positions(2, 0) += 0.05;
  const auto calc = mesochain::testing::sccCalculator(1000.0);
  const dftb::Result r = calc.evaluate(unit, {true, false});
  for (int a = 0; a < unit.atomCount(); ++a)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r.gradient(k, a), fd(calc, unit, a, k, 1e-4), 2e-8) << a << " " << k;
}

TEST(Scc, GradientOfMoleculeMatchesFiniteDifferences) {
  const ObjectiveCell cell = molecule(reference("c2h4_scc"));
  const auto calc = mesochain::testing::sccCalculator(2000.0);  // fractional occupations too
  const dftb::Result r = calc.evaluate(cell, {true, false});
  for (int a = 0; a < cell.atomCount(); ++a)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r.gradient(k, a), fd(calc, cell, a, k, 1e-4), 2e-8) << a << " " << k;
}

TEST(Scc, SimpleMixingReachesTheSameSolution) {
  const ObjectiveCell cell = molecule(reference("c2h4_scc"));
  auto s = mesochain::testing::sccSettings(300.0);
  const dftb::Result broyden = dftb::Calculator(mesochain::testing::chParameters(), s).evaluate(cell, {});
  s.scc.mixer = "simple";
  s.scc.mixing = 0.3;
  s.scc.maxIterations = 400;
  const dftb::Result simple = dftb::Calculator(mesochain::testing::chParameters(), s).evaluate(cell, {});
  EXPECT_NEAR(simple.freeEnergy, broyden.freeEnergy, 1e-10);
  EXPECT_GT(simple.extras.at("scc_iterations"), broyden.extras.at("scc_iterations"));
}

TEST(Scc, NonConvergenceIsAnErrorWithTheHistory) {
  const ObjectiveCell cell = molecule(reference("c2h4_scc"));
  auto s = mesochain::testing::sccSettings(300.0);
  s.scc.maxIterations = 2;
  const dftb::Calculator calc(mesochain::testing::chParameters(), s);
  try {
    calc.evaluate(cell, {});
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("max_iterations = 2"), std::string::npos) << m;
    EXPECT_NE(m.find("history"), std::string::npos) << m;
  }
  s.scc.stopIfUnconverged = false;  // flagged result instead
  const dftb::Result r = dftb::Calculator(mesochain::testing::chParameters(), s).evaluate(cell, {});
  EXPECT_EQ(r.extras.at("scc_converged"), 0.0);
  EXPECT_EQ(r.series.at("scc_history_residual").size(), 2u);
}

TEST(Scc, ToleranceBeyondDoublePrecisionIsRefused) {
  auto s = mesochain::testing::sccSettings(300.0);
  s.scc.chargeTolerance = 1e-16;
  EXPECT_THROW(dftb::Calculator(mesochain::testing::chParameters(), s), InputError);
}

TEST(Scc, UnknownMixerIsRefused) {
  auto s = mesochain::testing::sccSettings(300.0);
  s.scc.mixer = "anderson2";
  EXPECT_THROW(dftb::Calculator(mesochain::testing::chParameters(), s), InputError);
}

TEST(Scc, CarbonRingNearlyAgreesWithNonScc) {
  // A cyclic C18 (ring of nine C2 units) whose two atoms are not equivalent: the second sits
  // 0.2 % further out. (Unequal bond lengths alone would not do: the mirror through the middle of
  // a bond exchanges the two atoms, their charges are zero by symmetry and the SCC correction
  // is rounding.) Small charges, so the SCC and non-SCC free energies agree to second order.
  ObjectiveCell cell;
  cell.symmetry = Symmetry::ring(9);
  const double radius = 2.6 * 9 / units::kPi, step = 2 * units::kPi / 9;
  const double outer = 1.002 * radius;
  cell.addAtom("C", {radius, 0.0, 0.0});
  cell.addAtom("C", {outer * std::cos(0.48 * step), outer * std::sin(0.48 * step), 0.0});
  auto s = mesochain::testing::sccSettings(1000.0);
  const dftb::Result scc = dftb::Calculator(mesochain::testing::chParameters(), s).evaluate(cell, {});
  // The SCC functional is minimised by the SCC density, and its Coulomb term is >= 0: the
  // non-SCC free energy is a lower bound, and the functional at the non-SCC density (the first
  // iteration, started from neutral atoms) an upper bound.
  s.scc.maxIterations = 1;
  s.scc.stopIfUnconverged = false;
  const auto first = dftb::Calculator(mesochain::testing::chParameters(), s).evaluate(cell, {});
  s.scc.enabled = false;
  const auto plain = dftb::Calculator(mesochain::testing::chParameters(), s).evaluate(cell, {});
  const auto& q = scc.series.at("mulliken_charges");
  EXPECT_LT(std::abs(q[0]), 1e-2);
  EXPECT_GT(std::abs(q[0]), 1e-5);  // the atoms are not equivalent
  EXPECT_NEAR(q[0] + q[1], 0.0, 1e-10);  // neutral
  EXPECT_LT(std::abs(scc.freeEnergy - plain.freeEnergy), 1e-5);
  EXPECT_GE(scc.freeEnergy, plain.freeEnergy - 1e-12);
  EXPECT_LE(scc.freeEnergy, first.freeEnergy + 1e-12);
  EXPECT_GT(first.freeEnergy - plain.freeEnergy, 1e-8);  // the non-SCC density has charges (5.7e-7)
}
