// The `mesochain beam` workflow: four synthetic scan tables (JSON and CSV) of a known rectangle
// give back its constants and Y, G, h, w within the reported uncertainties; the constants file
// converts its units; bad tables and inconsistent inputs are InputErrors naming file and key.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "beam/beam_run.hpp"
#include "beam_constants_support.hpp"
#include "common/errors.hpp"
#include "tests/support/expect_input_error.hpp"

namespace mesochain::beam {
namespace {

using testing::kG;
using testing::kH;
using testing::kT0;
using testing::kW;
using testing::kY;

BeamConstants truth() { return testing::collapsedTubeConstants(); }

// A scan table of U = -500 + k x^2 / 2 - (k / x_a^2) x^4 with x_a = 40 * step (2 x^2 / x_a^2: 1% anharmonic at
// 2 steps) and small deterministic "noise" (relaxation residue).
std::string scanJson(const std::string& kind, const std::string& direction, double k, double step,
                     const std::string& unit, bool oneSided) {
  std::string pts;
  const double xa = 40.0 * step;
  for (int j = oneSided ? 0 : -8; j <= 8; ++j) {
    const double x = j * step;
    const double e = -500.0 + 0.5 * k * x * x - k / (xa * xa) * x * x * x * x + 1e-9 * std::sin(7.0 * j + 1.0) * k * step * step;
    pts += fmt::format("{}{{\"deformation\": {:.17g}, \"energy_hartree\": {:.17g}, \"converged\": true}}",
                       pts.empty() ? "" : ", ", x, e);
  }
  // An unconverged point far off the curve: must be skipped.
  pts += fmt::format(", {{\"deformation\": {:.17g}, \"energy_hartree\": -400.0, \"converged\": false}}", 0.5 * step);
  return fmt::format(
      "{{\"format\": 1, \"kind\": \"{}\", {} \"T0_bohr\": {}, \"atoms_per_cell\": 120, \"thickness_bohr\": 6.4, "
      "\"deformation_unit\": \"{}\", \"points\": [{}]}}",
      kind, direction.empty() ? "" : "\"direction\": \"" + direction + "\",", kT0, unit, pts);
}

std::vector<ScanCurve> fourCurves() {
  const BeamConstants c = truth();
  return {parseScanJson(scanJson("stretch", "", c.stretch, 0.002, "strain", false), "stretch.json"),
          parseScanJson(scanJson("twist", "", c.twist, 0.01, "rad_per_cell", false), "twist.json"),
          parseScanJson(scanJson("bend", "soft", c.bendSoft, 0.004, "per_bohr", true), "soft.json"),
          parseScanJson(scanJson("bend", "hard", c.bendHard, 0.0005, "per_bohr", true), "hard.json")};
}

TEST(BeamRun, ScanTablesGiveBackTheRectangle) {
  BeamInputs in;
  in.curves = fourCurves();
  in.cellsPerBrick = 5;
  const BeamRun r = runBeam(in);
  const BeamConstants t = truth();
  EXPECT_LE(std::abs(r.constants.stretch - t.stretch), 3.0 * r.uncertainties.stretch + 1e-12);
  EXPECT_LE(std::abs(r.constants.twist - t.twist), 3.0 * r.uncertainties.twist + 1e-12);
  EXPECT_LE(std::abs(r.constants.bendSoft - t.bendSoft), 3.0 * r.uncertainties.bendSoft + 1e-12);
  EXPECT_LE(std::abs(r.constants.bendHard - t.bendHard), 3.0 * r.uncertainties.bendHard + 1e-12);
  EXPECT_EQ(r.beam.closure, "four_constants");
  // Y, G, h, w within three propagated standard uncertainties (the report's, in GPa and nm).
  const auto& u = r.report["beam"]["uncertainty"];
  const double gpa = r.report["beam"]["young_modulus_GPa"].get<double>() / r.beam.young;
  const double nm = r.report["beam"]["thickness_nm"].get<double>() / r.beam.thickness;
  EXPECT_LE(std::abs(r.beam.young - kY) * gpa, 3.0 * u["young_modulus_GPa"].get<double>());
  EXPECT_LE(std::abs(r.beam.shear - kG) * gpa, 3.0 * u["shear_modulus_GPa"].get<double>());
  EXPECT_LE(std::abs(r.beam.thickness - kH) * nm, 3.0 * u["thickness_nm"].get<double>());
  EXPECT_LE(std::abs(r.beam.width - kW) * nm, 3.0 * u["width_nm"].get<double>());
  // ... and the tolerance of the quadratic regime bounds the bias of each constant: a quadratic
  // fit of c x^4 on the grid j = -4..4 shifts k by 2 c beta with beta = 16.4 steps^2, i.e. by
  // 1.03 times the edge anharmonicity 2 c X^2 / k, which the window keeps <= tol.
  EXPECT_NEAR(r.constants.stretch / t.stretch, 1.0, 1.05 * in.tolerance);
  EXPECT_NEAR(r.constants.bendHard / t.bendHard, 1.0, 1.05 * in.tolerance);
  const auto& rep = r.report;
  EXPECT_EQ(rep["constants"]["C_hartree"]["unconverged_points_skipped"], 1);
  EXPECT_TRUE(rep["constants"]["C_hartree"]["linear_term"].get<bool>());
  EXPECT_FALSE(rep["constants"]["D_soft_hartree_bohr2"]["linear_term"].get<bool>());
  // The measured thickness of the tables gives the alternative closure with its D_s residual.
  ASSERT_EQ(r.alternatives.size(), 1u);
  EXPECT_EQ(r.alternatives[0].closure, "measured_thickness");
  const double hRatio = 6.4 / r.beam.thickness;
  EXPECT_NEAR(r.alternatives[0].residuals.bendSoft, hRatio * hRatio - 1.0, 1e-9);
  EXPECT_NEAR(rep["thickness_ratio_fitted_over_measured"].get<double>(), 1.0 / hRatio, 1e-12);
  // Uncertainties propagated to the beam parameters are reported and small.
  const double uY = rep["beam"]["uncertainty"]["young_modulus_GPa"];
  EXPECT_GT(uY, 0.0);
  EXPECT_LT(uY, 0.1 * rep["beam"]["young_modulus_GPa"].get<double>());
  EXPECT_DOUBLE_EQ(rep["brick"]["mass_dalton"].get<double>(), 5 * 120 * 12.011);
  // curveConstant names the constant each curve was fitted into (the key of beam.json).
  for (const ScanCurve& c : in.curves)
    EXPECT_EQ(rep["constants"][curveConstant(c).key]["source"], c.source) << c.label();

  // The closure asked for is the one used.
  in.closure = "measured_thickness";
  const BeamRun m = runBeam(in);
  EXPECT_EQ(m.beam.closure, "measured_thickness");
  EXPECT_EQ(m.report["beam"]["closure"], "measured_thickness");
  EXPECT_DOUBLE_EQ(m.beam.thickness, 6.4);
}

TEST(BeamRun, CsvEqualsJson) {
  const std::string csv =
      "# format = 1\n# kind = bend\n# direction: soft\n# T0_bohr = 4.65\n# atoms_per_cell = 120\n"
      "# deformation_unit = per_bohr\n"
      "deformation,energy_hartree,converged,time_s\n0.0,-10.0,true,1\n0.01,-9.99,true,2\n0.02,-9.96,false,3\n";
  const ScanCurve c = parseScanCsv(csv, "soft.csv");
  const ScanCurve j = parseScanJson(
      R"({"format": 1, "kind": "bend", "direction": "soft", "T0_bohr": 4.65, "atoms_per_cell": 120,
          "deformation_unit": "per_bohr", "points": [
          {"deformation": 0.0, "energy_hartree": -10.0, "converged": true},
          {"deformation": 0.01, "energy_hartree": -9.99, "converged": true},
          {"deformation": 0.02, "energy_hartree": -9.96, "converged": false}]})",
      "soft.json");
  EXPECT_EQ(c.label(), "bend soft");
  EXPECT_EQ(c.label(), j.label());
  ASSERT_EQ(c.points.size(), j.points.size());
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    EXPECT_EQ(c.points[i].deformation, j.points[i].deformation);
    EXPECT_EQ(c.points[i].energy, j.points[i].energy);
    EXPECT_EQ(c.points[i].converged, j.points[i].converged);
  }
}

