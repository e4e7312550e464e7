// Run under mpirun (tests/CMakeLists.txt: 2 and 3 ranks): every rank computes the same
// evaluation on one rank alone (Communicator::serial) and shared by all ranks (world), and the
// two must agree to 1e-12 Ha (energies), Ha/Bohr (forces), Ha/Bohr and Ha/rad (dF/dT, dF/dgamma):
// a helical tube cell (k-points and angular points over ranks), an SCC helical chain (the
// density sums of every iteration over ranks), a 2-k-point cell on more ranks than k-points, and
// a stretch scan whose two chains go to two groups of ranks. Also: a failure on one rank is the
// same failure on every rank.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/band_solver.hpp"
#include "dftb/calculator.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/drivers/scan.hpp"
#include "parallel/communicator.hpp"
#include "parallel/session.hpp"

using namespace mesochain;
using parallel::Communicator;

namespace {

const double kBond = 1.42 * units::kAngstromInBohr;
constexpr double kTolerance = 1e-12;

std::shared_ptr<const dftb::ParameterSet> carbon() {
  return std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C"}, {{"C-C", std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf"}}, "test"));
}

std::shared_ptr<const dftb::ParameterSet> carbonHydrogen() {
  const std::string dir = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/";
  return std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C", "H"},
      {{"C-C", dir + "C-C.skf"}, {"C-H", dir + "C-H.skf"}, {"H-C", dir + "H-C.skf"},
       {"H-H", dir + "H-H.skf"}},
      "test"));
}

dftb::CalculatorSettings settings(int kpoints) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = kpoints;
  s.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
  return s;
}

// Moves every atom a little (deterministically), so that no force vanishes by symmetry.
objective::ObjectiveCell distorted(objective::ObjectiveCell c) {
  for (int a = 0; a < c.atomCount(); ++a)
    for (int k = 0; k < 3; ++k) c.positions(k, a) += 0.03 * std::sin(1.7 * a + 2.3 * k + 0.4);
  return c;
}

// The evaluation on this rank alone and on all ranks agree.
void expectSameOnAllRanks(std::shared_ptr<const dftb::ParameterSet> params,
                          const dftb::CalculatorSettings& s, const objective::ObjectiveCell& cell) {
  const Communicator world = Communicator::world();
  ASSERT_GE(world.size(), 2) << "run under mpirun with at least 2 ranks";
  const dftb::Calculator one(params, s, Communicator::serial());
  const dftb::Calculator all(params, s, world);
  const dftb::Result a = one.evaluate(cell, {true, true});
  const dftb::Result b = all.evaluate(cell, {true, true});
  EXPECT_NEAR(a.freeEnergy, b.freeEnergy, kTolerance);
  EXPECT_NEAR(a.totalEnergy, b.totalEnergy, kTolerance);
  for (const dftb::LedgerEntry& e : a.energies.entries())
    EXPECT_NEAR(e.value, b.energies.at(e.name), kTolerance) << e.name;
  ASSERT_EQ(a.gradient.cols(), b.gradient.cols());
  EXPECT_LE((a.gradient - b.gradient).cwiseAbs().maxCoeff(), kTolerance);
  EXPECT_NEAR(a.dFdTranslation, b.dFdTranslation, kTolerance);
  EXPECT_NEAR(a.dFdTwist, b.dFdTwist, kTolerance);
  // Not a vacuous comparison: the forces are not zero.
  EXPECT_GT(a.gradient.cwiseAbs().maxCoeff(), 1e-3);
}

}  // namespace

TEST(Distribution, HelicalTubeCellMatchesOneRank) {
  // (5,5) as a 2-atom helical cell: 5 angular x 6 kappa points, shared by the ranks.
  const objective::ObjectiveCell cell = distorted(objective::buildNanotubeHelical(5, 5, kBond));
  const dftb::CalculatorSettings s = settings(6);
  const dftb::BandGeometry geo(cell, *carbon(), s.band.helicalKPoints, s.band.angular);
  // Every rank owns some of the points (the comparison below exercises the distribution).
  const std::vector<int> owner = dftb::kpointOwners(geo.grid, Communicator::world());
  for (int r = 0; r < Communicator::world().size(); ++r)
    EXPECT_GT(std::count(owner.begin(), owner.end(), r), 0) << "rank " << r;
  expectSameOnAllRanks(carbon(), s, cell);
}

