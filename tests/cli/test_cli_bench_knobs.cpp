// `mesochain bench knobs` end to end on tiny finished scans made here: a (5,5) helical stretch
// and twist (5 points each) and an (8,0) bend (the straight reference and two rings, T = 0). The structures
// re-evaluated at the scan's own settings reproduce the curve: the scan-setting row's constant
// equals the constant the beam fitter gets from the curve JSON itself, and a curve energy
// shifted on purpose shows up as exactly that difference in the consistency check. Another
// k-point count changes the constant (the knob is applied); --compare-curve reports the other
// curve's fit and its time from the JSON; missing structures and bad knob values are clear
// errors.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "beam/beam_run.hpp"
#include "beam/scan_table.hpp"
#include "common/plot/png_io.hpp"

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using mesochain::testing::readJson;
using mesochain::testing::slurp;

int run(const std::string& args, const fs::path& dir, std::string& output) {
  return mesochain::testing::runMesochain(args, dir, output);
}


const char* kCnt55 =
    "format = 1\n[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\n"
    "bond_length = 1.42\n[kpoints]\nhelical = 32\nangular = \"all\"\n"
    "[electrons]\ntemperature = 300.0\n[parameters]\nset = \"pbc-0-3\"\n";
const char* kCnt80 =
    "format = 1\n[builder]\ntype = \"nanotube\"\nn = 8\nm = 0\ncell = \"translational\"\n"
    "[kpoints]\nhelical = 8\n[electrons]\ntemperature = 300.0\n[parameters]\nset = \"pbc-0-3\"\n";

std::string stretchScan(const std::string& name, double tolerance, bool structures) {
  return fmt::format(
      "format = 1\ncell = \"cnt55.toml\"\nkind = \"stretch\"\n"
      "strains = [-0.01, -0.005, 0.005, 0.01]\n[relax]\nforce_tolerance = {}\n"
      "relax_translation = true\n[output]\njson = \"{}.json\"\n{}",
      tolerance, name, structures ? fmt::format("structures = \"{}\"\n", name) : "");
}

// The stretch scans (~0.3 s each) are run once for the suite; the bend (~3 s) in its test.
class BenchKnobs : public ::testing::Test {
 protected:
  static fs::path dir;
  static void SetUpTestSuite() {
    dir = fs::temp_directory_path() / fmt::format("cli-bench-knobs-{}", ::getpid());
    fs::create_directories(dir);
    std::ofstream(dir / "cnt55.toml") << kCnt55;
    std::ofstream(dir / "cnt80.toml") << kCnt80;
    std::ofstream(dir / "stretch.toml") << stretchScan("stretch", 1e-5, true);
    std::ofstream(dir / "stretch-loose.toml") << stretchScan("stretch-loose", 1e-3, false);
    std::string out;
    for (const char* scan : {"stretch.toml", "stretch-loose.toml"})
      ASSERT_EQ(run(fmt::format("scan {}", scan), dir, out), 0) << out;
  }
  static void TearDownTestSuite() { fs::remove_all(dir); }

  // The constant of `mesochain beam` (same fitter, same options) from a curve JSON.
  static double fittedFromCurve(const fs::path& curve) {
    const mesochain::beam::ScanCurve c = mesochain::beam::readScanTable(curve.string());
    const std::string q = c.kind == "stretch" ? "C" : "D_s";
    return mesochain::beam::fitScanCurve(c, q, q, 0.02, "auto", false).fit.stiffness;
  }
  static const json& row(const json& report, const std::string& knob, const std::string& setting) {
    for (const json& r : report.at("rows"))
      if (r.at("knob") == knob && r.at("setting").get<std::string>().rfind(setting, 0) == 0) return r;
    throw std::runtime_error("no row " + knob + " " + setting);
  }
};
fs::path BenchKnobs::dir;

