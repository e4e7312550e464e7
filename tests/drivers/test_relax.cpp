// Relaxation at fixed symmetry: the FIRE relaxation reaches the force tolerance, and the search
// for T0 lands where the axial force vanishes, i.e. at the minimum of the relaxed F(T).
#include <cmath>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/drivers/relax.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
dftb::Calculator calculator() {
  auto params = std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C"}, {{"C-C", std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf"}}, "test"));
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = 48;
  s.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
  return dftb::Calculator(params, s);
}
}  // namespace

TEST(Relax, AtomsAndTranslationOfAZigzagTube) {
  const auto calc = calculator();
  ObjectiveCell cell = buildNanotubeHelical(8, 0, 1.42 * units::kAngstromInBohr);
  cell.positions(0, 1) += 0.05;  // start away from the ideal roll-up
  RelaxSettings rs;
  rs.forceTolerance = 1e-5;
  rs.axialTolerance = 1e-5;
  rs.relaxTranslation = true;
  const RelaxOutcome out = relax(calc, cell, rs);
  ASSERT_TRUE(out.converged);
  EXPECT_LT(maxForce(out.result.gradient), 1e-5);
  EXPECT_LT(std::abs(out.result.dFdTranslation), 1e-5);
  // Independent check of T0: relaxed energies at T0 +- h are not lower.
  const double t0 = out.cell.symmetry.translation(), h = 0.01;
  RelaxSettings fixedT = rs;
  fixedT.relaxTranslation = false;
  for (double t : {t0 - h, t0 + h}) {
    ObjectiveCell c = out.cell;
    c.positions.row(2) *= t / t0;
    c.symmetry = c.symmetry.withTranslation(t);
    const RelaxOutcome o = relax(calc, c, fixedT);
    EXPECT_GT(o.result.freeEnergy, out.result.freeEnergy);
  }
  // The relaxed structure is a tube of the same radius to within a few per cent.
  const double r0 = std::hypot(cell.positions(0, 0), cell.positions(1, 0));
  const double r1 = std::hypot(out.cell.positions(0, 0), out.cell.positions(1, 0));
  EXPECT_NEAR(r1 / r0, 1.0, 0.05);
}
