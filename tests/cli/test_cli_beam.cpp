// `mesochain beam` and `mesochain beam plate` end to end, as a user runs them: synthetic scan
// tables made here from known constants -> the program -> beam.json / plate.json hold those
// constants within the uncertainties they report, and the PNGs they list are valid images.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "beam/plate.hpp"
#include "common/plot/png_io.hpp"

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct TempDir {
  fs::path path = fs::temp_directory_path() / fmt::format("cli-beam-{}-{}", ::getpid(), counter()++);
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  static int& counter() {
    static int n = 0;
    return n;
  }
};

using mesochain::testing::readJson;

// The program in the folder of `log` (absolute paths in args).
int run(const std::string& args, const fs::path& log, std::string& output) {
  return mesochain::testing::runMesochain(args, log.parent_path(), output);
}

// A scan of U = U0 + k x^2 / 2 (1 - x^2 / xa^2) with a deterministic relaxation-like scatter.
std::string scanTable(const std::string& kind, const std::string& direction, const std::string& unit, double k,
                      double step, bool oneSided, double t0, double width = NAN) {
  std::string pts;
  const double xa = 60.0 * step;
  for (int j = oneSided ? 0 : -8; j <= 8; ++j) {
    const double x = j * step;
    const double e = -480.0 + 0.5 * k * x * x * (1.0 - x * x / (xa * xa)) + 2e-4 * k * step * step * std::sin(5.3 * j + 0.7);
    pts += fmt::format("{}{{\"deformation\": {:.17g}, \"energy_hartree\": {:.17g}, \"converged\": true, \"time_s\": 1.5}}",
                       pts.empty() ? "" : ", ", x, e);
  }
  std::string extra = direction.empty() ? "" : fmt::format("\"direction\": \"{}\", ", direction);
  if (!std::isnan(width)) extra += fmt::format("\"width_bohr\": {}, ", width);
  return fmt::format(
      "{{\"format\": 1, \"kind\": \"{}\", {}\"T0_bohr\": {}, \"atoms_per_cell\": 120, \"deformation_unit\": \"{}\", "
      "\"points\": [{}]}}",
      kind, extra, t0, unit, pts);
}

void expectValidPng(const std::string& path, int width, int height) {
  ASSERT_TRUE(fs::is_regular_file(path)) << path;
  const mesochain::plot::Image img = mesochain::plot::readPng(path);  // throws if not a PNG
  EXPECT_EQ(img.width(), width) << path;
  EXPECT_EQ(img.height(), height) << path;
  // Not blank: some ink on the white background.
  long ink = 0;
  for (int y = 0; y < img.height(); y += 2)
    for (int x = 0; x < img.width(); x += 2) ink += !(img.at(x, y) == mesochain::plot::Color{255, 255, 255});
  EXPECT_GT(ink, 1000) << path;
}

TEST(CliBeam, ScanTablesToBeamJsonAndPlots) {
  TempDir dir;
  // A rectangle h x w with moduli Y, G (atomic units), per cell of T0.
  const double t0 = 4.65, h = 2.2, w = 36.0, Y = 0.03, G = 0.011;
  const double C = Y * h * w * t0, K = G * (h * w * w * w + w * h * h * h) / 12.0 / t0;
  const double Ds = Y * w * h * h * h / 12.0 * t0, Dh = Y * h * w * w * w / 12.0 * t0;
  const struct {
    const char* file;
    std::string text;
    const char* key;
    double truth;
  } curves[] = {
      {"stretch.json", scanTable("stretch", "", "strain", C, 0.002, false, t0), "C_hartree", C},
      {"twist.json", scanTable("twist", "", "rad_per_cell", K, 0.01, false, t0), "K_hartree_per_rad2", K},
      {"soft.json", scanTable("bend", "soft", "per_bohr", Ds, 0.004, true, t0), "D_soft_hartree_bohr2", Ds},
      {"hard.json", scanTable("bend", "hard", "per_bohr", Dh, 0.0005, true, t0), "D_hard_hartree_bohr2", Dh}};
  std::string files;
  for (const auto& c : curves) {
    std::ofstream(dir.path / c.file) << c.text;
    files.append(" ").append((dir.path / c.file).string());
  }
  const fs::path out = dir.path / "out";
  std::string log;
  ASSERT_EQ(run(fmt::format("beam{} -n 4 -o {}", files, out.string()), dir.path / "log.txt", log), 0) << log;

  const json rep = readJson(out / "beam.json");
  for (const auto& c : curves) {
    const json& k = rep["constants"][c.key];
    const double value = k["value"], sigma = k["uncertainty"];
    EXPECT_GT(sigma, 0.0) << c.key;
    EXPECT_LT(sigma, 0.05 * value) << c.key;
    EXPECT_LE(std::abs(value - c.truth), 3.0 * sigma) << c.key << ": " << value << " vs " << c.truth;
    expectValidPng(k["plot"].get<std::string>(), 900, 1000);
  }
  const json& plots = rep["files"]["plots"];
  ASSERT_EQ(plots.size(), 4u);
  for (const auto& p : plots) EXPECT_TRUE(fs::is_regular_file(p.get<std::string>()));
  EXPECT_TRUE(fs::is_regular_file(out / "model.toml"));
  EXPECT_NE(log.find("fit-bend-soft.png"), std::string::npos) << log;
  // The beam back: Y and h within three propagated uncertainties.
  const json& b = rep["beam"];
  const double gpa = b["young_modulus_GPa"].get<double>() / b["young_modulus_hartree_per_bohr3"].get<double>();
  EXPECT_LE(std::abs(b["young_modulus_GPa"].get<double>() - Y * gpa), 3.0 * b["uncertainty"]["young_modulus_GPa"].get<double>());
  EXPECT_LE(std::abs(b["thickness_bohr"].get<double>() - h) * (b["thickness_nm"].get<double>() / b["thickness_bohr"].get<double>()),
            3.0 * b["uncertainty"]["thickness_nm"].get<double>());
}

