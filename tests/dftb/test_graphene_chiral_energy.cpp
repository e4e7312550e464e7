// A monolayer graphene sector along the chiral direction (2, 1), with N_a sectors of c cells,
// is the (2 c N_a, c N_a) nanotube: its DFTB free energy per atom equals that of the tube's
// translational cell from the nanotube builder (N_a = 1, all atoms), built with the same bond
// length, to rounding. Both use the same helical k-points along the common period T; the
// sector sums all N_a angular quantum numbers.
#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "support.hpp"

using namespace mesochain;
using namespace mesochain::objective;

TEST(GrapheneChiralEnergy, MonolayerSectorIsTheNanotube) {
  const double bond = 1.42 * units::kAngstromInBohr;
  const dftb::Calculator calc = mesochain::testing::carbonCalculator(4, 300.0);
  const ObjectiveCell tube = buildNanotubeTranslational(4, 2, bond, false);
  ASSERT_EQ(tube.atomCount(), 56);
  const double reference = calc.evaluate(tube, {}).freeEnergy / tube.atomCount();
  for (const auto& [na, cells] : {std::pair{2, 1}, std::pair{1, 2}}) {
    const ObjectiveCell sector = buildGrapheneRingSector(1, ChiralIndices{2, 1}, na, cells, 0.0, bond);
    ASSERT_EQ(sector.atomCount(), 28 * cells);
    ASSERT_NEAR(sector.symmetry.translation(), tube.symmetry.translation(), 1e-10);
    const double e = calc.evaluate(sector, {}).freeEnergy / sector.atomCount();
    EXPECT_NEAR(e, reference, 1e-9) << "N_a = " << na << ", cells = " << cells;
  }
  // The comparison resolves structure: the zigzag (5, 0) sector, a tube 5 % thinner, is far off.
  const ObjectiveCell other = buildGrapheneRingSector(1, ChiralIndices{1, 0}, 5, 1, 0.0, bond);
  EXPECT_GT(std::abs(calc.evaluate(other, {}).freeEnergy / other.atomCount() - reference), 1e-4);
}
