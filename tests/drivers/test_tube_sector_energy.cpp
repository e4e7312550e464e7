// A one-wall sector of buildMultiWallSector is the same tube as the graphene-ring monolayer of
// the existing builder (N_a sectors of c sheet cells = the (c N_a, c N_a) tube) and as the
// translational cell: same DFTB energy per tube length at the same settings (every angular
// quantum number of the sector is summed, so C_d x sector = translational cell exactly). Two
// walls: the sector's energy is 1/d of the two-wall translational cell's.
#include <cmath>

#include <gtest/gtest.h>

#include "carbon_fixture.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"

namespace mesochain::objective {
namespace {

using testing::carbon;
using testing::kBond;
using testing::settings;

TEST(TubeSectorEnergy, OneWallSectorEqualsTheRingAndTheTranslationalCell) {
  const dftb::Calculator calc(carbon(), settings(8));
  // (10,10): C5 sector of 8 atoms; the graphene ring of 5 sectors x 2 armchair cells; 40 atoms.
  const ObjectiveCell sector = buildMultiWallSector({{10, 10}}, kBond, 5);
  const ObjectiveCell ring = buildGrapheneRingSector(1, Direction::Armchair, 5, 2, 0.0, kBond);
  const ObjectiveCell full = buildNanotubeTranslational(10, 10, kBond, false);
  ASSERT_EQ(sector.atomCount(), 8);
  ASSERT_EQ(ring.atomCount(), 8);
  EXPECT_EQ(ring.symmetry.rotationOrder(), sector.symmetry.rotationOrder());
  EXPECT_NEAR(ring.symmetry.translation(), sector.symmetry.translation(), 1e-9);
  const double es = calc.evaluate(sector, {}).freeEnergy;
  const double er = calc.evaluate(ring, {}).freeEnergy;
  const double ef = calc.evaluate(full, {}).freeEnergy;
  EXPECT_TRUE(std::isfinite(es));
  EXPECT_NEAR(es, er, 1e-8 * std::abs(es));
  EXPECT_NEAR(5.0 * es, ef, 1e-8 * std::abs(ef));
}

TEST(TubeSectorEnergy, TwoWallSectorIsOneFifthOfTheTranslationalCell) {
  const dftb::Calculator calc(carbon(), settings(4));
  const ObjectiveCell sector = buildMultiWallSector({{5, 5}, {10, 10}}, kBond, 5);
  const ObjectiveCell full = buildMultiWallTranslational({{5, 5}, {10, 10}}, kBond);
  ASSERT_EQ(sector.atomCount(), 4 + 8);
  const double es = calc.evaluate(sector, {}).freeEnergy;
  const double ef = calc.evaluate(full, {}).freeEnergy;
  EXPECT_NEAR(5.0 * es, ef, 1e-8 * std::abs(ef));
}

}  // namespace
}  // namespace mesochain::objective