TEST_F(BenchKnobs, StretchAtTheScanSettingsReproducesTheCurve) {
  std::string out;
  ASSERT_EQ(run("bench knobs stretch.toml --kpoints 8,64 --temperature 1000 --forces "
                "--json knobs.json --csv knobs.csv --png knobs.png",
                dir, out),
            0)
      << out;
  const json r = readJson(dir / "knobs.json");
  EXPECT_LT(r.at("max_abs_energy_difference_hartree").get<double>(), 1e-9);
  const double direct = fittedFromCurve(dir / "stretch.json");
  const json& own = row(r, "kpoints", "32");
  EXPECT_TRUE(own.at("scan_setting").get<bool>());
  EXPECT_NEAR(own.at("constant").get<double>(), direct, 1e-9 * direct);
  EXPECT_NEAR(row(r, "temperature", "300").at("constant").get<double>(), direct, 1e-9 * direct);
  // The knob is applied: 8 kappa points give another constant (metallic tube: ~10 %).
  const double c8 = row(r, "kpoints", "8").at("constant").get<double>();
  EXPECT_GT(std::abs(c8 / direct - 1), 1e-4);
  // The most accurate setting is the reference: 64 kappa points, the lower temperature.
  EXPECT_TRUE(row(r, "kpoints", "64").at("reference").get<bool>());
  EXPECT_TRUE(row(r, "temperature", "300").at("reference").get<bool>());
  EXPECT_NEAR(row(r, "kpoints", "8").at("relative_difference").get<double>(),
              c8 / row(r, "kpoints", "64").at("constant").get<double>() - 1, 1e-12);
  EXPECT_EQ(r.at("rows").size(), 5u);
  // --forces: at the scan's settings the largest force is the one the scan reported for its
  // relaxed points; at 8 kappa points the same atoms are no longer relaxed.
  double scanForce = 0;
  const json curve = readJson(dir / "stretch.json");
  for (const json& p : curve.at("points"))
    scanForce = std::max(scanForce, p.at("max_force_hartree_per_bohr").get<double>());
  const double ownForce = own.at("max_force_hartree_per_bohr").get<double>();
  EXPECT_NEAR(ownForce, scanForce, 1e-6 * scanForce);
  EXPECT_LE(ownForce, 1e-5);
  EXPECT_GT(row(r, "kpoints", "8").at("max_force_hartree_per_bohr").get<double>(), 10 * ownForce);
  const mesochain::plot::Image png = mesochain::plot::readPng((dir / "knobs.png").string());
  EXPECT_EQ(png.width(), 900);
  EXPECT_EQ(png.height(), 600);
  // RFC 4180: a plain field unquoted (common/csv.hpp).
  EXPECT_NE(slurp(dir / "knobs.csv").find("\nkpoints,8,false,false,"), std::string::npos);
}

TEST_F(BenchKnobs, TheConsistencyCheckSeesAShiftedCurveEnergy) {
  json curve = readJson(dir / "stretch.json");
  curve["points"][3]["energy_hartree"] = curve["points"][3]["energy_hartree"].get<double>() + 2.5e-6;
  std::ofstream(dir / "shifted.json") << curve.dump(2);
  std::string scan = stretchScan("stretch", 1e-5, true);
  scan.replace(scan.find("json = \"stretch.json\""), 21, "json = \"shifted.json\"");
  std::ofstream(dir / "shifted.toml") << scan;
  std::string out;
  ASSERT_EQ(run("bench knobs shifted.toml --json shifted-knobs.json", dir, out), 0) << out;
  EXPECT_NEAR(readJson(dir / "shifted-knobs.json").at("max_abs_energy_difference_hartree").get<double>(),
              2.5e-6, 1e-9);
  EXPECT_NE(out.find("warning: the re-evaluated energies differ"), std::string::npos) << out;
}

