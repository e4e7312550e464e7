// Deformation scans: a stretch scan agrees with independent relaxations of each strained cell
// started from the ideal tube; a ring of tiny curvature approaches the straight energy with the
// expected 1/R^2 law; an interrupted scan resumed from its checkpoint gives the same numbers as
// an uninterrupted one; a checkpoint of another input is refused; a finished scan extended by
// new deformations reuses its points, and points dropped from the list stay in the checkpoint.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "carbon_fixture.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/drivers/scan.hpp"
#include "objective/drivers/scan_checkpoint.hpp"
#include "input/scan_output.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
using namespace mesochain::objective::testing;

ScanSettings stretchSettings() {
  ScanSettings s;
  s.kind = ScanKind::Stretch;
  s.values = {0.02, -0.01, 0.01};
  s.relax.forceTolerance = 1e-6;
  s.relax.axialTolerance = 1e-6;
  s.relax.relaxTranslation = true;
  s.progressBar = false;
  return s;
}

// stretchSettings at 1e-5 Ha/Bohr (forces and axial force): the checkpoint tests' scan.
ScanSettings stretchAt1e5() {
  ScanSettings s = stretchSettings();
  s.relax.forceTolerance = 1e-5;
  s.relax.axialTolerance = 1e-5;
  return s;
}

// Rings of a straight cell: 4 angular samples, 1e-4 Ha/Bohr, the cell's T kept.
ScanSettings ringSettings(std::vector<int> rotationOrders) {
  ScanSettings s;
  s.kind = ScanKind::Bend;
  s.rotationOrders = std::move(rotationOrders);
  s.ringAngular.samples = 4;
  s.relax.forceTolerance = 1e-4;
  s.relax.relaxTranslation = false;
  s.progressBar = false;
  return s;
}

std::string tempPath(const std::string& name) {
  const auto dir = mesochain::testing::processTempDir("mesochain-scan-test");
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

// Resumes `s` from a fresh checkpoint NAME in the temporary folder (an old file removed);
// returns the checkpoint's path.
std::string resumeFromFreshCheckpoint(ScanSettings& s, const std::string& name) {
  const std::string path = tempPath(name);
  std::filesystem::remove(path);
  s.checkpointPath = path;
  s.resume = true;
  return path;
}
}  // namespace

TEST(Scan, StretchMatchesIndependentRelaxations) {
  const ObjectiveCell tube = buildNanotubeHelical(5, 5, kBond);
  const auto params = carbon();
  const auto calc = settings(32);
  const ScanResult r = runScan(tube, params, calc, stretchSettings());
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.points.size(), 4u);
  EXPECT_EQ(r.atomsPerCell, 2);
  const double t0 = r.translation0;
  // Points sorted by strain, the reference (strain 0) at dF/dT = 0 and lowest in energy.
  EXPECT_DOUBLE_EQ(r.points[1].deformation, 0.0);
  for (const ScanPoint& p : r.points) {
    EXPECT_TRUE(p.converged);
    EXPECT_LT(p.maxForce, 1e-6);
    EXPECT_EQ(p.helicalKPoints, 32);
    EXPECT_EQ(p.angularPoints, 5);  // (5,5): N_a = 5, all angular quantum numbers
    EXPECT_GT(p.evaluations, 0);
    if (p.deformation != 0.0) {
      EXPECT_GT(p.energy, r.points[1].energy);
    }
    EXPECT_NEAR(p.cell.symmetry.translation(), t0 * (1 + p.deformation), 1e-12);
  }
  // Independent single points: the ideal tube at T0 (1 + eps), relaxed from scratch.
  const dftb::Calculator calculator(params, calc);
  RelaxSettings rs;
  rs.forceTolerance = 1e-6;
  for (const ScanPoint& p : r.points) {
    ObjectiveCell c = tube;
    const double t = t0 * (1 + p.deformation);
    setTranslation(c, t);
    const RelaxOutcome o = relax(calculator, c, rs);
    ASSERT_TRUE(o.converged);
    EXPECT_NEAR(o.result.freeEnergy, p.energy, 1e-9) << "strain " << p.deformation;
  }
  // The curve output carries the agreed keys.
  const auto j = scanCurveJson(r);
  EXPECT_EQ(j["kind"], "stretch");
  EXPECT_EQ(j["deformation_unit"], "strain");
  EXPECT_FALSE(j.contains("direction"));
  EXPECT_EQ(j["points"].size(), 4u);
  // Per slice of length T0: the 2-atom cell with C_5 is a fifth of it.
  EXPECT_EQ(r.cellsPerSlice, 5);
  EXPECT_EQ(j["atoms_per_cell"], 10);
  EXPECT_DOUBLE_EQ(j["points"][3]["energy_hartree"].get<double>(), 5 * r.points[3].energy);
}

