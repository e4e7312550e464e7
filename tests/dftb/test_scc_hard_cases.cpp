// Hard cases of the SCC loop: a metallic tube at low electronic temperature, charge sloshing in
// a long polar cell (Broyden converges; simple mixing is reported, not silently wrong).
// A tolerance beyond double precision is refused in test_scc.cpp (ToleranceBeyond...). And the
// warm start of the loop from the charges of the previous evaluation.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "scc_support.hpp"
#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
// The (5,5) tube as a translational cell without rotation symmetry: the 2-atom helical cell's
// images under the screw steps z = 0, 1 and the rotations c = 0..4 (20 atoms); screw 2 steps
// and rotate back by one C_5 step is the pure translation 2 T.
ObjectiveCell tube55TranslationalCell() {
  const ObjectiveCell unit = mesochain::testing::armchairHelical(5);
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(2 * unit.symmetry.translation(), 0.0, 1);
  for (int z = 0; z < 2; ++z)
    for (int c = 0; c < 5; ++c)
      for (int a = 0; a < unit.atomCount(); ++a)
        cell.addAtom("C", unit.symmetry.apply(GroupElement{z, c}, unit.positions.col(a)));
  return cell;
}

// The polar (CH)_2 chain of tests/data/dftbplus/ch_chain_1d (translation 2.46 A).
ObjectiveCell polarChain() {
  const double b = 1.0 / 0.529177249;
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(2.46 * b, 0.0, 1);
  cell.addAtom("C", {-0.36 * b, 0.0, 0.0});
  cell.addAtom("C", {0.34 * b, 0.05 * b, 1.25 * b});
  cell.addAtom("H", {-1.40 * b, 0.30 * b, -0.20 * b});
  cell.addAtom("H", {1.05 * b, 0.85 * b, 1.60 * b});
  return cell;
}
}  // namespace

TEST(SccHardCases, MetallicTubeAtLowTemperatureConverges) {
  auto cell = tube55TranslationalCell();
  ASSERT_EQ(cell.atomCount(), 20);
  mesochain::testing::distort(cell, 0.05);  // unequal atoms: charges move at the Fermi level
  auto s = mesochain::testing::sccSettings(10.0, 16);
  const auto params = mesochain::testing::carbonParameters();
  const dftb::Result scc = dftb::Calculator(params, s).evaluate(cell, {});
  EXPECT_EQ(scc.extras.at("scc_converged"), 1.0);
  EXPECT_LT(scc.series.at("scc_history_residual").back(), 1e-11);
  const auto& q = scc.series.at("mulliken_charges");
  double total = 0, largest = 0;
  for (double x : q) {
    total += x;
    largest = std::max(largest, std::abs(x));
  }
  EXPECT_NEAR(total, 0.0, 1e-10);
  EXPECT_GT(largest, 1e-4);
  // Variational bounds: F(non-SCC) <= F(SCC) <= F at the non-SCC density (first iteration).
  s.scc.maxIterations = 1;
  s.scc.stopIfUnconverged = false;
  const auto first = dftb::Calculator(params, s).evaluate(cell, {});
  s.scc.enabled = false;
  const auto plain = dftb::Calculator(params, s).evaluate(cell, {});
  EXPECT_GE(scc.freeEnergy, plain.freeEnergy - 1e-12);
  EXPECT_LE(scc.freeEnergy, first.freeEnergy + 1e-12);
}

