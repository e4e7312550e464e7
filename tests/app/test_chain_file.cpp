// The chain file of `mesochain chain` (app/chain_file.hpp, docs/chain.md) read into its
// ChainFile: both examples and the files of tests/cli/test_cli_chain.cpp, every field checked,
// and the scan files generated from a stage read back; bad files are InputErrors naming the file,
// the key and its line, what was found and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <toml.hpp>

#include "app/chain_file.hpp"
#include "tests/support/expect_input_error.hpp"

namespace mesochain::app {
namespace {

namespace fs = std::filesystem;
using mesochain::testing::expectInputError;

const fs::path kExamples = fs::path(MESOCHAIN_SOURCE_DIR) / "examples";

std::vector<std::string> stageNames(const ChainFile& c) {
  std::vector<std::string> out;
  for (const auto& [stage, keys] : c.scans) out.push_back(stage->name);
  return out;
}

// A chain file written to a temporary folder, read; the folder goes away with it.
struct TempChain {
  fs::path dir = fs::temp_directory_path() / ("test-chain-file-" + std::to_string(::getpid()));
  fs::path file = dir / "chain.toml";
  explicit TempChain(const std::string& text) {
    fs::create_directories(dir);
    std::ofstream(file) << text;
  }
  ~TempChain() { fs::remove_all(dir); }
  ChainFile read() const { return readChainFile(file.string()); }
};

TEST(ChainFile, CollapsedTubeExampleReadsEveryField) {
  const fs::path path = kExamples / "chain-collapsed-3030.toml";
  const ChainFile c = readChainFile(path.string());
  EXPECT_EQ(c.file, fs::absolute(path));
  EXPECT_EQ(c.dir, (fs::absolute(kExamples) / "chain-collapsed-3030").lexically_normal());
  EXPECT_EQ(c.cellPath, (fs::absolute(kExamples) / "collapsed-3030.toml").lexically_normal().string());
  EXPECT_EQ(c.forceTolerance, 1e-4);
  EXPECT_EQ(c.cellsPerBrick, 8);
  EXPECT_EQ(c.section, "rectangle");
  EXPECT_TRUE(c.beam);
  EXPECT_EQ(c.cantileverTolerance, 0.01);
  EXPECT_EQ(stageNames(c), (std::vector<std::string>{"stretch", "twist", "bend_soft", "bend_hard"}));
  EXPECT_EQ(std::string(c.scans[2].first->kind), "bend");
  EXPECT_EQ(std::string(c.scans[3].first->direction), "hard");
  EXPECT_TRUE(c.knobs.given);
  EXPECT_EQ(c.knobs.stages, (std::vector<std::string>{"stretch", "bend_soft"}));
  EXPECT_EQ(c.knobs.kpoints, (std::vector<std::string>{"12", "48"}));
  EXPECT_EQ(c.knobs.dispersion, (std::vector<std::string>{"cutoff:20", "ewald"}));
  EXPECT_EQ(c.knobs.sampling, (std::vector<std::string>{"12:6", "48:24"}));
  EXPECT_TRUE(c.knobs.angular.empty() && c.knobs.temperature.empty());

  // The stretch's scan file: the stage's keys, its [dimensions], and what the chain sets.
  std::istringstream in(scanFileText(c, *c.scans[0].first, c.scans[0].second, "stretch", true));
  const toml::value scan = toml::parse(in, "stretch.scan.toml");
  EXPECT_EQ(toml::find<std::string>(scan, "cell"), c.cellPath);
  EXPECT_EQ(toml::find<std::string>(scan, "kind"), "stretch");
  EXPECT_EQ(toml::find<std::string>(scan, "reference"), "reference.json");
  EXPECT_EQ(toml::find<std::vector<double>>(scan, "strains"), (std::vector<double>{-0.01, -0.005, 0.005, 0.01}));
  EXPECT_TRUE(toml::find<bool>(scan, "dimensions", "measure"));
  EXPECT_EQ(toml::find<double>(scan, "dimensions", "interlayer"), 3.4);
  EXPECT_EQ(toml::find<double>(scan, "relax", "force_tolerance"), 1e-4);
  EXPECT_EQ(toml::find<std::string>(scan, "output", "checkpoint"), "stretch.checkpoint.json");
  // The hard bend: its direction, its rings.
  std::istringstream hard(scanFileText(c, *c.scans[3].first, c.scans[3].second, "bend_hard", false));
  const toml::value bend = toml::parse(hard, "bend_hard.scan.toml");
  EXPECT_EQ(toml::find<std::string>(bend, "direction"), "hard");
  EXPECT_EQ(toml::find<std::vector<long>>(bend, "rotation_orders"), (std::vector<long>{19200, 9600}));
  EXPECT_EQ(toml::find<long>(bend, "ring_angular"), 12);
  EXPECT_FALSE(bend.contains("reference"));
}

TEST(ChainFile, BilayerExampleHasNoBeamAndItsCellInline) {
  const ChainFile c = readChainFile((kExamples / "chain-graphene-bilayer.toml").string());
  EXPECT_EQ(c.dir, (fs::absolute(kExamples) / "chain-graphene-bilayer").lexically_normal());
  // The inline [cell] is written by the run into the stages' folder.
  ASSERT_TRUE(c.inlineCell.has_value());
  EXPECT_EQ(c.cellPath, (c.dir / "chain-cell.toml").string());
  std::istringstream cellText(inlineCellText(c));
  const toml::value cell = toml::parse(cellText, "cell.toml");
  EXPECT_EQ(toml::find<std::string>(cell, "builder", "type"), "graphene_ring");
  EXPECT_EQ(toml::find<long>(cell, "builder", "layers"), 2);
  EXPECT_EQ(toml::find<std::string>(cell, "parameters", "set"), "pbc-0-3");
  EXPECT_FALSE(c.beam);
  EXPECT_EQ(c.cellsPerBrick, 0);
  EXPECT_EQ(c.section, "");
  EXPECT_EQ(c.cantileverTolerance, 0.01);
  EXPECT_EQ(stageNames(c), (std::vector<std::string>{"bend_soft"}));
  EXPECT_FALSE(c.knobs.given);
}

// An inline cell's relative paths are those of the chain file's folder; the cell file the run
// writes elsewhere holds them absolute, and a bad key of the cell names cell.KEY and its line.
TEST(ChainFile, InlineCellPathsAreTheChainFilesFolder) {
  const fs::path dir = fs::temp_directory_path() / ("chain-inline-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "skf");
  fs::copy_file(fs::path(MESOCHAIN_SOURCE_DIR) / "params" / "pbc-0-3" / "C-C.skf", dir / "skf" / "C-C.skf");
  const std::string head = "format = 1\nbeam = false\n[stretch]\nstrains = [-0.01, -0.005, 0.005, 0.01]\n";
  const std::string cell =
      "[cell]\nformat = 1\n[cell.builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"translational\"\n"
      "[cell.kpoints]\nhelical = 8\n[cell.electrons]\ntemperature = 300\n[cell.parameters]\nprefix = \"skf/\"\n";
  std::ofstream(dir / "chain.toml") << head << cell;
  const ChainFile c = readChainFile((dir / "chain.toml").string());
  std::istringstream text(inlineCellText(c));
  const toml::value written = toml::parse(text, "cell.toml");
  EXPECT_EQ(toml::find<std::string>(written, "parameters", "prefix"), (dir / "skf/").string());
  // An explicit table: beside the chain file if it is there, else the project root's, written
  // absolute either way (as the reader found it).
  for (const char* table : {"skf/C-C.skf", "params/pbc-0-3/C-C.skf"}) {
    std::string explicitTable = cell;
    explicitTable.replace(explicitTable.find("prefix = \"skf/\""), 15, "set = \"pbc-0-3\"\n\"C-C\" = \"" + std::string(table) + "\"");
    std::ofstream(dir / "table.toml") << head << explicitTable;
    const ChainFile e = readChainFile((dir / "table.toml").string());
    std::istringstream t(inlineCellText(e));
    const fs::path found = fs::path(toml::find<std::string>(toml::parse(t, "cell.toml"), "parameters", "C-C"));
    EXPECT_TRUE(found.is_absolute()) << found;
    EXPECT_TRUE(fs::is_regular_file(found)) << found;
    EXPECT_EQ(found.filename(), "C-C.skf");
  }
  std::string bad = cell;
  bad.replace(bad.find("temperature = 300"), 17, "temperature = -3");
  std::ofstream(dir / "bad.toml") << head << bad;
  expectInputError([&] { readChainFile((dir / "bad.toml").string()); },
                   {"bad.toml", "cell.electrons.temperature", "line 15"});
  fs::remove_all(dir);
}

// The files of tests/cli/test_cli_chain.cpp: defaults (output folder, no section), stage order
// from the stage, not from the file; the knobs default to every scan stage.
TEST(ChainFile, DefaultsAndStageOrder) {
  const TempChain t(
      "format = 1\ncell = \"cnt55t.toml\"\nforce_tolerance = 1e-4\ncells_per_brick = 4\n"
      "[bend_soft]\nrotation_orders = [1280, 640]\nring_angular = 4\n"
      "[stretch]\nstrains = [-0.01, -0.005, 0.005, 0.01]\n"
      "[twist]\ntwist_deg_per_cell = [-0.4, -0.2, 0.2, 0.4]\n");
  const ChainFile c = t.read();
  EXPECT_EQ(c.dir, fs::absolute(t.dir) / "chain-out");
  EXPECT_EQ(c.cellPath, (fs::absolute(t.dir) / "cnt55t.toml").string());
  EXPECT_EQ(c.cellsPerBrick, 4);
  EXPECT_EQ(stageNames(c), (std::vector<std::string>{"stretch", "twist", "bend_soft"}));
  EXPECT_FALSE(c.knobs.given);

  const TempChain k("format = 1\ncell = \"cnt55t.toml\"\nbeam = false\nforce_tolerance = 2\n"
                    "[stretch]\nstrains = [-0.01, -0.005, 0.005, 0.01]\n[twist]\ntwist_deg_per_cell = [1]\n"
                    "[knobs]\nkpoints = [4, 16]\ntemperature = [300.0, 1e3]\nsampling = [\"16:4\"]\n");
  const ChainFile ck = k.read();
  EXPECT_EQ(ck.forceTolerance, 2.0);
  EXPECT_FALSE(ck.beam);
  EXPECT_EQ(ck.knobs.stages, (std::vector<std::string>{"stretch", "twist"}));
  EXPECT_EQ(ck.knobs.kpoints, (std::vector<std::string>{"4", "16"}));
  EXPECT_EQ(ck.knobs.temperature, (std::vector<std::string>{"300", "1000"}));
  EXPECT_EQ(ck.knobs.sampling, (std::vector<std::string>{"16:4"}));
}

const std::string kHead = "format = 1\ncell = \"c.toml\"\ncells_per_brick = 4\n";
const std::string kStretch = "[stretch]\nstrains = [0.01]\n";

void expectRefused(const std::string& text, std::initializer_list<const char*> fragments) {
  const TempChain t(text);
  expectInputError([&] { t.read(); }, fragments);
}

TEST(ChainFile, BadKeysAreNamedWithTheirLine) {
  expectRefused(kHead + "[strech]\nstrains = [0.01]\n",
                {"chain.toml", "key strech (line 4)", "unknown key 'strech'", "[stretch]", "[knobs]", "cells_per_brick"});
  expectRefused("format = 2\ncell = \"c.toml\"\ncells_per_brick = 4\n" + kStretch,
                {"key format (line 1)", "an integer (2)", "format = 1"});
  expectRefused("cell = \"c.toml\"\ncells_per_brick = 4\n" + kStretch, {"key format", "required", "format = 1"});
  expectRefused("format = 1\ncells_per_brick = 4\n" + kStretch, {"key cell", "required", "cell file"});
  expectRefused("format = 1\ncell = 3\ncells_per_brick = 4\n" + kStretch, {"key cell (line 2)", "an integer (3)", "cell file"});
  expectRefused("format = 1\ncell = \"c.toml\"\n" + kStretch, {"key cells_per_brick", "required", "beam = false"});
  expectRefused("format = 1\ncell = \"c.toml\"\ncells_per_brick = 0\n" + kStretch,
                {"key cells_per_brick (line 3)", "an integer (0)", "an integer from 1 to 10000000"});
  expectRefused(kHead + "output = \"\"\n" + kStretch, {"key output (line 4)", "an empty string", "folder"});
  expectRefused(kHead + "force_tolerance = -1e-4\n" + kStretch, {"key force_tolerance (line 4)", "-0.0001", "> 0 (Ha/Bohr)"});
  expectRefused(kHead + "force_tolerance = nan\n" + kStretch, {"key force_tolerance (line 4)", "non-finite", "> 0"});
  expectRefused(kHead + "section = \"square\"\n" + kStretch,
                {"key section (line 4)", "\"square\"", "\"rectangle\", \"circle\" or \"annulus\""});
  expectRefused(kHead + "beam = 1\n" + kStretch, {"key beam (line 4)", "an integer (1)", "true or false"});
  expectRefused(kHead, {"chain.toml", "no scan table", "[stretch]"});
  expectRefused(kHead + "stretch = 3\n", {"key stretch (line 4)", "an integer (3)", "a table [stretch]"});
}

TEST(ChainFile, BadTablesAreNamedWithTheirLine) {
  expectRefused(kHead + kStretch + "[cantilever]\ntolerance = 1.5\n",
                {"key cantilever.tolerance (line 7)", "a float (1.5)", "(0, 1)"});
  expectRefused(kHead + kStretch + "[cantilever]\ntol = 0.1\n",
                {"key cantilever.tol (line 7)", "unknown key 'tol'", "tolerance"});
  expectRefused(kHead + "cantilever = 0.1\n" + kStretch, {"key cantilever (line 4)", "a float (0.1)", "[cantilever]"});
  expectRefused(kHead + kStretch + "[knobs]\nkpoints = [4, true]\n",
                {"key knobs.kpoints (line 7)", "a boolean (true)", "numbers or strings"});
  expectRefused(kHead + kStretch + "[knobs]\nkpoints = 4\n", {"key knobs.kpoints (line 7)", "an integer (4)", "an array"});
  expectRefused(kHead + kStretch + "[knobs]\nkpoint = [4]\n",
                {"key knobs.kpoint (line 7)", "unknown key 'kpoint'", "stages, kpoints, angular, sampling, dispersion, temperature"});
  expectRefused(kHead + kStretch + "[knobs]\nstages = [\"twist\"]\n",
                {"key knobs.stages (line 7)", "\"twist\"", "scan stages of this chain file: stretch"});
  // Keys the chain sets in the scan file itself, and sub-tables other than [STAGE.dimensions].
  expectRefused(kHead + kStretch + "kind = \"twist\"\n", {"key stretch.kind (line 6)", "a key the chain sets itself", "strains"});
  expectRefused(kHead + kStretch + "[stretch.relax]\nforce_tolerance = 1e-3\n",
                {"key stretch.relax (line 6)", "a table", "[stretch.dimensions]"});
}

}  // namespace
}  // namespace mesochain::app
