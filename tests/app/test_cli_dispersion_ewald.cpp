// `mesochain run` end to end with Ewald-summed dispersion: a (5,5) tube cell file with
// [dispersion] model = "lj", summation = "ewald" gives the dispersion (and total) energy of the
// plain cutoff sum with a cutoff so large (1000 Å) that its r^-5 tail error (~2e-13 relative) is
// far below the Ewald tolerance; the default 30 Å cutoff is visibly worse (the test can fail).
#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

std::string cellFile(const std::string& dispersion) {
  return "format = 1\n"
         "[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\nbond_length = 1.42\n"
         "[kpoints]\nhelical = 64\nangular = \"all\"\n"
         "[electrons]\ntemperature = 300.0\n"
         "[parameters]\nset = \"pbc-0-3\"\n"
         "[dispersion]\nmodel = \"lj\"\n" +
         dispersion + "[task]\ntype = \"energy\"\n";
}

struct Energies {
  double dispersion = 0, total = 0;
};

// Writes the cell file, runs the mesochain executable on it and reads its JSON result.
Energies run(const std::string& name, const std::string& dispersion) {
  const fs::path dir = mesochain::testing::processTempDir("mesochain-test-cli-dispersion");
  fs::create_directories(dir);
  const fs::path cell = dir / (name + ".toml"), json = dir / (name + ".json");
  std::ofstream(cell) << cellFile(dispersion);
  fs::remove(json);
  // The parameter set is found relative to the working directory (the source tree).
  const std::string cmd = std::string("cd \"") + MESOCHAIN_SOURCE_DIR + "\" && \"" +
                          MESOCHAIN_EXECUTABLE + "\" run \"" + cell.string() + "\" --json \"" +
                          json.string() + "\" > \"" + (dir / (name + ".log")).string() + "\" 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(status, 0) << cmd;
  std::ifstream in(json);
  EXPECT_TRUE(in.good()) << "no JSON from " << cmd;
  if (!in.good()) return {};
  const auto j = nlohmann::json::parse(in);
  const auto& e = j.at("energies_hartree");
  return {e.at("dispersion").at("per_cell").get<double>(), e.at("total").at("per_cell").get<double>()};
}

}  // namespace

TEST(CliDispersionEwald, RunMatchesTheCutoffSumWithAVeryLargeCutoff) {
  const Energies ewald = run("ewald", "summation = \"ewald\"\newald_tolerance = 1e-10\n");
  const Energies ewaldLoose = run("ewald-1e-4", "summation = \"ewald\"\newald_tolerance = 1e-4\n");
  const Energies cutoff = run("cutoff-1000", "summation = \"cutoff\"\ncutoff = 1000.0\n");
  const Energies cutoff30 = run("cutoff-30", "summation = \"cutoff\"\n");
  ASSERT_NE(ewald.dispersion, 0.0);
  const double scale = std::abs(cutoff.dispersion);
  EXPECT_NEAR(ewald.dispersion, cutoff.dispersion, 1e-10 * scale);
  EXPECT_NEAR(ewald.total - ewald.dispersion, cutoff.total - cutoff.dispersion, 1e-12);
  EXPECT_NEAR(ewaldLoose.dispersion, cutoff.dispersion, 1e-4 * scale);
  // The default cutoff misses the r^-6 tail beyond 30 Å: a relative error near 1e-5.
  EXPECT_GT(std::abs(cutoff30.dispersion - cutoff.dispersion), 1e-7 * scale);
}