TEST(SccHardCases, ChargeSloshingInALongCell) {
  // 16 chain units (64 atoms, 39 A, slightly distorted so that the charges are not periodic in
  // the unit): simple mixing with alpha = 0.5, which converges the single unit, lets the
  // long-wavelength charge modes of the long cell oscillate, and the loop says so; Broyden
  // converges it.
  auto unit = polarChain();
  auto cell = mesochain::testing::translationalSupercell(unit, 16);
  mesochain::testing::distort(unit, 0.05);
  mesochain::testing::distort(cell, 0.05);
  const auto params = mesochain::testing::chParameters();
  auto s = mesochain::testing::sccSettings(300.0, 16);
  s.scc.mixer = "simple";
  s.scc.mixing = 0.5;
  EXPECT_EQ(dftb::Calculator(params, s).evaluate(unit, {}).extras.at("scc_converged"), 1.0);

  s.band.helicalKPoints = 1;
  try {
    dftb::Calculator(params, s).evaluate(cell, {});
    FAIL() << "simple mixing 0.5 converged the long cell";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("charge sloshing"), std::string::npos) << m;
    EXPECT_NE(m.find("history"), std::string::npos) << m;
  }
  s.scc.stopIfUnconverged = false;  // the flagged last iterate instead of an exception
  const dftb::Result flagged = dftb::Calculator(params, s).evaluate(cell, {});
  EXPECT_EQ(flagged.extras.at("scc_converged"), 0.0);
  EXPECT_GT(flagged.extras.at("scc_residual"), 1e-3);

  s.scc.mixer = "broyden";
  s.scc.stopIfUnconverged = true;
  const dftb::Result broyden = dftb::Calculator(params, s).evaluate(cell, {});
  EXPECT_EQ(broyden.extras.at("scc_converged"), 1.0);
  EXPECT_LT(broyden.extras.at("scc_residual"), 1e-11);
  // The unconverged iterate is far from the solution: flagging it matters.
  EXPECT_GT(std::abs(flagged.freeEnergy - broyden.freeEnergy), 1e-6);
  // Variational bounds of the converged energy (see test_scc_helical.cpp).
  s.scc.enabled = false;
  const dftb::Result plain = dftb::Calculator(params, s).evaluate(cell, {});
  EXPECT_GE(broyden.freeEnergy, plain.freeEnergy - 1e-12);
  // The history holds the band term (no repulsive): its first entry is the functional at the
  // non-SCC density.
  EXPECT_LE(broyden.freeEnergy - broyden.energies.at("repulsive"),
            broyden.series.at("scc_history_energy").front() + 1e-12);
}

TEST(SccWarmStart, RelaxationLikeStepsNeedFewerIterations) {
  // A sequence of nearby geometries (steps of a relaxation): warm-started loops take fewer
  // iterations than loops from neutral atoms and reach the same energies and charges.
  const auto params = mesochain::testing::chParameters();
  auto s = mesochain::testing::sccSettings(300.0, 8);
  const dftb::Calculator warm(params, s);
  s.scc.warmStart = false;
  const dftb::Calculator cold(params, s);
  long warmIterations = 0, coldIterations = 0;
  for (int step = 0; step < 4; ++step) {
    auto cell = polarChain();
    mesochain::testing::distort(cell, 0.02 * step);
    const auto rw = warm.evaluate(cell, {true, false});
    const auto rc = cold.evaluate(cell, {true, false});
    EXPECT_EQ(rw.extras.at("scc_warm_start"), step > 0 ? 1.0 : 0.0);
    EXPECT_EQ(rc.extras.at("scc_warm_start"), 0.0);
    warmIterations += static_cast<long>(rw.extras.at("scc_iterations"));
    coldIterations += static_cast<long>(rc.extras.at("scc_iterations"));
    EXPECT_NEAR(rw.freeEnergy, rc.freeEnergy, 1e-10);
    for (int a = 0; a < 4; ++a) {
      EXPECT_NEAR(rw.series.at("mulliken_charges")[a], rc.series.at("mulliken_charges")[a], 1e-9);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(rw.gradient(k, a), rc.gradient(k, a), 1e-9);
    }
  }
  EXPECT_LT(warmIterations, coldIterations);
  EXPECT_EQ(warm.chargeCache().hits(), 3);
  EXPECT_EQ(warm.chargeCache().iterations(), warmIterations);
  // Different atoms (a supercell) do not take the cached charges.
  const auto super = mesochain::testing::translationalSupercell(polarChain(), 2);
  EXPECT_EQ(warm.evaluate(super, {}).extras.at("scc_warm_start"), 0.0);
  // clear() forgets them.
  warm.chargeCache().clear();
  EXPECT_EQ(warm.evaluate(polarChain(), {}).extras.at("scc_warm_start"), 0.0);
}
