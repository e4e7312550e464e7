// Geometry made by a driver passes the check of a read geometry: a relaxation refuses a
// starting cell (or a step) with collapsed atoms, a scan names the point, a checkpoint with
// coincident atoms names the file and point, and builders refuse cells too large to allocate.
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "carbon_fixture.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "input/xyz_file.hpp"
#include "objective/drivers/relax.hpp"
#include "objective/drivers/scan.hpp"
#include "objective/drivers/scan_checkpoint.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
using namespace mesochain::objective::testing;

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}
}  // namespace

TEST(DriverGeometry, RelaxationRefusesCollapsedAtoms) {
  ObjectiveCell cell = buildNanotubeHelical(5, 5, kBond);
  cell.positions.col(1) = cell.positions.col(0);  // coincident atoms
  const dftb::Calculator calc(carbon(), settings(4));
  const std::string m = messageOf([&] { relax(calc, cell, RelaxSettings{}); });
  EXPECT_NE(m.find("the starting geometry of the relaxation"), std::string::npos) << m;
  EXPECT_NE(m.find("atom 1 and atom 2"), std::string::npos) << m;
}

// A strain of -0.9 is accepted by the list check (> -1) but collapses the tube's images to
// 0.12 Å: the point is an error naming it, after the reference has been computed.
TEST(DriverGeometry, ScanPointThatCollapsesImagesIsNamed) {
  const ObjectiveCell cell = buildNanotubeHelical(5, 5, kBond);
  ScanSettings s;
  s.values = {-0.9};
  s.relax.forceTolerance = 1e-2;
  s.relax.maxSteps = 5;
  s.progressBar = false;
  const std::string m = messageOf([&] { runScan(cell, carbon(), settings(4), s); });
  EXPECT_NE(m.find("scan point 2 of 2 (stretch -0.9 strain)"), std::string::npos) << m;
  EXPECT_NE(m.find("own image"), std::string::npos) << m;
}

TEST(DriverGeometry, CheckpointWithCoincidentAtomsNamesFileAndPoint) {
  const ObjectiveCell cell = buildNanotubeHelical(5, 5, kBond);
  ScanCheckpoint c;
  c.inputHash = "0";
  ScanPoint p;
  p.cell = cell;
  p.cell.positions.col(1) = p.cell.positions.col(0);
  c.completed[3] = p;
  const std::string path =
      (std::filesystem::temp_directory_path() / "driver-geometry-checkpoint.json").string();
  writeScanCheckpoint(path, c, cell);
  const std::string m = messageOf([&] { readScanCheckpoint(path, cell); });
  EXPECT_NE(m.find(path + ", completed point with index 3"), std::string::npos) << m;
  EXPECT_NE(m.find("Å"), std::string::npos) << m;
  std::filesystem::remove(path);
}

TEST(DriverGeometry, OversizedBuildsAreRefusedWithTheEstimate) {
  const std::string tube =
      messageOf([] { buildNanotubeTranslational(10000, 9999, kBond, false); });
  EXPECT_NE(tube.find("atoms"), std::string::npos) << tube;
  EXPECT_NE(tube.find("at most 100000 atoms"), std::string::npos) << tube;
  const std::string ring = messageOf(
      [] { buildGrapheneRingSector(1000, ChiralIndices{9000, 1}, 12, 1, 6.3, kBond); });
  EXPECT_NE(ring.find("at most 100000 atoms"), std::string::npos) << ring;
  const ObjectiveCell cell = buildNanotubeHelical(5, 5, kBond);
  EXPECT_EQ(unrolledAtomCount(cell, 0, 9), 100);  // 10 steps x 5 rotations x 2 atoms
  const std::string unrolled = messageOf([&] { unroll(cell, 0, 100000000); });
  EXPECT_NE(unrolled.find("at most 10000000 unrolled atoms"), std::string::npos) << unrolled;
}

// 50000 carbon atoms: 200000 orbitals, at least 1.9 TB for the band matrices of one k-point;
// refused with the estimate before anything is allocated (a bare std::bad_alloc otherwise).
TEST(DriverGeometry, CalculatorRefusesACellBeyondTheMachinesMemory) {
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(1000.0, 0.0, 1);
  for (int a = 0; a < 50000; ++a) cell.addAtom("C", {3.0 * (a % 200), 3.0 * (a / 200), 0.0});
  const dftb::Calculator calc(carbon(), settings(1));
  const std::string m = messageOf([&] { calc.evaluate(cell, {false, false}); });
  EXPECT_NE(m.find("50000 atoms with 200000 orbitals"), std::string::npos) << m;
  EXPECT_NE(m.find("GB of this machine"), std::string::npos) << m;
}

// A non-finite energy never leaves the calculator as a result (it would be written as null with
// exit 0): a dispersion strength of 1e308 Ha (finite, accepted by the term) overflows the pair
// sum to inf, a NumericalError naming the term.
TEST(DriverGeometry, NonFiniteEnergyIsANumericalError) {
  dftb::CalculatorSettings s = settings(4);
  s.dispersion.enabled = true;
  s.dispersion.epsilon = 1e308;
  s.dispersion.r0 = 3.8 * units::kAngstromInBohr;
  s.dispersion.cutoff = 10.0 * units::kAngstromInBohr;
  const dftb::Calculator calc(carbon(), s);
  try {
    calc.evaluate(buildNanotubeHelical(5, 5, kBond), {false, false});
    FAIL() << "a non-finite energy was returned";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite dispersion energy"), std::string::npos)
        << e.what();
  }
}