using mesochain::testing::expectInputError;

TEST(BeamRun, BadTablesAndInputsAreClearErrors) {
  const std::string ok = scanJson("bend", "soft", 1.0, 0.01, "per_bohr", true);
  auto replaced = [&](const std::string& a, const std::string& b) {
    std::string s = ok;
    s.replace(s.find(a), a.size(), b);
    return s;
  };
  expectInputError([&] { parseScanJson(replaced("\"direction\": \"soft\",", ""), "x.json"); }, {"x.json", "direction"});
  expectInputError([&] { parseScanJson(replaced("per_bohr", "strain"), "x.json"); }, {"x.json", "deformation_unit", "per_bohr"});
  expectInputError([&] { parseScanJson(replaced("\"bend\"", "\"shear\""), "x.json"); }, {"x.json", "kind"});
  expectInputError([&] { parseScanJson(replaced("\"T0_bohr\": 4.65", "\"T0_bohr\": -1"), "x.json"); }, {"T0_bohr"});
  expectInputError([&] { parseScanJson("{\"format\": 1,", "x.json"); }, {"x.json", "JSON"});
  expectInputError([&] { readScanTable("/nonexistent/scan.json"); }, {"/nonexistent/scan.json"});

  BeamInputs in;
  in.curves = fourCurves();
  in.curves.push_back(in.curves[0]);
  in.curves.back().source = "again.json";
  in.cellsPerBrick = 2;
  expectInputError([&] { runBeam(in); }, {"again.json", "second stretch curve", "stretch.json"});
  in.curves = fourCurves();
  in.curves.pop_back();
  expectInputError([&] { runBeam(in); }, {"no D_h"});
  in.curves = fourCurves();
  in.curves[1].cellLength = 5.0;
  expectInputError([&] { runBeam(in); }, {"twist.json", "T0_bohr"});
}