TEST(Scan, RingOfTinyCurvatureApproachesTheStraightEnergy) {
  // A semiconducting (8,0) tube in its translational cell (32 atoms). 24 helical k-points for
  // the straight cell and 12 sampled angular quantum numbers of the half zone for the rings:
  // with N_a a multiple of 4 * 12 the ring's Bloch phases 2 pi mu / N_a are exactly the
  // straight cell's kappa grid (objective/core/kgrid.cpp), so the difference is the bending
  // energy alone, which scales as 1/R^2 = 1/N_a^2 (1/2 D T0 / R^2 ~ 1e-2 Ha per cell at
  // R = 135 Å for D = C pi r^3, C = 345 N/m).
  // The reference is relaxed at T0 (dF/dT = 0): a ring may change its radius freely, and a
  // straight cell held away from T0 would relax its axial stress into the ring's radius.
  const ObjectiveCell tube = buildNanotubeTranslational(8, 0, kBond);
  ScanSettings s;
  s.kind = ScanKind::Bend;
  s.rotationOrders = {1920, 192};
  s.ringAngular.samples = 12;
  s.relax.forceTolerance = 2e-5;
  s.relax.axialTolerance = 2e-5;
  s.relax.relaxTranslation = true;
  s.progressBar = false;
  const ScanResult r = runScan(tube, carbon(), settings(24), s);
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.points.size(), 3u);
  const ScanPoint &straight = r.points[0], &gentle = r.points[1], &bent = r.points[2];
  EXPECT_EQ(gentle.rotationOrder, 1920);
  EXPECT_EQ(bent.rotationOrder, 192);
  EXPECT_EQ(bent.helicalKPoints, 1);
  EXPECT_EQ(bent.angularPoints, 12);
  const double t0 = r.translation0;
  EXPECT_NEAR(bent.deformation, 2 * units::kPi / (192 * t0), 1e-15);
  // Measured curvature: with the reference at T0, the centroid line keeps its length, so the
  // atoms' mean radius is the nominal radius (a beam would stretch by I/(2 A R^2) ~ 1e-4).
  EXPECT_NEAR(bent.measuredCurvature / bent.deformation, 1.0, 1e-3);
  EXPECT_NEAR(gentle.measuredCurvature / gentle.deformation, 1.0, 1e-3);
  const double eBent = bent.energy - straight.energy;
  const double eGentle = gentle.energy - straight.energy;
  EXPECT_GT(eBent, 1e-3);
  EXPECT_LT(eBent, 1e-1);
  // 1/R^2 scaling: (192/1920)^2 = 0.01 of the bent ring's energy, give or take relaxation noise.
  EXPECT_NEAR(eGentle / eBent, 0.01, 0.005) << eGentle << " " << eBent;
}

