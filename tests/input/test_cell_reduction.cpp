// mesochain reduce (issue 17): hidden rotation orders found, and the reduced cell's energy per
// atom, Mermin free energy per atom and forces equal to the original cell's (block
// diagonalisation by the irreducible representations of the larger group, not an approximation).
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_calculator.hpp"
#include "input/cell_reduction.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "tests/support/expect_input_error.hpp"

namespace mesochain::objective {
namespace {

const double kBond = 1.42 / units::kBohrInAngstrom;

CellInput tubeInput(const ObjectiveCell& cell, int helical) {
  CellInput in;
  in.source = "<test>";
  in.cell = cell;
  in.band.helicalKPoints = helical;
  in.band.electronicTemperature = 3000.0 * units::kBoltzmannHartreePerKelvin;  // a real entropy term
  in.parameterSet = "pbc-0-3";
  in.parameterFiles = parameterSetFiles("pbc-0-3", cell.speciesNames, "<test>", "parameters.set");
  return in;
}

TEST(CellReduction, TranslationalArmchairCellHasItsFiveFoldAxis) {
  // (5,5): the pure rotations about the axis are C_gcd(5,5) = C_5 (the C_10 is a screw).
  const ObjectiveCell cell = buildNanotubeTranslational(5, 5, kBond);
  ASSERT_EQ(cell.atomCount(), 20);
  const RotationReduction r = findExtraRotation(cell, kDefaultReductionToleranceBohr);
  EXPECT_EQ(r.extraOrder, 5);
  EXPECT_EQ(r.representatives.size(), 4u);
  const ObjectiveCell reduced = reducedCell(cell, r);
  EXPECT_EQ(reduced.symmetry.rotationOrder(), 5);
  EXPECT_DOUBLE_EQ(reduced.symmetry.translation(), cell.symmetry.translation());
  // Every atom is its orbit element applied to its representative.
  for (int a = 0; a < cell.atomCount(); ++a) {
    const Eigen::Vector3d image = reduced.symmetry.apply(r.element[a], reduced.positions.col(r.orbit[a]));
    EXPECT_LT((image - cell.positions.col(a)).norm(), 1e-10) << "atom " << a;
  }
}

TEST(CellReduction, CellDeclaringPartOfItsRotationReducesFurther) {
  // The C_5 sector of (10,10) (N_a = 5, 8 atoms) has the C_10 axis: m = 2.
  const ObjectiveCell sector = buildNanotubeSector(10, 10, kBond, 5);
  const RotationReduction r = findExtraRotation(sector, kDefaultReductionToleranceBohr);
  EXPECT_EQ(r.extraOrder, 2);
  EXPECT_EQ(reducedCell(sector, r).symmetry.rotationOrder(), 10);
  EXPECT_EQ(r.representatives.size(), static_cast<size_t>(sector.atomCount() / 2));
}

TEST(CellReduction, DisplacedAtomBreaksTheSymmetry) {
  ObjectiveCell cell = buildNanotubeTranslational(5, 5, kBond);
  cell.positions(0, 7) += 1e-3;
  EXPECT_EQ(findExtraRotation(cell, kDefaultReductionToleranceBohr).extraOrder, 1);
  // Within a tolerance larger than the displacement it is found again.
  EXPECT_EQ(findExtraRotation(cell, 2e-3).extraOrder, 5);
}

TEST(CellReduction, BadToleranceIsRefusedNamingTheOption) {
  const ObjectiveCell cell = buildNanotubeTranslational(5, 5, kBond);
  for (double tol : {0.0, -1e-5, 0.5, std::nan("")}) {
    SCOPED_TRACE(tol);
    mesochain::testing::expectInputError([&] { findExtraRotation(cell, tol); }, {"--tolerance-bohr"});
  }
}

TEST(CellReduction, SampledAngularNumbersAreRefused) {
  CellInput in = tubeInput(buildNanotubeSector(10, 10, kBond, 5), 4);
  in.band.angular.samples = 3;
  const RotationReduction r = findExtraRotation(in.cell, kDefaultReductionToleranceBohr);
  mesochain::testing::expectInputError([&] { reducedCellInput(in, r); }, {"kpoints.angular"});
  in.band.angular.samples = 5;  // every mu of N_a = 5: exact
  EXPECT_EQ(reducedCellInput(in, r).band.angular.samples, 0);
}

TEST(CellReduction, ReducedCellGivesTheSameEnergyAndForces) {
  // A (5,5) translational cell off equilibrium: radial and axial displacements that vary as
  // cos(5 phi) and sin(5 phi), so C_5 is kept and the forces are not zero.
  ObjectiveCell cell = buildNanotubeTranslational(5, 5, kBond);
  for (int a = 0; a < cell.atomCount(); ++a) {
    const double phi = std::atan2(cell.positions(1, a), cell.positions(0, a));
    const double s = 1.0 + 0.02 * std::cos(5.0 * phi + 0.3);
    cell.positions(0, a) *= s;
    cell.positions(1, a) *= s;
    cell.positions(2, a) += 0.03 * std::sin(5.0 * phi);
  }
  const CellInput in = tubeInput(cell, 6);
  const RotationReduction r = findExtraRotation(cell, kDefaultReductionToleranceBohr);
  ASSERT_EQ(r.extraOrder, 5);
  const CellInput reduced = reducedCellInput(in, r);
  const dftb::Result full = makeCalculator(in).evaluate(in.cell, {true, false});
  const dftb::Result small = makeCalculator(reduced).evaluate(reduced.cell, {true, false});
  const double n = in.cell.atomCount(), nr = reduced.cell.atomCount();
  EXPECT_NEAR(small.totalEnergy / nr, full.totalEnergy / n, 1e-10);
  EXPECT_NEAR(small.freeEnergy / nr, full.freeEnergy / n, 1e-10);
  EXPECT_GT(std::abs(full.totalEnergy - full.freeEnergy) / n, 1e-6);  // the entropy term is there
  const Eigen::Matrix3Xd mapped = mapToOriginalAtoms(reduced.cell, r, small.gradient);
  EXPECT_GT(full.gradient.cwiseAbs().maxCoeff(), 1e-3);  // forces that could disagree
  for (size_t i = 0; i < r.representatives.size(); ++i)
    EXPECT_LT((small.gradient.col(static_cast<Eigen::Index>(i)) - full.gradient.col(r.representatives[i])).norm(), 1e-8);
  for (int a = 0; a < cell.atomCount(); ++a)
    EXPECT_LT((mapped.col(a) - full.gradient.col(a)).norm(), 1e-8) << "atom " << a;
}

}  // namespace
}  // namespace mesochain::objective