TEST(Distribution, MoreRanksThanKPoints) {
  // A (3,3) translational cell with the fewest kappa points that give 2 reduced k-points: with
  // 3 ranks one rank owns no k-point and still takes part in the sums.
  const objective::ObjectiveCell cell =
      distorted(objective::buildNanotubeTranslational(3, 3, kBond, false));
  int nKappa = 2;
  while (dftb::BandGeometry(cell, *carbon(), nKappa, {}).grid.points().size() < 2) ++nKappa;
  const dftb::BandGeometry geo(cell, *carbon(), nKappa, {});
  ASSERT_EQ(geo.grid.points().size(), 2u);
  const std::vector<int> owner = dftb::kpointOwners(geo.grid, Communicator::world());
  EXPECT_NE(owner[0], owner[1]);
  expectSameOnAllRanks(carbon(), settings(nKappa), cell);
}

TEST(Distribution, SccHelicalChainMatchesOneRank) {
  // A helical (CH)_x chain (one CH unit, screw 150 degrees), SCC with 8 kappa points.
  const double a = 1.0 / 0.529177249;
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(1.15 * a, 150.0 * units::kDegree, 1);
  cell.addAtom("C", {0.45 * a, 0.02 * a, 0.0});
  cell.addAtom("H", {1.54 * a, -0.03 * a, 0.04 * a});
  dftb::CalculatorSettings s = settings(8);
  s.scc.enabled = true;
  s.scc.chargeTolerance = 1e-10;
  s.scc.energyTolerance = 1e-10;
  s.scc.maxIterations = 200;
  expectSameOnAllRanks(carbonHydrogen(), s, cell);
}

TEST(Distribution, StretchScanMatchesOneRank) {
  // Two chains (+1 %, -1 %) after the reference: on 2 or more ranks, two groups.
  objective::ScanSettings s;
  s.kind = objective::ScanKind::Stretch;
  s.values = {0.01, -0.01, 0.02};
  s.relax.forceTolerance = 1e-6;
  s.progressBar = false;
  std::vector<int> reported;
  s.pointDone = [&](const objective::ScanPoint&, int index, int) { reported.push_back(index); };
  const objective::ObjectiveCell tube = objective::buildNanotubeHelical(5, 5, kBond);
  const objective::ScanResult one =
      objective::runScan(tube, carbon(), settings(8), s, Communicator::serial());
  const std::vector<int> serialOrder = reported;
  reported.clear();
  const objective::ScanResult all =
      objective::runScan(tube, carbon(), settings(8), s, Communicator::world());
  ASSERT_EQ(one.points.size(), 4u);
  ASSERT_EQ(all.points.size(), one.points.size());
  EXPECT_TRUE(all.complete);
  EXPECT_EQ(all.computed, 4);
  for (std::size_t i = 0; i < one.points.size(); ++i) {
    EXPECT_EQ(all.points[i].deformation, one.points[i].deformation);
    EXPECT_NEAR(all.points[i].energy, one.points[i].energy, kTolerance) << i;
    EXPECT_NEAR(all.points[i].maxForce, one.points[i].maxForce, kTolerance) << i;
    EXPECT_EQ(all.points[i].evaluations, one.points[i].evaluations) << i;
    EXPECT_LE((all.points[i].cell.positions - one.points[i].cell.positions).cwiseAbs().maxCoeff(),
              1e-12);
  }
  // Points reported in the order of the plan, as in the serial scan.
  EXPECT_EQ(reported, serialOrder);
  EXPECT_EQ(serialOrder, (std::vector<int>{0, 1, 2, 3}));
}

TEST(Distribution, FailureOnOneRankReachesEveryRank) {
  const Communicator world = Communicator::world();
  const std::string mine = world.rank() == world.size() - 1 ? "boom on the last rank" : "";
  EXPECT_EQ(world.firstFailure(mine), "boom on the last rank");
  EXPECT_EQ(world.firstFailure(""), "");
}

int main(int argc, char** argv) {
  parallel::Session mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
