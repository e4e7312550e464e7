// `mesochain chain` end to end on a (5,5) tube (seconds): a stopped chain resumes where its
// scan checkpoint left off, finished stages are skipped, a changed stage reruns alone, and the
// report's constants are those of `mesochain beam` run by hand on the stages' curves.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using mesochain::testing::readJson;
using mesochain::testing::runMesochain;

std::string chainFile(const std::string& orders) {
  return fmt::format(
      "format = 1\ncell = \"cnt55t.toml\"\nforce_tolerance = 1e-4\ncells_per_brick = 4\n"
      "[stretch]\nstrains = [-0.01, -0.005, 0.005, 0.01]\n"
      "[twist]\ntwist_deg_per_cell = [-0.4, -0.2, 0.2, 0.4]\n"
      "[bend_soft]\nrotation_orders = {}\nring_angular = 4\n",
      orders);
}

std::string status(const json& report, const std::string& stage) {
  for (const json& s : report["stages"])
    if (s["stage"] == stage) return s["status"].get<std::string>();
  return "missing";
}

TEST(CliChain, StagesResumeSkipAndMatchTheHandRunBeam) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cli-chain-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string out;
  ASSERT_EQ(runMesochain("build cnt 5 5 --cell translational --task energy --kpoints 8 -o cnt55t.toml", dir, out), 0)
      << out;
  std::ofstream(dir / "chain.toml") << chainFile("[1280, 640]");
  // Interrupted inside the first scan: exit 4, no report yet.
  ASSERT_EQ(runMesochain("chain chain.toml --stop-after 3", dir, out), 4) << out;
  EXPECT_FALSE(fs::exists(dir / "chain-out" / "chain.json"));
  EXPECT_TRUE(fs::exists(dir / "chain-out" / "stretch.checkpoint.json"));
  // Rerun: the stretch continues from its checkpoint, the others run.
  ASSERT_EQ(runMesochain("chain chain.toml", dir, out), 0) << out;
  const json first = readJson(dir / "chain-out" / "chain.json");
  EXPECT_EQ(status(first, "stretch"), "resumed");
  EXPECT_EQ(status(first, "twist"), "ran");
  EXPECT_EQ(status(first, "bend_soft"), "ran");
  for (const json& s : first["stages"])
    if (s["stage"] == "stretch") {
      EXPECT_EQ(s["points_restored"].get<int>(), 3);
    }
  EXPECT_TRUE(fs::exists(dir / "chain-out" / "chain.md"));
  EXPECT_TRUE(fs::exists(dir / "chain-out" / "beam" / "cantilever.toml"));

  // The hand-run beam on the same curves gives the same constants.
  ASSERT_EQ(runMesochain("beam chain-out/stretch.json chain-out/twist.json chain-out/bend_soft.json -n 4 --section circle "
                         "-o hand",
                         dir, out),
            0)
      << out;
  const json hand = readJson(dir / "hand" / "beam.json");
  for (const char* key : {"C_hartree", "K_hartree_per_rad2", "D_soft_hartree_bohr2"}) {
    EXPECT_DOUBLE_EQ(first["constants"][key]["value"].get<double>(), hand["constants"][key]["value"].get<double>()) << key;
    EXPECT_DOUBLE_EQ(first["constants"][key]["uncertainty"].get<double>(),
                     hand["constants"][key]["uncertainty"].get<double>())
        << key;
  }
  EXPECT_DOUBLE_EQ(first["brick"]["k_n_MPa_per_nm"].get<double>(), hand["brick"]["k_n_MPa_per_nm"].get<double>());

  // Nothing changed: every scan is skipped, the constants are the same.
  ASSERT_EQ(runMesochain("chain chain.toml", dir, out), 0) << out;
  const json again = readJson(dir / "chain-out" / "chain.json");
  for (const char* s : {"stretch", "twist", "bend_soft"}) EXPECT_EQ(status(again, s).rfind("skipped", 0), 0u) << s;
  EXPECT_EQ(again["constants"], first["constants"]);

  // Another ring list: the bend reruns alone.
  std::ofstream(dir / "chain.toml") << chainFile("[2560, 1280]");
  ASSERT_EQ(runMesochain("chain chain.toml", dir, out), 0) << out;
  const json changed = readJson(dir / "chain-out" / "chain.json");
  EXPECT_EQ(status(changed, "stretch").rfind("skipped", 0), 0u);
  EXPECT_EQ(status(changed, "bend_soft"), "ran");
  EXPECT_NE(changed["constants"]["D_soft_hartree_bohr2"]["value"], first["constants"]["D_soft_hartree_bohr2"]["value"]);
  fs::remove_all(dir);
}

TEST(CliChain, BadChainFileNamesTheKey) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cli-chain-bad-{}", ::getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "bad.toml") << "format = 1\ncell = \"x.toml\"\ncells_per_brick = 4\n[strech]\nstrains = [0.01]\n";
  std::string out;
  EXPECT_EQ(runMesochain("chain bad.toml", dir, out), 2);
  EXPECT_NE(out.find("strech"), std::string::npos) << out;
  EXPECT_NE(out.find("[stretch]"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