TEST_F(BenchKnobs, RingsAtTheScanSettingsReproduceTheCurve) {
  std::ofstream(dir / "bend.toml")
      << "format = 1\ncell = \"cnt80.toml\"\nkind = \"bend\"\nrotation_orders = [640, 320]\n"
         "ring_angular = 4\n[relax]\nforce_tolerance = 1e-4\n[output]\njson = \"bend.json\"\n"
         "structures = \"bend\"\n";
  std::string out;
  ASSERT_EQ(run("scan bend.toml", dir, out), 0) << out;
  ASSERT_EQ(run("bench knobs bend.toml --angular 8,all --kpoints 16 --json bend-knobs.json", dir, out), 0)
      << out;
  const json r = readJson(dir / "bend-knobs.json");
  EXPECT_EQ(r.at("points").get<int>(), 3);
  EXPECT_LT(r.at("max_abs_energy_difference_hartree").get<double>(), 1e-9);
  const double direct = fittedFromCurve(dir / "bend.json");
  EXPECT_NEAR(row(r, "angular", "4").at("constant").get<double>(), direct, 1e-9 * direct);
  EXPECT_TRUE(row(r, "angular", "all").at("reference").get<bool>());
  // Ring samples alone: the straight reference keeps its 8 kappa points, so the rings' Bloch
  // phases no longer match it and the bend energies carry a sampling offset. The bend fit is
  // anchored at the reference (docs/beam.md), so the offset shows as a drifting secant and the
  // fit is refused, naming it, instead of being absorbed by a free U(0).
  for (const char* setting : {"8", "all"}) {
    EXPECT_TRUE(row(r, "angular", setting).at("constant").is_null()) << setting;
    EXPECT_NE(row(r, "angular", setting).at("note").get<std::string>().find("the secant"), std::string::npos)
        << setting;
  }
  // The rings have one kappa point: the knob reaches the straight reference only.
  EXPECT_NE(out.find("only the straight points depend on this knob"), std::string::npos) << out;
  // Joint sampling (straight kappa points K with ring samples M): the scan's own pair (8:4)
  // reproduces the curve's constant; another pair changes it; K alone is not a pair.
  ASSERT_EQ(run("bench knobs bend.toml --sampling 4:2,16:8 --json bend-sampling.json", dir, out), 0)
      << out;
  const json j = readJson(dir / "bend-sampling.json");
  EXPECT_NEAR(row(j, "sampling", "8:4").at("constant").get<double>(), direct, 1e-9 * direct);
  EXPECT_TRUE(row(j, "sampling", "16:8").at("reference").get<bool>());
  EXPECT_NE(row(j, "sampling", "4:2").at("constant").get<double>(), direct);
  EXPECT_NE(run("bench knobs bend.toml --sampling 16", dir, out), 0);
  EXPECT_NE(out.find("--sampling: found '16'"), std::string::npos) << out;
}

TEST_F(BenchKnobs, CompareCurveReportsTheOtherScanAndItsTime) {
  std::string out;
  ASSERT_EQ(run("bench knobs stretch.toml --compare-curve stretch-loose.json --json cmp.json", dir, out), 0)
      << out;
  const json r = readJson(dir / "cmp.json");
  const json& loose = row(r, "relaxation", "stretch-loose.json");
  const json& tight = row(r, "relaxation", "stretch.json");
  EXPECT_TRUE(tight.at("reference").get<bool>());
  EXPECT_TRUE(tight.at("scan_setting").get<bool>());
  const double cLoose = fittedFromCurve(dir / "stretch-loose.json");
  EXPECT_NEAR(loose.at("constant").get<double>(), cLoose, 1e-12 * cLoose);
  double seconds = 0;
  int evaluations = 0;
  const json looseCurve = readJson(dir / "stretch-loose.json");
  for (const json& p : looseCurve.at("points")) {
    seconds += p.at("time_s").get<double>();
    evaluations += p.at("evaluations").get<int>();
  }
  EXPECT_NEAR(loose.at("total_wall_s").get<double>(), seconds, 1e-12);
  EXPECT_EQ(loose.at("evaluations").get<int>(), evaluations);
  // A curve of another kind is refused, naming it.
  json twist = readJson(dir / "stretch-loose.json");
  twist["kind"] = "twist";
  twist["deformation_unit"] = "rad_per_cell";
  std::ofstream(dir / "wrong-kind.json") << twist.dump();
  EXPECT_NE(run("bench knobs stretch.toml --compare-curve wrong-kind.json", dir, out), 0);
  EXPECT_NE(out.find("wrong-kind.json"), std::string::npos) << out;
}

TEST_F(BenchKnobs, MissingOrMismatchedStructuresAreClearErrors) {
  std::string out;
  // No [output] structures in the scan file.
  EXPECT_NE(run("bench knobs stretch-loose.toml", dir, out), 0);
  EXPECT_NE(out.find("structures"), std::string::npos) << out;
  // A prefix whose files do not exist: the error names the first missing file.
  std::string scan = stretchScan("stretch", 1e-5, true);
  scan.replace(scan.find("structures = \"stretch\""), 22, "structures = \"nothere\"");
  std::ofstream(dir / "nothere.toml") << scan;
  EXPECT_NE(run("bench knobs nothere.toml", dir, out), 0);
  EXPECT_NE(out.find("nothere-000.xyz"), std::string::npos) << out;
  EXPECT_EQ(out.find("terminate"), std::string::npos) << out;
  // One structure too many.
  fs::copy_file(dir / "stretch-000.xyz", dir / "stretch-005.xyz", fs::copy_options::overwrite_existing);
  EXPECT_NE(run("bench knobs stretch.toml", dir, out), 0);
  EXPECT_NE(out.find("stretch-005.xyz"), std::string::npos) << out;
  fs::remove(dir / "stretch-005.xyz");
  // Structures in the wrong order: the deformation of point 2 is not the curve's.
  scan.replace(scan.find("structures = \"nothere\""), 22, "structures = \"swapped\"");
  std::ofstream(dir / "swapped.toml") << scan;
  for (int k = 0; k < 5; ++k)
    fs::copy_file(dir / fmt::format("stretch-{:03d}.xyz", k == 1 ? 0 : k == 0 ? 1 : k),
                  dir / fmt::format("swapped-{:03d}.xyz", k), fs::copy_options::overwrite_existing);
  EXPECT_NE(run("bench knobs swapped.toml", dir, out), 0);
  EXPECT_NE(out.find("swapped-000.xyz"), std::string::npos) << out;
  EXPECT_NE(out.find("deformation"), std::string::npos) << out;
}

