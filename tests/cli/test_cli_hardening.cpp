// Bad input at the command line, as a demanding user (or a fuzzer) gives it: each case must end
// with a non-zero exit, a message naming the option or the file and key, and no output file.
// The cases are the examples of issue 14 outside mdem/ and their relatives.
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = fs::temp_directory_path() / fmt::format("cli-hard-{}-{}", ::getpid(), counter()++);
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  static int& counter() {
    static int n = 0;
    return n;
  }
};

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string cellFile(const std::string& kpoints = "helical = 8", const std::string& kelvin = "300",
                     const std::string& task = "energy") {
  return fmt::format(
      "format = 1\n[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\n"
      "[kpoints]\n{}\n[electrons]\ntemperature = {}\n[parameters]\nset = \"pbc-0-3\"\n"
      "[task]\ntype = \"{}\"\n",
      kpoints, kelvin, task);
}

struct Case {
  std::string name;
  std::string args;        // after `mesochain`, run in the case's folder
  std::string mustSay;     // a regex the output must match
  std::vector<std::string> noOutput = {};  // files that must not exist afterwards
};

// Runs a case in a fresh folder holding cell.toml (5,5 helical, energy) and beam.toml.
void expectRefused(const Case& c, const std::string& cell = cellFile(),
                   const std::string& beam = "") {
  TempDir dir;
  write(dir.path / "cell.toml", cell);
  if (!beam.empty()) write(dir.path / "beam.toml", beam);
  std::string out;
  const int code = mesochain::testing::runMesochain(c.args, dir.path, out);
  EXPECT_NE(code, 0) << c.name << ": " << out;
  EXPECT_TRUE(std::regex_search(out, std::regex(c.mustSay))) << c.name << ": " << out;
  EXPECT_EQ(out.find("terminate"), std::string::npos) << c.name << ": " << out;
  EXPECT_EQ(out.find("bad_alloc"), std::string::npos) << c.name << ": " << out;
  for (const std::string& f : c.noOutput)
    EXPECT_FALSE(fs::exists(dir.path / f)) << c.name << " wrote " << f << ": " << out;
}

TEST(CliHardening, BuildOptionsOutOfRangeAreRefused) {
  const std::vector<Case> cases = {
      {"kpoints 0", "build cnt 5 5 --kpoints 0 -o b.toml", "--kpoints.*1 to 1000000", {"b.toml"}},
      {"temperature -3", "build cnt 5 5 --temperature -3 -o b.toml", "--temperature", {"b.toml"}},
      {"temperature 1e-13", "build cnt 5 5 --temperature 1e-13 -o b.toml",
       "command line.*option --temperature.*0.01 K", {"b.toml"}},
      {"rotation order 2", "build graphene-ring 1 --direction armchair --rotation-order 2 -o b.toml",
       "--rotation-order.*3 to 10000000", {"b.toml"}},
      {"rotation order 3e9",
       "build graphene-ring 1 --direction armchair --rotation-order 3000000000 -o b.toml",
       "--rotation-order.*3000000000.*3 to 10000000", {"b.toml"}},
      {"bond 0.2 Å", "build cnt 5 5 --bond 0.2 -o b.toml", "command line.*0.50 Å", {"b.toml"}},
      {"n 0", "build cnt 0 0 -o b.toml", "1 to 10000", {"b.toml"}},
      {"wall 5000000000,0", "build multiwall 5,5 5000000000,0 -o b.toml",
       "wall '5000000000,0'.*n <= 10000", {"b.toml"}},
      {"chiral 2,-1", "build graphene-ring 1 --direction chiral --chiral 2,-1 --rotation-order 12 -o b.toml",
       "--chiral.*0 <= m <= 10000", {"b.toml"}},
      {"output in no folder", "build cnt 5 5 -o /nonexistent/b.toml", "/nonexistent.*does not exist"},
  };
  for (const Case& c : cases) expectRefused(c);
}

TEST(CliHardening, RunAndScanOptionsOutOfRangeAreRefused) {
  const std::vector<Case> cases = {
      {"unroll -3", "run cell.toml --unroll -3 --structure s", "--unroll", {"s.xyz"}},
      {"json empty", "run cell.toml --json ''", "--json.*empty path"},
      {"json in no folder", "run cell.toml --json /nonexistent/x.json",
       "command line.*option --json.*/nonexistent.*does not exist"},
      {"unroll 1e8", "run cell.toml --unroll 100000000 --structure s",
       "option --unroll.*atoms.*GB.*at most 10000000", {"s.xyz", "s-unrolled.xyz"}},
      {"stop after -1", "scan scan.toml --stop-after -1", "--stop-after"},
  };
  for (const Case& c : cases) expectRefused(c);
}