TEST(CliBeam, RefusedCurveNamesItsFile) {
  TempDir dir;
  std::ofstream(dir.path / "short.json")
      << R"({"format": 1, "kind": "stretch", "T0_bohr": 4.65, "atoms_per_cell": 120, "deformation_unit": "strain",
            "points": [{"deformation": 0.0, "energy_hartree": -1.0}, {"deformation": 0.01, "energy_hartree": -0.99}]})";
  std::string log;
  EXPECT_EQ(run(fmt::format("beam {} -n 4 -o {}", (dir.path / "short.json").string(), (dir.path / "out").string()),
                dir.path / "log.txt", log),
            2);
  EXPECT_NE(log.find("short.json"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir.path / "out" / "beam.json"));
}

TEST(CliBeam, PlateFromRingScans) {
  TempDir dir;
  // Plate rigidities of N = 1..3 layers between the bounds (a third of the membrane term), per
  // cell of area T0 x w; atomic units.
  const double c2 = 0.0288, z0 = 6.33, nu = 0.165, d1 = 0.0515, t0 = 8.05, w = 4.65;
  std::string toml = fmt::format(
      "format = 1\nin_plane_stiffness_eV_per_angstrom2 = {:.17g}\ninterlayer_spacing_bohr = {:.17g}\n"
      "poisson_ratio = {}\n",
      c2 * 27.211386245988 / (0.529177210903 * 0.529177210903), z0, nu);
  double truth[4] = {};
  for (int n = 1; n <= 3; ++n) {
    const double sliding = n * d1;
    truth[n] = sliding + (mesochain::beam::plateBendingRigidity(n, c2, z0, nu, d1) - sliding) / 3.0;
    std::ofstream(dir.path / fmt::format("ring{}.json", n))
        << scanTable("bend", "soft", "per_bohr", truth[n] * t0 * w, 0.003, true, t0, w);
    toml += fmt::format("[[stack]]\nlayers = {}\nscan = \"ring{}.json\"\n", n, n);
  }
  std::ofstream(dir.path / "plate.toml") << toml;
  const fs::path out = dir.path / "plate-out";
  std::string log;
  ASSERT_EQ(run(fmt::format("beam plate {} -o {}", (dir.path / "plate.toml").string(), out.string()),
                dir.path / "log.txt", log),
            0)
      << log;
  const json rep = readJson(out / "plate.json");
  ASSERT_EQ(rep["stacks"].size(), 3u);
  for (const json& s : rep["stacks"]) {
    const int n = s["layers"];
    const double d = s["rigidity_eV"], sigma = s["uncertainty_eV"];
    EXPECT_LE(std::abs(d - truth[n] * 27.211386245988), 3.0 * sigma) << n << " layers";
    if (n > 1) {
      EXPECT_NEAR(s["bonded_fraction"].get<double>(), 1.0 / 3.0, 0.02);
    }
    expectValidPng(s["plot"].get<std::string>(), 900, 1000);
  }
  expectValidPng(rep["files"]["plot"].get<std::string>(), 900, 650);
}

}  // namespace
