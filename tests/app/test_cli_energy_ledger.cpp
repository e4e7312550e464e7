// `mesochain run` end to end: the results JSON's energies_hartree and the terminal table are the
// calculator's energy ledger. A (5,5) tube without and with dispersion: keys only for the terms
// built, total = the sum of the Energy entries, mermin_free = total - TS, and the table's rows
// follow the same entries.
#include <gtest/gtest.h>

#include "tests/support/process_temp_dir.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

struct LedgerRun {
  nlohmann::json energies;
  std::string table;
};

LedgerRun run(const std::string& name, const std::string& dispersionModel) {
  const fs::path dir = mesochain::testing::processTempDir("mesochain-test-cli-ledger");
  fs::create_directories(dir);
  const fs::path cell = dir / (name + ".toml"), json = dir / (name + ".json"),
                 log = dir / (name + ".log");
  std::ofstream(cell)
      << "format = 1\n"
         "[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\nbond_length = 1.42\n"
         "[kpoints]\nhelical = 16\nangular = \"all\"\n"
         "[electrons]\ntemperature = 3000.0\n"
         "[parameters]\nset = \"pbc-0-3\"\n"
         "[dispersion]\nmodel = \"" << dispersionModel << "\"\n[task]\ntype = \"energy\"\n";
  fs::remove(json);
  const std::string cmd = std::string("cd \"") + MESOCHAIN_SOURCE_DIR + "\" && \"" +
                          MESOCHAIN_EXECUTABLE + "\" run \"" + cell.string() + "\" --json \"" +
                          json.string() + "\" > \"" + log.string() + "\" 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(json), text(log);
  EXPECT_TRUE(in.good()) << "no JSON from " << cmd;
  if (!in.good()) return {};
  std::stringstream t;
  t << text.rdbuf();
  return {nlohmann::json::parse(in).at("energies_hartree"), t.str()};
}

double perCell(const nlohmann::json& e, const char* key) {
  return e.at(key).at("per_cell").get<double>();
}

}  // namespace

TEST(CliEnergyLedger, ResultsAndTableAreTheLedgerOfTheBuiltTerms) {
  const LedgerRun plain = run("plain", "none");
  const LedgerRun lj = run("lj", "lj");
  EXPECT_FALSE(plain.energies.contains("dispersion"));
  EXPECT_FALSE(plain.energies.contains("scc"));
  ASSERT_TRUE(lj.energies.contains("dispersion"));
  // Within one wall the bonded neighbours sit inside the LJ switch radius (positive there).
  EXPECT_GT(std::abs(perCell(lj.energies, "dispersion")), 1e-4);
  EXPECT_GT(perCell(plain.energies, "entropy_term_ts"), 0.0);  // 3000 K on a metallic tube
  for (const LedgerRun* r : {&plain, &lj}) {
    const auto& e = r->energies;
    const double sum = perCell(e, "band") + perCell(e, "repulsive") +
                       (e.contains("dispersion") ? perCell(e, "dispersion") : 0.0);
    EXPECT_NEAR(perCell(e, "total"), sum, 1e-12);
    EXPECT_NEAR(perCell(e, "mermin_free"), sum - perCell(e, "entropy_term_ts"), 1e-12);
    EXPECT_NE(r->table.find("\nband "), std::string::npos) << r->table;
    EXPECT_NE(r->table.find("\nrepulsive "), std::string::npos) << r->table;
  }
  EXPECT_EQ(plain.table.find("\ndispersion "), std::string::npos) << plain.table;
  EXPECT_NE(lj.table.find("\ndispersion "), std::string::npos) << lj.table;
  // The terms not touched by dispersion are the same numbers.
  EXPECT_EQ(perCell(plain.energies, "band"), perCell(lj.energies, "band"));
  EXPECT_EQ(perCell(plain.energies, "repulsive"), perCell(lj.energies, "repulsive"));
}
