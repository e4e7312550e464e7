// `mesochain run dftb_in.hsd` and `mesochain convert` end to end: DFTB+'s input of the methane
// case (tests/data/dftbplus/ch4, table prefix pointed at this tree's params/) gives DFTB+'s
// Mermin free energy; the converted cell file gives the same; a keyword outside the subset ends
// with exit code 2 naming it and its line; --set with a .hsd input is refused.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using mesochain::testing::readJson;
using mesochain::testing::runMesochain;
using mesochain::testing::slurp;

struct HsdCommandLine : ::testing::Test {
  fs::path dir;
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / fmt::format("cli-hsd-{}-{}", ::getpid(), info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string data = std::string(MESOCHAIN_SOURCE_DIR) + "/tests/data/dftbplus/ch4/";
    fs::copy_file(data + "geo.gen", dir / "geo.gen");
    std::string text = slurp(data + "dftb_in.hsd");
    const std::string recorded = "/work/shared/params/pbc-0-3/";
    text.replace(text.find(recorded), recorded.size(), std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/");
    std::ofstream(dir / "dftb_in.hsd") << text;
  }
  void TearDown() override { fs::remove_all(dir); }
};

double dftbPlusMermin() {
  std::ifstream f(std::string(MESOCHAIN_SOURCE_DIR) + "/tests/data/dftbplus/ch4/reference.json");
  return nlohmann::json::parse(f)["summary"]["total_mermin_free_energy"].get<double>();
}

}  // namespace

TEST_F(HsdCommandLine, RunAndConvertGiveDftbPlusNumbers) {
  std::string out;
  ASSERT_EQ(runMesochain("run dftb_in.hsd --json hsd.json", dir, out), 0) << out;
  const double hsd = readJson(dir / "hsd.json")["energies_hartree"]["mermin_free"]["per_cell"].get<double>();
  EXPECT_NEAR(hsd, dftbPlusMermin(), 1e-9);
  ASSERT_EQ(runMesochain("convert dftb_in.hsd -o cell.toml", dir, out), 0) << out;
  EXPECT_NE(slurp(dir / "cell.toml").find("type = \"forces\""), std::string::npos);
  ASSERT_EQ(runMesochain("run cell.toml --json toml.json", dir, out), 0) << out;
  const double toml = readJson(dir / "toml.json")["energies_hartree"]["mermin_free"]["per_cell"].get<double>();
  EXPECT_NEAR(toml, hsd, 1e-11);
}

TEST_F(HsdCommandLine, KeywordsOutsideTheSubsetExitWithTwo) {
  std::string text = slurp(dir / "dftb_in.hsd");
  text.replace(text.find("SCC = No"), 8, "SCC = No\n  ThirdOrderFull = Yes");
  std::ofstream(dir / "bad.hsd") << text;
  std::string out;
  EXPECT_EQ(runMesochain("run bad.hsd", dir, out), 2) << out;
  EXPECT_NE(out.find("bad.hsd, line 7 (Hamiltonian/DFTB/ThirdOrderFull)"), std::string::npos) << out;
  EXPECT_EQ(runMesochain("convert bad.hsd -o x.toml", dir, out), 2) << out;
  EXPECT_FALSE(fs::exists(dir / "x.toml"));
  EXPECT_EQ(runMesochain("run dftb_in.hsd --set kpoints.helical=4", dir, out), 2) << out;
  EXPECT_NE(out.find("--set"), std::string::npos) << out;
}