TEST(Scan, ResumedScanEqualsUninterruptedScan) {
  const ObjectiveCell tube = buildNanotubeHelical(5, 5, kBond);
  const auto params = carbon();
  const auto calc = settings(16);
  ScanSettings s = stretchAt1e5();
  const ScanResult full = runScan(tube, params, calc, s);
  const std::string path = resumeFromFreshCheckpoint(s, "resume.json");
  s.stopAfter = 2;
  const ScanResult part = runScan(tube, params, calc, s);
  EXPECT_FALSE(part.complete);
  EXPECT_EQ(part.computed, 2);
  EXPECT_EQ(part.points.size(), 2u);
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp." + std::to_string(::getpid())));
  s.stopAfter = -1;
  const ScanResult rest = runScan(tube, params, calc, s);
  EXPECT_TRUE(rest.complete);
  EXPECT_EQ(rest.computed, 2);  // the two remaining points only
  ASSERT_EQ(rest.points.size(), full.points.size());
  // Equal to the last bits with one thread (ctest); threaded sums may differ in the last bit.
  EXPECT_NEAR(rest.translation0, full.translation0, 1e-12);
  for (std::size_t k = 0; k < full.points.size(); ++k) {
    EXPECT_EQ(rest.points[k].deformation, full.points[k].deformation);
    EXPECT_NEAR(rest.points[k].energy, full.points[k].energy, 1e-12);
    EXPECT_EQ(rest.points[k].evaluations, full.points[k].evaluations);
    // The ledger of every point, restored from the checkpoint or not, adds up to its energy.
    const auto& e = rest.points[k].energies;
    ASSERT_EQ(e.size(), full.points[k].energies.size()) << k;
    EXPECT_NEAR(e.at("band") + e.at("repulsive") - e.at("entropy_term_ts"), rest.points[k].energy,
                1e-12) << k;
  }
  // A checkpoint of an earlier version (a hash of a hand-kept list of settings that left out
  // the SCC settings and the dispersion summation, no settings recorded) is refused, saying so.
  std::string saved;
  {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    saved = text.str();
  }
  for (const std::string& legacyHash : legacyScanInputHashes(tube, calc, s)) {
    {
      std::ifstream in(path);
      nlohmann::json j = nlohmann::json::parse(in);
      j["input_hash"] = legacyHash;
      j.erase("settings");
      std::ofstream(path) << j.dump(1);
    }
    try {
      runScan(tube, params, calc, s);
      FAIL() << "a checkpoint of an earlier version was resumed";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("did not record the [scc] settings"),
                std::string::npos) << e.what();
    }
  }
  // The checkpoint of this version, resumed with the same settings: nothing to compute.
  std::ofstream(path) << saved;
  const ScanResult same = runScan(tube, params, calc, s);
  EXPECT_EQ(same.computed, 0);
  EXPECT_EQ(same.reused, 4);
  // Another SCC mixing (which the earlier identity left out) is refused, naming the setting.
  {
    dftb::CalculatorSettings scc = calc;
    scc.scc.mixing = 0.3;
    try {
      runScan(tube, params, scc, s);
      FAIL() << "a checkpoint of another SCC mixing was resumed";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("calculator.scc.mixing (checkpoint 0.2"),
                std::string::npos) << e.what();
    }
  }
  // A changed setting (another force tolerance) refuses the checkpoint, naming it.
  s.relax.forceTolerance = 2e-5;
  try {
    runScan(tube, params, calc, s);
    FAIL() << "a checkpoint of another input was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("resume.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("another scan input"), std::string::npos) << e.what();
  }
  // So does a different k-point setting.
  s.relax.forceTolerance = 1e-5;
  EXPECT_THROW(runScan(tube, params, settings(20), s), InputError);
}

namespace {
const ScanPoint* pointAt(const ScanResult& r, double deformation) {
  for (const ScanPoint& p : r.points)
    if (p.deformation == deformation) return &p;
  return nullptr;
}
}  // namespace