TEST(BeamRun, ConstantsFileConvertsUnits) {
  const auto dir = std::filesystem::temp_directory_path() / ("beam-run-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "c.toml").string();
  std::ofstream(path) << "format = 1\nT0_angstrom = 2.46\natoms_per_cell = 120\ncells_per_brick = 8\n"
                         "C_eV = 6770.0\nK_hartree_per_rad2 = 49.6\nD_soft_eV_angstrom2 = 5000\n"
                         "D_hard_hartree_bohr2 = 3.0e5\n";
  BeamInputs in;
  readConstantsFile(path, in);
  EXPECT_NEAR(in.stretch->value, 6770.0 / 27.211386245988, 1e-9);
  EXPECT_NEAR(in.bendSoft->value, 5000.0 / 27.211386245988 / (0.529177210903 * 0.529177210903), 1e-9);
  EXPECT_NEAR(*in.cellLength, 2.46 / 0.529177210903, 1e-12);
  EXPECT_EQ(in.cellsPerBrick, 8);
  const BeamRun r = runBeam(in);
  EXPECT_NEAR(predictConstants(r.beam).bendHard / 3.0e5, 1.0, 1e-12);
  std::ofstream(path) << "format = 1\nC_eV = 1.0\nC_hartree = 2.0\n";
  expectInputError([&] { BeamInputs x; readConstantsFile(path, x); }, {"c.toml", "C_"});
  std::ofstream(path) << "format = 1\nC_joule = 1.0\n";
  expectInputError([&] { BeamInputs x; readConstantsFile(path, x); }, {"c.toml", "C_joule", "unknown"});
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mesochain::beam
