// The `mesochain skgen` input file: strict reading with clear errors, and a small run whose
// tables dftb/skf_file reads back.
#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "dftb/skf_file.hpp"
#include "skgen/skgen_job.hpp"

using namespace mesochain;
using namespace mesochain::skgen;

namespace {
const char* kHydrogen = R"(functional = "pbe"
pairs = ["H-H"]
[grid]
spacing_bohr = 0.5
cutoff_bohr = 6.0
quadrature_points = 32
[elements.H]
exponents_per_bohr = [0.5, 1.0, 2.0]
powers = 3
density = { r0_bohr = 2.5, power = 2 }
wavefunction = { r0_bohr = 3.0, power = 2 }
)";

std::string writeInput(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("mesochain-skgen-" + name + ".toml");
  std::ofstream(p) << text;
  return p.string();
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto i = s.find(from);
  EXPECT_NE(i, std::string::npos) << from;
  return s.replace(i, from.size(), to);
}

// The InputError message of reading (and, with run = true, running) the file.
std::string errorOf(const std::string& name, const std::string& text, bool run = false) {
  const std::string path = writeInput(name, text);
  try {
    SkgenJob job = readSkgenJob(path);
    if (run) {
      job.outputDir = mesochain::testing::processTempDir("mesochain-skgen-err").string();
      runSkgen(job);
    }
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << name;
  return "";
}
}  // namespace

TEST(SkgenJob, ReadsTheRecipe) {
  const SkgenJob job = readSkgenJob(writeInput("ok", kHydrogen));
  ASSERT_EQ(job.elements.size(), 1u);
  EXPECT_EQ(job.elements[0].symbol, "H");
  EXPECT_EQ(job.elements[0].slater.exponents.size(), 3u);
  EXPECT_EQ(job.elements[0].shells.size(), 1u);
  EXPECT_DOUBLE_EQ(job.elements[0].shells[0].r0, 3.0);
  EXPECT_DOUBLE_EQ(job.elements[0].density.r0, 2.5);
  EXPECT_EQ(job.pairs.size(), 1u);
  EXPECT_EQ(job.grid.quadrature.nXi, 32);
  EXPECT_EQ(job.hubbardXc, XcKind::Pbe);
  EXPECT_EQ(job.grid.quadrature.superposition, Superposition::Density);  // the default
  const SkgenJob pot = readSkgenJob(writeInput("pot", std::string("superposition = \"potential\"\n") + kHydrogen));
  EXPECT_EQ(pot.grid.quadrature.superposition, Superposition::Potential);
  EXPECT_NE(skgenDocumentation(pot, pot.elements[0], pot.elements[0], nullptr)
                .find("<Superposition>potential</Superposition>"),
            std::string::npos);
  const std::string e = errorOf("sup", std::string("superposition = \"average\"\n") + kHydrogen);
  EXPECT_NE(e.find("superposition"), std::string::npos) << e;
  EXPECT_NE(e.find("\"density\" or \"potential\""), std::string::npos) << e;
}

TEST(SkgenJob, RunWritesTablesTheReaderAccepts) {
  SkgenJob job = readSkgenJob(writeInput("run", kHydrogen));
  job.outputDir = mesochain::testing::processTempDir("mesochain-skgen-run").string();
  double last = -1.0;
  bool monotone = true;
  const SkgenOutput out = runSkgen(job, [&](double f, const std::string&) {
    monotone = monotone && f >= last;
    last = f;
  });
  ASSERT_EQ(out.tables.size(), 1u);
  EXPECT_TRUE(monotone);
  EXPECT_DOUBLE_EQ(last, 1.0);
  const dftb::SkfTable t = dftb::readSkfFile(out.tables[0], true);
  EXPECT_EQ(t.rows(), 12);
  EXPECT_NEAR(t.onsite[0], -0.2386004, 1e-6);  // PBE hydrogen 1s (pbc-0-3 H-H.skf: -0.23860040)
  EXPECT_GT(t.over(3, dftb::kSkfSsSigma), 0.0);
  ASSERT_TRUE(t.spline.has_value());
  // atomic data beside the tables: the PBE hydrogen spin constant (DFTB+ manual, PBE: -0.072)
  // and the spin-polarisation energy, also in the SPE field of the atomic line
  std::ifstream in(out.atomicData);
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& h = j["elements"]["H"];
  EXPECT_EQ(h["valence_shells"][0], "1s");
  EXPECT_NEAR(h["spin_constants_Ha"][0][0].get<double>(), -0.072, 5e-4);
  EXPECT_NEAR(h["onsite_Ha"]["1s"].get<double>(), t.onsite[0], 1e-15);
  const double spe = h["spin_polarisation_energy_Ha"].get<double>();
  EXPECT_LT(spe, -0.03);  // the polarised H atom lies lower (LDA: -0.0330, pbc-0-3 H-H.skf)
  EXPECT_NEAR(t.spinPolarisationError, spe, 1e-15);
}

