// The shared reference of `mesochain chain` (objective/drivers/scan_reference.hpp): relaxed once
// by relaxScanReference (from the settings of a scan of another kind), written and read back, it
// is the reference a scan finds by itself (T0 and energy to the last bit), and a scan started
// from it gives the same curve as one that relaxes its own; a reference of other settings is
// refused, naming the file and the setting.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "carbon_fixture.hpp"
#include "common/errors.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/drivers/relax.hpp"
#include "objective/drivers/scan.hpp"
#include "objective/drivers/scan_reference.hpp"

namespace mesochain::objective {
namespace {

using namespace mesochain::objective::testing;

ScanSettings stretch() {
  ScanSettings s;
  s.kind = ScanKind::Stretch;
  s.values = {0.01, -0.01};
  s.relax.forceTolerance = 1e-5;
  s.relax.axialTolerance = 1e-5;
  s.relax.relaxTranslation = true;
  s.progressBar = false;
  return s;
}

// The (5,5) tube 1 % longer than its T0, so that the T0 search has work to do.
ObjectiveCell stretchedTube() {
  ObjectiveCell tube = buildNanotubeHelical(5, 5, kBond);
  setTranslation(tube, tube.symmetry.translation() * 1.01);
  return tube;
}

TEST(ScanReference, SharedReferenceIsTheOneAScanFindsByItself) {
  const ObjectiveCell tube = stretchedTube();
  const auto params = carbon();
  const auto calc = settings(16);
  const ScanResult own = runScan(tube, params, calc, stretch());

  // Relaxed from the settings of a twist scan: the reference does not depend on the kind.
  ScanSettings twist = stretch();
  twist.kind = ScanKind::Twist;
  twist.values = {0.002};
  ScanReference computed = relaxScanReference(tube, params, calc, twist);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("mesochain-scan-reference-" + std::to_string(::getpid()) + ".json")).string();
  writeScanReference(path, computed);
  const ScanReference ref = readScanReference(path, tube);
  EXPECT_EQ(ref.source, path);
  EXPECT_EQ(ref.identity, referenceIdentity(tube, calc, stretch()));
  EXPECT_NE(ref.point.cell.symmetry.translation(), tube.symmetry.translation());  // T0 was searched
  // The same bits with one thread (ctest); threaded sums may differ in the last bit.
  EXPECT_NEAR(ref.point.cell.symmetry.translation(), own.translation0, 1e-12);
  ASSERT_EQ(own.points[1].deformation, 0.0);
  EXPECT_NEAR(ref.point.energy, own.points[1].energy, 1e-12);
  EXPECT_EQ(ref.point.evaluations, own.points[1].evaluations);

  ScanSettings shared = stretch();
  shared.reference = std::make_shared<const ScanReference>(ref);
  const ScanResult r = runScan(tube, params, calc, shared);
  EXPECT_EQ(r.computed, 2);  // the two strained points: the reference was not relaxed again
  EXPECT_NEAR(r.translation0, own.translation0, 1e-12);
  ASSERT_EQ(r.points.size(), own.points.size());
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    EXPECT_EQ(r.points[k].deformation, own.points[k].deformation);
    EXPECT_NEAR(r.points[k].energy, own.points[k].energy, 1e-12) << k;
  }

  // Another force tolerance: refused, naming the file and the setting.
  ScanSettings other = shared;
  other.relax.forceTolerance = 1e-4;
  try {
    runScan(tube, params, calc, other);
    ADD_FAILURE() << "a reference of another force tolerance was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scan.relax.force_tolerance"), std::string::npos) << e.what();
  }
  // Another cell (its atoms moved): refused too.
  ObjectiveCell moved = tube;
  moved.positions(0, 0) += 1e-3;
  EXPECT_THROW(runScan(moved, params, calc, shared), InputError);
  std::filesystem::remove(path);
}

// The chain's reference keeps its relaxation in its checkpoint as it goes: killed inside the T0
// search, relaxScanReference continues it (the same T0 and energy to the tolerances), returns the
// finished reference from the checkpoint without relaxing again, and replaces a checkpoint of
// other settings.
TEST(ScanReference, AnInterruptedReferenceContinuesFromItsCheckpoint) {
  const ObjectiveCell tube = stretchedTube();
  const auto params = carbon();
  const auto calc = settings(16);
  const ScanReference whole = relaxScanReference(tube, params, calc, stretch());
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("mesochain-reference-ckpt-" + std::to_string(::getpid()) + ".json")).string();
  std::filesystem::remove(path);
  ScanSettings s = stretch();
  s.checkpointPath = path;
  s.snapshotSeconds = 0;
  struct Killed {};
  const int killAt = whole.point.evaluations * 2 / 3;
  ASSERT_GT(killAt, 5);
  ScanSettings killed = s;
  int calls = 0;
  killed.relax.progress = [&](int evaluation, double, double) {
    ++calls;
    if (evaluation >= killAt) throw Killed{};
  };
  EXPECT_THROW(relaxScanReference(tube, params, calc, killed), Killed);
  ASSERT_TRUE(std::filesystem::exists(path));
  ScanSettings counted = s;
  int firstEvaluation = 0;
  counted.relax.progress = [&](int evaluation, double, double) {
    if (calls++ == 0) firstEvaluation = evaluation;
  };
  calls = 0;
  const ScanReference resumed = relaxScanReference(tube, params, calc, counted);
  EXPECT_GT(calls, 0);
  EXPECT_GT(firstEvaluation, 5) << "the reference started afresh instead of from its snapshot";
  EXPECT_TRUE(resumed.point.converged);
  EXPECT_NEAR(resumed.point.cell.symmetry.translation(), whole.point.cell.symmetry.translation(), 1e-4);
  EXPECT_NEAR(resumed.point.energy, whole.point.energy, 1e-8);
  EXPECT_EQ(resumed.identity, whole.identity);
  // Finished: taken from the checkpoint, nothing evaluated.
  calls = 0;
  const ScanReference again = relaxScanReference(tube, params, calc, counted);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(again.point.energy, resumed.point.energy);
  EXPECT_EQ(again.point.cell.positions, resumed.point.cell.positions);
  // Other settings: the checkpoint is replaced, the reference relaxed afresh.
  ScanSettings other = counted;
  other.relax.forceTolerance = 2e-5;
  other.relax.axialTolerance = 2e-5;
  const ScanReference fresh = relaxScanReference(tube, params, calc, other);
  EXPECT_GT(calls, 0);
  EXPECT_TRUE(fresh.point.converged);
  // A file that is no checkpoint (or one of a cell with other atoms): replaced too, not an error.
  std::ofstream(path) << "not a checkpoint\n";
  calls = 0;
  EXPECT_TRUE(relaxScanReference(tube, params, calc, counted).point.converged);
  EXPECT_GT(calls, 0);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mesochain::objective