// A scan killed inside a point's relaxation keeps that point in its checkpoint (written every
// snapshotSeconds of the relaxation; here after every step) and a resumed scan continues it from
// there: the points come out at the same energies (the resumed point takes other L-BFGS steps to
// the same tolerance), the point in progress disappears from the checkpoint once finished, and a
// point in progress that is no longer in the list is dropped.
TEST(Scan, ResumesThePointInProgress) {
  const ObjectiveCell tube = buildNanotubeHelical(5, 5, kBond);
  const auto params = carbon();
  const auto calc = settings(16);
  ScanSettings s = stretchAt1e5();
  const ScanResult full = runScan(tube, params, calc, s);
  const std::string path = resumeFromFreshCheckpoint(s, "in-progress.json");
  s.snapshotSeconds = 0;
  struct Killed {};
  int finished = 0, evaluationsAtKill = 0;
  ScanSettings killed = s;
  killed.pointDone = [&](const ScanPoint&, int, int) { ++finished; };
  killed.relax.progress = [&](int evaluation, double, double) {
    // Inside the second point of the plan (strain +0.01), after a few accepted steps.
    if (finished == 1 && evaluation >= 4) {
      evaluationsAtKill = evaluation;
      throw Killed{};
    }
  };
  EXPECT_THROW(runScan(tube, params, calc, killed), Killed);
  ASSERT_EQ(finished, 1);
  {
    std::ifstream in(path);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_TRUE(j.contains("in_progress"));
    EXPECT_EQ(j["in_progress"]["index"], 1);
    EXPECT_EQ(j["in_progress"]["deformation"], 0.01);
    EXPECT_GT(j["in_progress"]["evaluations"].get<int>(), 1);
    EXPECT_LT(j["in_progress"]["evaluations"].get<int>(), evaluationsAtKill);
    EXPECT_EQ(j["completed"].size(), 1u);
  }
  int firstEvaluation = 0;  // the count the resumed point reports first: after the snapshot's
  ScanSettings resuming = s;
  finished = 0;
  resuming.pointDone = [&](const ScanPoint&, int, int) { ++finished; };
  resuming.relax.progress = [&](int evaluation, double, double) {
    if (finished == 1 && firstEvaluation == 0) firstEvaluation = evaluation;
  };
  const ScanResult rest = runScan(tube, params, calc, resuming);
  EXPECT_GT(firstEvaluation, 2) << "point +0.01 started afresh instead of from its snapshot";
  EXPECT_LE(firstEvaluation, evaluationsAtKill);  // the step after the snapshot is taken again
  ASSERT_TRUE(rest.complete);
  EXPECT_EQ(rest.computed, 3);
  ASSERT_EQ(rest.points.size(), full.points.size());
  for (std::size_t k = 0; k < full.points.size(); ++k) {
    EXPECT_EQ(rest.points[k].deformation, full.points[k].deformation);
    EXPECT_TRUE(rest.points[k].converged);
    // To the force tolerance: E error ~ |F|^2 / k, far below 1e-8 Ha for |F| < 1e-5 Ha/Bohr.
    EXPECT_NEAR(rest.points[k].energy, full.points[k].energy, 1e-8) << k;
  }
  {
    std::ifstream in(path);
    EXPECT_FALSE(nlohmann::json::parse(in).contains("in_progress"));
  }
  // Killed again inside +0.01 of a fresh run; resumed with that strain no longer listed: the point
  // in progress is dropped and the others are computed as usual.
  std::filesystem::remove(path);
  finished = 0;
  EXPECT_THROW(runScan(tube, params, calc, killed), Killed);
  ScanSettings shorter = s;
  shorter.values = {0.02, -0.01};
  const ScanResult without = runScan(tube, params, calc, shorter);
  ASSERT_TRUE(without.complete);
  EXPECT_EQ(without.points.size(), 3u);
  EXPECT_EQ(pointAt(without, 0.01), nullptr);
}

TEST(Scan, ExtendedScanReusesItsCheckpointedPoints) {
  const ObjectiveCell tube = buildNanotubeHelical(5, 5, kBond);
  const auto params = carbon();
  const auto calc = settings(16);
  ScanSettings s = stretchAt1e5();
  s.values = {0.01, -0.01};
  const std::string path = resumeFromFreshCheckpoint(s, "extend.json");
  const ScanResult first = runScan(tube, params, calc, s);
  ASSERT_TRUE(first.complete);
  ASSERT_EQ(first.points.size(), 3u);
  EXPECT_EQ(first.computed, 3);
  EXPECT_EQ(first.reused, 0);

  // (a) A point between the reference and +1 %: only it is computed, the others are restored.
  s.values = {0.01, 0.005, -0.01};
  const ScanResult extended = runScan(tube, params, calc, s);
  ASSERT_TRUE(extended.complete);
  EXPECT_EQ(extended.computed, 1);
  EXPECT_EQ(extended.reused, 3);
  EXPECT_EQ(extended.keptAside, 0);
  ASSERT_EQ(extended.points.size(), 4u);
  EXPECT_EQ(extended.translation0, first.translation0);
  for (const ScanPoint& p : first.points) {
    const ScanPoint* q = pointAt(extended, p.deformation);
    ASSERT_NE(q, nullptr) << p.deformation;
    EXPECT_EQ(q->energy, p.energy) << p.deformation;
    EXPECT_EQ(q->evaluations, p.evaluations) << p.deformation;
  }
  const ScanPoint* half = pointAt(extended, 0.005);
  ASSERT_NE(half, nullptr);
  EXPECT_TRUE(half->converged);
  EXPECT_NEAR(half->cell.symmetry.translation(), first.translation0 * 1.005, 1e-12);
  EXPECT_GT(half->energy, pointAt(first, 0.0)->energy);
  EXPECT_LT(half->energy, pointAt(first, 0.01)->energy);

  // (b) Dropping -1 %: nothing is computed, the curve lacks it, the checkpoint keeps it.
  s.values = {0.01, 0.005};
  const ScanResult trimmed = runScan(tube, params, calc, s);
  EXPECT_TRUE(trimmed.complete);
  EXPECT_EQ(trimmed.computed, 0);
  EXPECT_EQ(trimmed.reused, 3);
  EXPECT_EQ(trimmed.keptAside, 1);
  EXPECT_EQ(trimmed.points.size(), 3u);
  EXPECT_EQ(pointAt(trimmed, -0.01), nullptr);
  const ScanCheckpoint kept = readScanCheckpoint(path, tube);
  EXPECT_EQ(kept.completed.size(), 3u);
  ASSERT_EQ(kept.keptAside.size(), 1u);
  EXPECT_EQ(kept.keptAside[0].deformation, -0.01);
  EXPECT_EQ(kept.keptAside[0].energy, pointAt(first, -0.01)->energy);
  // Listed again, it comes back from the kept-aside points without a computation.
  s.values = {0.01, 0.005, -0.01};
  const ScanResult again = runScan(tube, params, calc, s);
  EXPECT_EQ(again.computed, 0);
  EXPECT_EQ(again.keptAside, 0);
  ASSERT_EQ(again.points.size(), 4u);
  EXPECT_EQ(pointAt(again, -0.01)->energy, pointAt(first, -0.01)->energy);

  // (c) A changed setting still refuses the checkpoint.
  s.relax.forceTolerance = 2e-5;
  try {
    runScan(tube, params, calc, s);
    FAIL() << "a checkpoint with another force tolerance was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another scan input"), std::string::npos) << e.what();
  }
}

