// The scan file: units are converted (degrees -> rad), paths are relative to the scan file,
// and bad input is an InputError naming the file and the key. Also the progress bar's text.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"

#include "common/errors.hpp"
#include "common/progress_bar.hpp"
#include "common/units.hpp"
#include "input/scan_file.hpp"
#include "tests/support/expect_input_error.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {
const std::string kDir = mesochain::testing::processTempDir("mesochain-scan-file").string();

std::string write(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(kDir);
  const std::string p = kDir + "/" + name;
  std::ofstream(p) << text;
  return p;
}

void writeCells() {
  write("helical.toml",
        "format = 1\n[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\n"
        "[kpoints]\nhelical = 8\n[electrons]\ntemperature = 300\n[parameters]\nset = \"pbc-0-3\"\n");
  write("straight.toml",
        "format = 1\n[builder]\ntype = \"nanotube\"\nn = 6\nm = 0\ncell = \"translational\"\n"
        "[kpoints]\nhelical = 8\n[electrons]\ntemperature = 300\n[parameters]\nset = \"pbc-0-3\"\n");
}

// Expects an InputError whose message names the scan file and contains `key`.
void expectError(const std::string& text, const std::string& key) {
  const std::string p = write("bad.toml", text);
  try {
    readScanFile(p);
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(ScanFile, ReadsTwistAndBendWithUnits) {
  writeCells();
  const ScanInput t = readScanFile(write(
      "twist.toml",
      "format = 1\ncell = \"helical.toml\"\nkind = \"twist\"\ntwist_deg_per_cell = [0.5, -1]\n"
      "[relax]\nforce_tolerance = 2e-5\nrelax_translation = false\n"
      "[output]\njson = \"out/t.json\"\ncheckpoint = \"t.ckpt\"\n"));
  EXPECT_EQ(t.settings.kind, ScanKind::Twist);
  ASSERT_EQ(t.settings.values.size(), 2u);
  EXPECT_DOUBLE_EQ(t.settings.values[0], 0.5 * units::kDegree);
  EXPECT_DOUBLE_EQ(t.settings.values[1], -units::kDegree);
  EXPECT_DOUBLE_EQ(t.settings.relax.forceTolerance, 2e-5);
  EXPECT_FALSE(t.settings.relax.relaxTranslation);
  // Outputs go to the working folder (or -o), not beside the scan file.
  EXPECT_EQ(t.jsonPath, "out/t.json");
  EXPECT_EQ(t.settings.checkpointPath, "t.ckpt");
  EXPECT_EQ(t.settings.snapshotSeconds, 600.0);  // the default: every 10 minutes inside a point
  const ScanInput often = readScanFile(write(
      "often.toml", "format = 1\ncell = \"helical.toml\"\nkind = \"twist\"\ntwist_deg_per_cell = [0.5]\n"
                    "[output]\njson = \"t.json\"\ncheckpoint = \"t.ckpt\"\ncheckpoint_minutes = 2.5\n"));
  EXPECT_EQ(often.settings.snapshotSeconds, 150.0);
  const ScanInput inFolder = readScanFile(kDir + "/twist.toml", "runs/a");
  EXPECT_EQ(inFolder.jsonPath, "runs/a/out/t.json");
  EXPECT_EQ(inFolder.settings.checkpointPath, "runs/a/t.ckpt");
  EXPECT_EQ(t.cell.cell.atomCount(), 2);
  const ScanInput b = readScanFile(write(
      "bend.toml",
      "format = 1\ncell = \"straight.toml\"\nkind = \"bend\"\nrotation_orders = [400, 200]\n"
      "direction = \"hard\"\nring_angular = 8\n[dimensions]\nmeasure = true\ninterlayer = 3.35\n"
      "[output]\njson = \"b.json\"\ncsv = \"b.csv\"\n"));
  EXPECT_EQ(b.settings.kind, ScanKind::Bend);
  EXPECT_EQ(b.settings.direction, BendDirection::Hard);
  EXPECT_EQ(b.settings.rotationOrders, (std::vector<int>{400, 200}));
  EXPECT_EQ(b.settings.ringAngular.samples, 8);
  EXPECT_TRUE(b.settings.relax.relaxTranslation);  // the default
  EXPECT_NEAR(b.settings.dimensionsInterlayer, 3.35 * units::kAngstromInBohr, 1e-12);
  EXPECT_TRUE(b.settings.checkpointPath.empty());
}

// The input hash of a checkpoint knows the parameter tables by content: the same table at
// another path (a moved project, another build tree) keeps the identity, another table does not.
TEST(ScanFile, TableIdentityIsTheContentNotThePath) {
  const std::string skf = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf";
  std::filesystem::create_directories(kDir + "/a");
  std::filesystem::create_directories(kDir + "/b");
  std::filesystem::copy_file(skf, kDir + "/a/C-C.skf",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(skf, kDir + "/b/C-C.skf",
                             std::filesystem::copy_options::overwrite_existing);
  const auto identity = [&](const std::string& sub) {
    write(sub + "/cell.toml",
          "format = 1\n[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\n"
          "[kpoints]\nhelical = 8\n[electrons]\ntemperature = 300\n[parameters]\n"
          "\"C-C\" = \"C-C.skf\"\n");
    const std::string scan = write(sub + "/scan.toml",
                                   "format = 1\ncell = \"cell.toml\"\nkind = \"stretch\"\n"
                                   "strains = [0.01]\n[output]\njson = \"s.json\"\n");
    return readScanFile(scan).settings.identity;
  };
  const std::string a = identity("a");
  EXPECT_EQ(a, identity("b"));
  std::ofstream(kDir + "/b/C-C.skf", std::ios::app) << "\n";  // one byte more
  EXPECT_NE(a, identity("b"));
}

// The tables' angular momenta change the basis, hence every point: part of the identity.
TEST(ScanFile, MaxAngularMomentumIsPartOfTheIdentity) {
  std::filesystem::create_directories(kDir + "/lmax");
  const auto identity = [&](const std::string& parameters) {
    write("lmax/cell.toml",
          "format = 1\n[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\n"
          "[kpoints]\nhelical = 8\n[electrons]\ntemperature = 300\n[parameters]\n"
          "set = \"pbc-0-3\"\n" + parameters);
    const std::string scan = write("lmax/scan.toml",
                                   "format = 1\ncell = \"cell.toml\"\nkind = \"stretch\"\n"
                                   "strains = [0.01]\n[output]\njson = \"s.json\"\n");
    return readScanFile(scan).settings.identity;
  };
  EXPECT_NE(identity(""), identity("max_angular_momentum = { C = \"s\" }\n"));
}

TEST(ScanFile, BadInputNamesFileAndKey) {
  writeCells();
  const std::string head = "format = 1\ncell = \"helical.toml\"\n";
  const std::string out = "[output]\njson = \"x.json\"\n";
  expectError(head + "kind = \"squeeze\"\nstrains = [0.1]\n" + out, "kind");
  expectError(head + "kind = \"stretch\"\n" + out, "strains");
  expectError(head + "kind = \"stretch\"\nstrains = [0.1, \"a\"]\n" + out, "strains");
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\ntwist_deg_per_cell = [1]\n" + out,
              "twist_deg_per_cell");
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\ndirection = \"soft\"\n" + out,
              "direction");
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\n", "output");
  expectError("format = 1\ncell = \"nope.toml\"\nkind = \"stretch\"\nstrains = [0.1]\n" + out,
              "cell");
  // Bending needs a straight translational cell; the helical (5,5) cell has a twist.
  expectError(head + "kind = \"bend\"\nrotation_orders = [100]\n" + out, "cell");
  const std::string straight = "format = 1\ncell = \"straight.toml\"\nkind = \"bend\"\n";
  expectError(straight + "rotation_orders = [1]\n" + out, "rotation_orders");
  expectError(straight + "rotation_orders = [100]\ndirection = \"sideways\"\n" + out,
              "direction");
  expectError(straight + "rotation_orders = [100]\nring_angular = 0\n" + out, "ring_angular");
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\n[relax]\nforce_tolerance = -1\n" + out,
              "force_tolerance");
  // Minutes between checkpoints inside a point: not negative, and only with a checkpoint.
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\n" + out + "checkpoint = \"c.json\"\ncheckpoint_minutes = -1\n",
              "checkpoint_minutes");
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\n" + out + "checkpoint_minutes = 5\n",
              "checkpoint_minutes");
  // A shared reference (docs/scan-file.md): a missing file names the key; a file that is no
  // reference names that file.
  expectError(head + "kind = \"stretch\"\nstrains = [0.1]\nreference = \"nope.json\"\n" + out, "reference");
  write("notref.json", "{\"format\": 1}\n");
  try {
    readScanFile(write("bad.toml", head + "kind = \"stretch\"\nstrains = [0.1]\nreference = \"notref.json\"\n" + out));
    FAIL() << "a file that is no reference was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("notref.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scan reference"), std::string::npos) << e.what();
  }
}