TEST(CliHardening, CellValuesThatBreakThePhysicsAreRefused) {
  expectRefused({"temperature 1e-13 K", "run cell.toml --json r.json",
                 "cell.toml.*electrons.temperature.*1e-13 K.*0.01 K", {"r.json"}},
                cellFile("helical = 8", "1e-13"));
  expectRefused({"temperature 1e-307 K", "run cell.toml --json r.json",
                 "cell.toml.*electrons.temperature", {"r.json"}},
                cellFile("helical = 8", "1e-307"));
  expectRefused({"helical 2e9", "run cell.toml --json r.json", "cell.toml.*helical.*1 to 1000000",
                 {"r.json"}},
                cellFile("helical = 2000000000"));
}

TEST(CliHardening, BeamOverflowsAndWrappedIntegersAreRefused) {
  const std::string head = "format = 1\natoms_per_cell = 120\n";
  const std::string rest =
      "K_eV_per_rad2 = 1350.0\nD_soft_eV_angstrom2 = 5000.0\nD_hard_eV_angstrom2 = 2.31e6\n"
      "thickness_angstrom = 6.8\n";
  const std::vector<std::string> written = {"out/beam.json", "out/model.toml",
                                            "out/cantilever.toml"};
  expectRefused({"C_eV 1e308", "beam beam.toml -o out", "non-finite", written}, cellFile(),
                head + "T0_angstrom = 2.46\ncells_per_brick = 8\nC_eV = 1e308\n" + rest);
  expectRefused({"T0 1e-300", "beam beam.toml -o out", "non-finite", written}, cellFile(),
                head + "T0_angstrom = 1e-300\ncells_per_brick = 8\nC_eV = 6770.0\n" + rest);
  expectRefused({"cells_per_brick 3e9", "beam beam.toml -o out",
                 "beam.toml, key cells_per_brick.*1 to 10000000", written},
                cellFile(), head + "T0_angstrom = 2.46\ncells_per_brick = 3e9\nC_eV = 6770.0\n" + rest);
  expectRefused({"-n 0", "beam beam.toml -o out -n 0", "cells-per-brick", written}, cellFile(),
                head + "T0_angstrom = 2.46\ncells_per_brick = 8\nC_eV = 6770.0\n" + rest);
  const std::string fine = head + "T0_angstrom = 2.46\ncells_per_brick = 8\nC_eV = 6770.0\n" + rest;
  expectRefused({"-o ''", "beam beam.toml -o ''", "output-dir.*empty path"}, cellFile(), fine);
  expectRefused({"-o in /proc", "beam beam.toml -o /proc/no/such", "option --output-dir.*cannot be created"},
                cellFile(), fine);
  expectRefused({"skgen -o ''", "skgen x.toml -o ''", "output-dir.*empty path"});
  expectRefused({"dem -o ''", "dem x.toml -o ''", "output-dir.*empty path"});
}

// A stretch of -90 % puts the atoms of a (5,5) tube 0.25 Å apart: an error naming the scan
// point, never an energy in the curve.
TEST(CliHardening, ScanPointThatCollapsesAtomsIsAnErrorNamingThePoint) {
  TempDir dir;
  write(dir.path / "cell.toml", cellFile("helical = 4"));
  write(dir.path / "scan.toml",
        "format = 1\ncell = \"cell.toml\"\nkind = \"stretch\"\nstrains = [-0.9]\n"
        "[relax]\nforce_tolerance = 1e-2\nrelax_translation = false\n"
        "[output]\njson = \"s.json\"\ncsv = \"s.csv\"\n");
  std::string out;
  const int code = mesochain::testing::runMesochain("scan scan.toml", dir.path, out);
  EXPECT_EQ(code, 2) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("scan point 2 of 2 \\(stretch -0.9 strain\\).*"
                                                "starting geometry.*Å")))
      << out;
  EXPECT_FALSE(fs::exists(dir.path / "s.json"));
  EXPECT_FALSE(fs::exists(dir.path / "s.csv"));
}

// A scan whose output folder does not exist is refused before the first point is computed.
TEST(CliHardening, ScanOutputPathIsCheckedBeforeTheComputation) {
  TempDir dir;
  write(dir.path / "cell.toml", cellFile("helical = 4"));
  write(dir.path / "scan.toml",
        "format = 1\ncell = \"cell.toml\"\nkind = \"stretch\"\nstrains = [0.01]\n"
        "[output]\njson = \"missing/s.json\"\n");
  std::string out;
  EXPECT_EQ(mesochain::testing::runMesochain("scan scan.toml", dir.path, out), 2) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("scan.toml, key output.json.*does not exist")))
      << out;
  EXPECT_EQ(out.find("point 1"), std::string::npos) << out;
}

}  // namespace