TEST(Scan, ExtendedBendScanReusesItsRing) {
  // (d) Rings of N_a = 400, then 800 and 400: the 400 ring is restored, the gentler 800 ring
  // (from the straight reference, the planner's neighbour) is computed and lies in between.
  const ObjectiveCell tube = buildNanotubeTranslational(5, 5, kBond);
  ScanSettings s = ringSettings({400});
  const std::string path = resumeFromFreshCheckpoint(s, "extend-bend.json");
  const auto params = carbon();
  const ScanResult first = runScan(tube, params, settings(8), s);
  ASSERT_TRUE(first.complete);
  ASSERT_EQ(first.points.size(), 2u);
  s.rotationOrders = {800, 400};
  const ScanResult extended = runScan(tube, params, settings(8), s);
  ASSERT_TRUE(extended.complete);
  EXPECT_EQ(extended.computed, 1);
  EXPECT_EQ(extended.reused, 2);
  ASSERT_EQ(extended.points.size(), 3u);  // by curvature: straight, 800, 400
  EXPECT_EQ(extended.points[1].rotationOrder, 800);
  EXPECT_EQ(extended.points[2].rotationOrder, 400);
  EXPECT_EQ(extended.points[0].energy, first.points[0].energy);
  EXPECT_EQ(extended.points[2].energy, first.points[1].energy);
  EXPECT_EQ(extended.points[2].evaluations, first.points[1].evaluations);
  EXPECT_GT(extended.points[1].energy, extended.points[0].energy);
  EXPECT_LT(extended.points[1].energy, extended.points[2].energy);
  // The bending energy follows 1/R^2: the reused ring and the new one agree on the law.
  const double e800 = extended.points[1].energy - extended.points[0].energy;
  const double e400 = extended.points[2].energy - extended.points[0].energy;
  EXPECT_NEAR(e400 / e800, 4.0, 0.2) << e400 << " " << e800;
}

TEST(Scan, BadListsAreInputErrors) {
  const ObjectiveCell tube = buildNanotubeHelical(5, 5, kBond);
  ScanSettings s = stretchSettings();
  s.values = {0.01, 0.01};
  EXPECT_THROW(runScan(tube, carbon(), settings(8), s), InputError);
  s.values = {-1.5};
  EXPECT_THROW(runScan(tube, carbon(), settings(8), s), InputError);
  s.values = {};
  EXPECT_THROW(runScan(tube, carbon(), settings(8), s), InputError);
  // Bending needs a translational cell (twist 0, N_a = 1).
  s.kind = ScanKind::Bend;
  s.rotationOrders = {100};
  EXPECT_THROW(runScan(tube, carbon(), settings(8), s), InputError);
}