// The lists and words of a scan file, read by common/toml_table: each message names the key
// and its line, what was found and what was expected.
TEST(ScanFile, BadListsAndWordsSayWhatWasFound) {
  writeCells();
  const std::string head = "format = 1\ncell = \"helical.toml\"\n";
  const std::string straight = "format = 1\ncell = \"straight.toml\"\nkind = \"bend\"\n";
  const std::string out = "[output]\njson = \"x.json\"\n";
  const auto refused = [&](const std::string& text, std::initializer_list<const char*> fragments) {
    mesochain::testing::expectInputError([&] { readScanFile(write("bad.toml", text)); }, fragments);
  };
  refused(head + "kind = \"squeeze\"\nstrains = [0.1]\n" + out,
          {"bad.toml", "key kind (line 3)", "a string (\"squeeze\")", "\"stretch\", \"twist\" or \"bend\""});
  refused(head + "kind = \"stretch\"\nstrains = []\n" + out,
          {"key strains (line 4)", "an empty array", "a non-empty array of strains"});
  refused(head + "kind = \"stretch\"\nstrains = [0.1, inf]\n" + out, {"key strains (line 4)", "non-finite"});
  refused(head + "kind = \"twist\"\ntwist_deg_per_cell = 1\n" + out,
          {"key twist_deg_per_cell (line 4)", "an integer (1)", "twist angles"});
  refused(straight + "rotation_orders = [100, 1]\n" + out,
          {"key rotation_orders (line 4)", "an array holding 1", "integers from 2 to 100000000"});
  refused(straight + "rotation_orders = [100, 2.5]\n" + out,
          {"key rotation_orders (line 4)", "an array holding a float (2.5)", "ring rotation orders"});
  refused(straight + "rotation_orders = []\n" + out, {"key rotation_orders (line 4)", "an empty array"});
  refused(straight + "rotation_orders = [100]\ndirection = \"sideways\"\n" + out,
          {"key direction (line 5)", "a string (\"sideways\")", "\"soft\" or \"hard\""});
}

TEST(ProgressBar, RendersCountsTimesAndNote) {
  EXPECT_EQ(ProgressBar::formatDuration(0), "0:00");
  EXPECT_EQ(ProgressBar::formatDuration(75.4), "1:15");
  EXPECT_EQ(ProgressBar::formatDuration(3725), "1:02:05");
  EXPECT_EQ(ProgressBar::formatDuration(-1), "--:--");
  EXPECT_EQ(ProgressBar::render("scan", 2, 8, 30, 90, "point 3", 8),
            "scan [##......] 2/8  elapsed 0:30  ETA 1:30  point 3");
  EXPECT_EQ(ProgressBar::render("x", 8, 8, 5, 0, "", 4), "x [####] 8/8  elapsed 0:05  ETA 0:00");
}

TEST(ProgressBar, SilentUnderCi) {
  setenv("CI", "true", 1);
  EXPECT_FALSE(progressOutputEnabled());
  ProgressBar bar("quiet", 3);
  EXPECT_FALSE(bar.enabled());
  unsetenv("CI");
}