TEST(SkgenJob, UnknownElementIsAClearError) {
  const std::string e = errorOf("unknown", replaced(kHydrogen, "[elements.H]", "[elements.Xx]"));
  EXPECT_NE(e.find("unknown element 'Xx'"), std::string::npos) << e;
  EXPECT_NE(e.find("elements.Xx"), std::string::npos) << e;
}

TEST(SkgenJob, DShellsAreAClearError) {
  // an element whose valence needs d shells, and a d shell asked for on a first-row element
  const std::string fe = errorOf("iron", replaced(replaced(kHydrogen, "[elements.H]", "[elements.Fe]"),
                                                  "pairs = [\"H-H\"]", "pairs = [\"Fe-Fe\"]"));
  EXPECT_NE(fe.find("Fe (Z = 26), whose valence needs d (or f) shells"), std::string::npos) << fe;
  EXPECT_NE(fe.find("s and p shells only"), std::string::npos) << fe;
  const std::string si = errorOf("silicon", replaced(kHydrogen, "[elements.H]", "[elements.Si]"));
  EXPECT_NE(si.find("Si (Z = 14), not in skgen's element list"), std::string::npos) << si;
  const std::string d = errorOf("dshell", std::string(kHydrogen) + "shells = { 3d = { r0_bohr = 3.0, power = 2 } }\n");
  EXPECT_NE(d.find("elements.H.shells.3d"), std::string::npos) << d;
  EXPECT_NE(d.find("a d shell"), std::string::npos) << d;
  EXPECT_NE(d.find("s and p shells only"), std::string::npos) << d;
}

TEST(SkgenJob, CutoffShorterThanTheFirstGridPointIsAClearError) {
  const std::string e = errorOf("cutoff", replaced(kHydrogen, "cutoff_bohr = 6.0", "cutoff_bohr = 0.3"));
  EXPECT_NE(e.find("grid.cutoff_bohr"), std::string::npos) << e;
  EXPECT_NE(e.find("shorter than the first grid point"), std::string::npos) << e;
}

// Integers checked before narrowing, a grid of too many rows, and a repulsion beyond the grid
// (a table the .skf reader would refuse) are refused with the limits.
TEST(SkgenJob, OutOfRangeValuesStateTheirLimits) {
  const std::string p = errorOf("powers", replaced(kHydrogen, "powers = 3", "powers = 4294967299"));
  EXPECT_NE(p.find("4294967299"), std::string::npos) << p;
  EXPECT_NE(p.find("from 1 to 6"), std::string::npos) << p;
  const std::string g = errorOf("rows", replaced(kHydrogen, "spacing_bohr = 0.5", "spacing_bohr = 1e-9"));
  EXPECT_NE(g.find("at most 100000 rows"), std::string::npos) << g;
  const std::string r = errorOf(
      "repulsion", std::string(kHydrogen) +
                       "[repulsive.H-H]\ncurve_csv = \"h2.csv\"\ncutoff_bohr = 8.0\n");
  EXPECT_NE(r.find("beyond the integral grid"), std::string::npos) << r;
}