TEST_F(BenchKnobs, BadKnobValuesAreClearErrors) {
  std::string out;
  EXPECT_NE(run("bench knobs stretch.toml --kpoints 0", dir, out), 0);
  EXPECT_NE(out.find("--kpoints: found '0'"), std::string::npos) << out;
  EXPECT_NE(run("bench knobs stretch.toml --kpoints 12,x", dir, out), 0);
  EXPECT_NE(out.find("--kpoints: found 'x'"), std::string::npos) << out;
  // Checked even where the knob does not apply (no dispersion in this cell file).
  EXPECT_NE(run("bench knobs stretch.toml --dispersion foo:3", dir, out), 0);
  EXPECT_NE(out.find("--dispersion: found 'foo:3'"), std::string::npos) << out;
  EXPECT_NE(run("bench knobs stretch.toml --angular=-2", dir, out), 0);
  EXPECT_NE(out.find("--angular"), std::string::npos) << out;
  EXPECT_NE(run("bench knobs stretch.toml --temperature 0", dir, out), 0);
  EXPECT_NE(out.find("--temperature: found '0'"), std::string::npos) << out;
  for (const std::string& o : {std::string("terminate"), std::string("Segmentation")})
    EXPECT_EQ(out.find(o), std::string::npos) << out;
}

TEST_F(BenchKnobs, TwistAtTheScanSettingsReproducesTheCurve) {
  // The structures' twists minus the reference's give the curve's deformations (rad per cell).
  std::ofstream(dir / "twist.toml")
      << "format = 1\ncell = \"cnt55.toml\"\nkind = \"twist\"\n"
         "twist_deg_per_cell = [-0.5, -0.25, 0.25, 0.5]\n[relax]\nforce_tolerance = 1e-5\n"
         "[output]\njson = \"twist.json\"\nstructures = \"twist\"\n";
  std::string out;
  ASSERT_EQ(run("scan twist.toml", dir, out), 0) << out;
  ASSERT_EQ(run("bench knobs twist.toml --kpoints 128 --json twist-knobs.json", dir, out), 0) << out;
  const json r = readJson(dir / "twist-knobs.json");
  EXPECT_LT(r.at("max_abs_energy_difference_hartree").get<double>(), 1e-9);
  const mesochain::beam::ScanCurve c = mesochain::beam::readScanTable((dir / "twist.json").string());
  const double direct = mesochain::beam::fitScanCurve(c, "K", "K", 0.02, "auto", false).fit.stiffness;
  EXPECT_NEAR(row(r, "kpoints", "32").at("constant").get<double>(), direct, 1e-9 * direct);
}

TEST_F(BenchKnobs, ACurveTheFitterRefusesIsAClearError) {
  // Three points: the stretch fit (with its linear term) needs four.
  std::ofstream(dir / "three.toml")
      << "format = 1\ncell = \"cnt55.toml\"\nkind = \"stretch\"\nstrains = [-0.005, 0.005]\n"
         "[output]\njson = \"three.json\"\nstructures = \"three\"\n";
  std::string out;
  ASSERT_EQ(run("scan three.toml", dir, out), 0) << out;
  EXPECT_NE(run("bench knobs three.toml --kpoints 16", dir, out), 0);
  EXPECT_NE(out.find("three.json, the curve of the scan"), std::string::npos) << out;
  EXPECT_NE(out.find("too few points"), std::string::npos) << out;
}

}  // namespace