TEST(Scan, TwistOfAnAchiralTubeIsEvenInTheTwist) {
  // A zigzag tube is mirror-symmetric: twisting by +dgamma and -dgamma gives mirror images of
  // one structure, so the relaxed energies agree; both lie above the untwisted reference.
  // 128 kappa points: with 32 the two differ by 3e-3 relative (a twist moves the helical grid
  // against the bands, differently for +-dgamma at finite sampling); with 128, below 1e-5.
  ScanSettings s;
  s.kind = ScanKind::Twist;
  s.values = {0.5 * units::kDegree, -0.5 * units::kDegree};
  s.relax.forceTolerance = 1e-6;
  s.relax.axialTolerance = 1e-6;
  s.relax.relaxTranslation = true;
  s.progressBar = false;
  const ScanResult r = runScan(buildNanotubeHelical(10, 0, kBond), carbon(), settings(128), s);
  ASSERT_EQ(r.points.size(), 3u);
  const double ePlus = r.points[2].energy - r.points[1].energy;
  const double eMinus = r.points[0].energy - r.points[1].energy;
  EXPECT_GT(ePlus, 0.0);
  EXPECT_NEAR(eMinus / ePlus, 1.0, 1e-5);
  EXPECT_NEAR(r.points[2].cell.symmetry.twist() - r.twist0, 0.5 * units::kDegree, 1e-14);
  EXPECT_EQ(scanCurveJson(r)["deformation_unit"], "rad_per_cell");
}

TEST(Scan, SoftAndHardRingsOfARoundTubeAgree) {
  // The (8,0) cross-section is invariant under a quarter turn (C_8), so bending it about
  // perpendicular axes gives the same ring.
  const ObjectiveCell tube = buildNanotubeTranslational(8, 0, kBond);
  ScanSettings s = ringSettings({64});
  const ScanResult soft = runScan(tube, carbon(), settings(8), s);
  s.direction = BendDirection::Hard;
  const ScanResult hard = runScan(tube, carbon(), settings(8), s);
  ASSERT_EQ(soft.points.size(), 2u);
  ASSERT_EQ(hard.points.size(), 2u);
  EXPECT_GT(soft.points[1].energy - soft.points[0].energy, 1e-3);
  EXPECT_NEAR(soft.points[1].energy, hard.points[1].energy, 1e-6);
  EXPECT_EQ(scanCurveJson(hard)["direction"], "hard");
}

TEST(Scan, GrapheneSectorsRebendWithTheInverseSquareLaw) {
  // A graphene monolayer bent about z (armchair along the arc), one rectangular cell per
  // sector: the scan rebends the N_a = 80 sector to 40 and 160 sectors. Differences between
  // rings cancel the unknown flat energy: (E40 - E160) / (E80 - E160) = (4^2 - 1) / (2^2 - 1) = 5
  // for U = 1/2 D / R^2.
  const ObjectiveCell sector = buildGrapheneRingSector(1, Direction::Armchair, 80, 1, 0.0, kBond);
  ScanSettings s;
  s.kind = ScanKind::Bend;
  s.rotationOrders = {40, 160};
  s.relax.forceTolerance = 1e-5;
  s.progressBar = false;
  const ScanResult r = runScan(sector, carbon(), settings(32), s);
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.points.size(), 3u);  // sorted by curvature: 160, 80, 40
  EXPECT_EQ(r.points[0].rotationOrder, 160);
  EXPECT_EQ(r.points[1].rotationOrder, 80);
  EXPECT_EQ(r.points[2].rotationOrder, 40);
  EXPECT_EQ(r.cellsPerSlice, 1);
  EXPECT_NEAR(r.translation0, 3 * kBond, 1e-9);  // the arc per cell: one armchair period
  // The ring radius is free: the sheet relaxes its lattice constant along the arc (built with
  // 1.42 Å bonds; DFTB's is ~0.7 % longer), the same fraction at every radius, so measured
  // and nominal curvature differ by one common factor.
  const double factor = r.points[0].measuredCurvature / r.points[0].deformation;
  EXPECT_LT(factor, 1.0);
  EXPECT_GT(factor, 0.98);
  for (const ScanPoint& p : r.points) {
    EXPECT_TRUE(p.converged);
    EXPECT_NEAR(p.deformation, 2 * units::kPi / (p.rotationOrder * 3 * kBond), 1e-12);
    EXPECT_NEAR(p.measuredCurvature / p.deformation, factor, 2e-4);
    EXPECT_EQ(p.cell.symmetry.rotationOrder(), p.rotationOrder);
  }
  const double ratio =
      (r.points[2].energy - r.points[0].energy) / (r.points[1].energy - r.points[0].energy);
  EXPECT_NEAR(ratio, 5.0, 0.1) << ratio;
}