TEST(SkgenJob, ConfinementTooSmallForABoundStateIsAClearError) {
  const std::string e = errorOf(
      "bound", replaced(kHydrogen, "wavefunction = { r0_bohr = 3.0", "wavefunction = { r0_bohr = 0.3"), true);
  EXPECT_NE(e.find("confinement radius large enough for a bound state"), std::string::npos) << e;
  EXPECT_NE(e.find("1s"), std::string::npos) << e;
}

TEST(SkgenJob, UnknownKeysWrongTypesAndBadPairsAreClearErrors) {
  EXPECT_NE(errorOf("key", replaced(kHydrogen, "powers = 3", "power = 3")).find("unknown key 'power'"),
            std::string::npos);
  EXPECT_NE(errorOf("type", replaced(kHydrogen, "spacing_bohr = 0.5", "spacing_bohr = \"0.5\"")).find("grid.spacing_bohr"),
            std::string::npos);
  EXPECT_NE(errorOf("pair", replaced(kHydrogen, "[\"H-H\"]", "[\"H-C\"]")).find("no [elements.C] table"),
            std::string::npos);
  EXPECT_NE(errorOf("xc", replaced(kHydrogen, "\"pbe\"", "\"b3lyp\"")).find("b3lyp"), std::string::npos);
  EXPECT_NE(errorOf("shell", replaced(kHydrogen, "wavefunction = { r0_bohr = 3.0, power = 2 }",
                                     "shells = { 2s = { r0_bohr = 3.0, power = 2 } }"))
                .find("2s"),
            std::string::npos);
  EXPECT_NE(errorOf("dup", replaced(kHydrogen, "[0.5, 1.0, 2.0]", "[0.5, 1.0, 1.0]")).find("twice"),
            std::string::npos);
}

// The lists and sub-tables read through common/toml_table: each message names the key, its line,
// what was found and what was expected.
TEST(SkgenJob, BadListsAndTablesSayWhatWasFound) {
  const auto has = [](const std::string& e, std::initializer_list<const char*> fragments) {
    for (const char* f : fragments) EXPECT_NE(e.find(f), std::string::npos) << e << " lacks " << f;
  };
  has(errorOf("exp0", replaced(kHydrogen, "[0.5, 1.0, 2.0]", "[0.5, 0.0, 2.0]")),
      {"key elements.H.exponents_per_bohr (line 8)", "an array holding 0", "exponents > 0 in 1/bohr"});
  has(errorOf("expempty", replaced(kHydrogen, "[0.5, 1.0, 2.0]", "[]")),
      {"key elements.H.exponents_per_bohr (line 8)", "an empty array", "a non-empty array"});
  has(errorOf("expstr", replaced(kHydrogen, "[0.5, 1.0, 2.0]", "[0.5, \"x\"]")),
      {"key elements.H.exponents_per_bohr (line 8)", "an array holding a string (\"x\")"});
  has(errorOf("pairsint", replaced(kHydrogen, "[\"H-H\"]", "[\"H-H\", 3]")),
      {"key pairs (line 2)", "an array holding an integer (3)", "an array of \"A-B\" strings"});
  has(errorOf("pairsstr", replaced(kHydrogen, "[\"H-H\"]", "\"H-H\"")),
      {"key pairs (line 2)", "a string (\"H-H\")", "an array of \"A-B\" strings"});
  has(errorOf("density", replaced(kHydrogen, "density = { r0_bohr = 2.5, power = 2 }", "density = 2.5")),
      {"key elements.H.density (line 10)", "a float (2.5)", "a confinement table { r0_bohr, power }"});
  has(errorOf("grid", replaced(replaced(kHydrogen, "[grid]\nspacing_bohr = 0.5\ncutoff_bohr = 6.0\nquadrature_points = 32\n", ""),
                            "functional = \"pbe\"", "functional = \"pbe\"\ngrid = 1")),
      {"key grid (line 2)", "an integer (1)", "a table [grid]"});
}
