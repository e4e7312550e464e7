// `mesochain reduce` end to end: the (5,5) translational cell written by `build` reduces to
// rotation order 5, and `run` of the reduced file gives the original's energy per atom, Mermin
// free energy per atom and forces on the kept atoms; a cell without extra rotation writes
// nothing; a bad tolerance is refused naming the option.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using mesochain::testing::readJson;
using mesochain::testing::runMesochain;

struct ReduceCommandLine : ::testing::Test {
  fs::path dir;
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / fmt::format("cli-reduce-{}-{}", ::getpid(), info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(ReduceCommandLine, ArmchairCellRunsAsFourAtomsWithTheSameEnergyAndForces) {
  std::string out;
  ASSERT_EQ(runMesochain("build cnt 5 5 --cell translational --kpoints 6 --temperature 3000 --task forces -o c.toml",
                         dir, out), 0) << out;
  ASSERT_EQ(runMesochain("reduce c.toml -o r.toml", dir, out), 0) << out;
  EXPECT_NE(out.find("rotation order 1 -> 5: 20 atoms -> 4 atoms"), std::string::npos) << out;
  ASSERT_EQ(runMesochain("run c.toml --json c.json", dir, out), 0) << out;
  ASSERT_EQ(runMesochain("run r.toml --json r.json", dir, out), 0) << out;
  const auto c = readJson(dir / "c.json"), r = readJson(dir / "r.json");
  for (const char* e : {"total", "mermin_free"})
    EXPECT_NEAR(r["energies_hartree"][e]["per_atom"].get<double>(), c["energies_hartree"][e]["per_atom"].get<double>(),
                1e-10) << e;
  const auto& fc = c["forces_hartree_per_bohr"];
  const auto& fr = r["forces_hartree_per_bohr"];
  ASSERT_EQ(fr.size(), 4u);
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(fr[a][k].get<double>(), fc[a][k].get<double>(), 1e-8) << a << " " << k;

  // The reduced cell has nothing more to give: no file, exit code 0.
  ASSERT_EQ(runMesochain("reduce r.toml -o again.toml", dir, out), 0) << out;
  EXPECT_NE(out.find("no extra rotational symmetry"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "again.toml"));
}

TEST_F(ReduceCommandLine, BadToleranceIsRefusedNamingTheOption) {
  std::string out;
  ASSERT_EQ(runMesochain("build cnt 5 5 --cell translational --kpoints 2 -o c.toml", dir, out), 0) << out;
  for (const char* tol : {"0", "-1e-5", "1", "abc"}) {
    EXPECT_NE(runMesochain(fmt::format("reduce c.toml -o r.toml --tolerance-bohr {}", tol), dir, out), 0) << tol;
    EXPECT_NE(out.find("--tolerance-bohr"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "r.toml"));
  }
}

}  // namespace
