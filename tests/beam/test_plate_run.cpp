// `beam plate`: synthetic bend scans of N = 1..4 layers made from a known rigidity law give back
// each rigidity within its reported uncertainty, D1 from the 1-layer stack, the bonded and
// sliding curves of the plate formula, and the bonded fraction; the plate file converts its
// units; bad plate files are InputErrors naming the file and the key.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "beam/plate.hpp"
#include "beam/plate_run.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::beam {
namespace {

constexpr double kC2 = 0.0288, kZ0 = 6.33, kNu = 0.165, kD1 = 0.0515, kFraction = 0.4;  // Hartree, Bohr
constexpr double kT0 = 8.05, kW = 4.65;  // Bohr: area per cell T0 x w

double lawRigidity(int n) {  // between the two bounds, by a known share of the membrane term
  const double sliding = n * kD1;
  return sliding + kFraction * (plateBendingRigidity(n, kC2, kZ0, kNu, kD1) - sliding);
}

std::string ringJson(int n) {
  const double k = lawRigidity(n) * kT0 * kW;
  std::string pts;
  for (int j = 0; j <= 10; ++j) {
    const double x = 0.003 * j;
    const double e = -50.0 * n + 0.5 * k * x * x * (1.0 - 10.0 * x * x) + 1e-6 * k * std::sin(3.0 * j + n) * 9e-6;
    pts += fmt::format("{}{{\"deformation\": {:.17g}, \"energy_hartree\": {:.17g}}}", pts.empty() ? "" : ", ", x, e);
  }
  return fmt::format(
      "{{\"format\": 1, \"kind\": \"bend\", \"direction\": \"soft\", \"T0_bohr\": {}, \"atoms_per_cell\": {}, "
      "\"width_bohr\": {}, \"deformation_unit\": \"per_bohr\", \"points\": [{}]}}",
      kT0, 4 * n, kW, pts);
}

PlateInputs inputs() {
  PlateInputs in;
  in.inPlaneStiffness = kC2;
  in.spacing = kZ0;
  in.poisson = kNu;
  for (int n = 1; n <= 4; ++n) {
    PlateStack s;
    s.layers = n;
    s.scan = parseScanJson(ringJson(n), fmt::format("ring{}.json", n));
    s.source = "test";
    in.stacks.push_back(s);
  }
  return in;
}

TEST(PlateRun, ScansGiveBackTheRigidityLaw) {
  const PlateRun r = runPlate(inputs());
  ASSERT_EQ(r.stacks.size(), 4u);
  for (const PlateStackResult& s : r.stacks) {
    const double truth = lawRigidity(s.layers);
    EXPECT_GT(s.uncertainty, 0.0);
    EXPECT_LE(std::abs(s.rigidity - truth), 3.0 * s.uncertainty) << s.layers << " layers";
    EXPECT_NEAR(s.rigidity / truth, 1.0, 0.03);
  }
  // D1 comes from the 1-layer stack; the curves are the plate formula (independent sum over
  // layers: sum of C2 z_k^2 with z_k = (k - (N-1)/2) Z0, plate factor 1 / (1 - nu^2)).
  EXPECT_DOUBLE_EQ(r.singleLayer, r.stacks[0].rigidity);
  ASSERT_EQ(r.layers.size(), 6u);  // 1 .. 6 by default
  for (std::size_t i = 0; i < r.layers.size(); ++i) {
    const int n = r.layers[i];
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += kC2 * std::pow((k - 0.5 * (n - 1)) * kZ0, 2);
    EXPECT_NEAR(r.bonded[i], n * r.singleLayer + sum / (1.0 - kNu * kNu), 1e-12 * r.bonded[i]);
    EXPECT_DOUBLE_EQ(r.sliding[i], n * r.singleLayer);
  }
  for (const auto& j : r.report["stacks"]) {
    if (j["layers"].get<int>() == 1) continue;
    EXPECT_NEAR(j["bonded_fraction"].get<double>(), kFraction, 0.03);
    EXPECT_GT(j["ratio_to_sliding"].get<double>(), 1.0);
    EXPECT_LT(j["ratio_to_bonded"].get<double>(), 1.0);
  }
  EXPECT_EQ(r.report["inputs"]["single_layer_rigidity_source"], "the 1-layer stack (ring1.json)");
  // The plot renders (log axis: all values positive).
  const plot::Image img = renderPlatePlot(r);
  EXPECT_EQ(img.width(), 900);
}

TEST(PlateRun, PlateFileConvertsUnitsAndReadsScansBesideIt) {
  const auto dir = std::filesystem::temp_directory_path() / ("plate-run-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "ring2.json") << ringJson(2);
  const std::string path = (dir / "plate.toml").string();
  std::ofstream(path) << "format = 1\nin_plane_stiffness_N_per_m = 340.0\ninterlayer_spacing_angstrom = 3.35\n"
                         "poisson_ratio = 0.165\nsingle_layer_rigidity_eV = 1.4\nmax_layers = 8\n"
                         "[[stack]]\nlayers = 2\nscan = \"ring2.json\"\n"
                         "[[stack]]\nlayers = 3\nrigidity_eV = 150.0\nrigidity_uncertainty_eV = 5.0\n";
  PlateInputs in;
  readPlateFile(path, in);
  // 340 N/m = 340 / 16.02176634 eV/Å^2.
  EXPECT_NEAR(in.inPlaneStiffness * units::kHartreeInEv * std::pow(units::kAngstromInBohr, 2), 340.0 / 16.02176634,
              1e-9);
  EXPECT_NEAR(in.spacing, 3.35 * units::kAngstromInBohr, 1e-12);
  EXPECT_NEAR(in.singleLayer->value, 1.4 / units::kHartreeInEv, 1e-15);
  ASSERT_EQ(in.stacks.size(), 2u);
  EXPECT_EQ(in.stacks[0].scan->source, (dir / "ring2.json").string());
  EXPECT_NEAR(in.stacks[1].rigidity->uncertainty, 5.0 / units::kHartreeInEv, 1e-15);
  const PlateRun r = runPlate(in);
  EXPECT_EQ(r.layers.size(), 8u);
  EXPECT_NEAR(r.report["stacks"][1]["rigidity_eV"].get<double>(), 150.0, 1e-9);
  EXPECT_NEAR(r.report["stacks"][0]["fit"]["area_per_cell_angstrom2"].get<double>(),
              kT0 * kW * std::pow(units::kBohrInAngstrom, 2), 1e-9);

  auto expectError = [&](const std::string& text, std::initializer_list<const char*> fragments) {
    std::ofstream(path) << text;
    try {
      PlateInputs x;
      readPlateFile(path, x);
      runPlate(x);
      ADD_FAILURE() << "no InputError for\n" << text;
    } catch (const InputError& e) {
      const std::string m = e.what();
      for (const char* s : fragments) EXPECT_NE(m.find(s), std::string::npos) << m << " lacks " << s;
    }
  };
  const std::string head = "format = 1\nin_plane_stiffness_eV_per_angstrom2 = 21.2\ninterlayer_spacing_angstrom = 3.35\n";
  expectError(head + "[[stack]]\nlayers = 2\nrigidity_eV = 1.0\n", {"plate.toml", "poisson_ratio"});
  expectError(head + "poisson_ratio = 0.2\n[[stack]]\nlayers = 2\nrigidity_eV = 100.0\n",
              {"plate.toml", "single-layer rigidity", "layers = 1"});
  expectError(head + "poisson_ratio = 0.2\n[[stack]]\nlayers = 1\n", {"plate.toml", "neither a scan nor a rigidity"});
  expectError(head + "poisson_ratio = 0.2\n[[stack]]\nlayers = 1\nrigidity_eV = 1\n[[stack]]\nlayers = 1\nrigidity_eV = 2\n",
              {"plate.toml", "a second stack of 1 layers"});
  expectError(head + "poisson_ratio = 0.2\n[[stack]]\nlayer = 1\n", {"plate.toml", "layer", "unknown key"});
  expectError(head + "poisson_ratio = 0.2\nC2 = 3\n", {"plate.toml", "C2", "unknown key"});
  expectError(head + "poisson_ratio = 0.2\n[[stack]]\nlayers = 1\nrigidity_eV = 1\ninterlayer_spacing_angstrom = -3\n",
              {"plate.toml", "interlayer_spacing_angstrom", "> 0"});

  // A stack's own (measured) spacing sets its bonded bound: the membrane term scales as Z^2.
  std::ofstream(path) << head + "poisson_ratio = 0.2\nsingle_layer_rigidity_eV = 1.4\n"
                                "[[stack]]\nlayers = 4\nrigidity_eV = 1000\ninterlayer_spacing_angstrom = 3.30\n"
                                "[[stack]]\nlayers = 3\nrigidity_eV = 500\n";
  PlateInputs own;
  readPlateFile(path, own);
  const PlateRun ownRun = runPlate(own);
  const auto& four = ownRun.report["stacks"][1];
  const auto& three = ownRun.report["stacks"][0];
  EXPECT_NEAR(four["interlayer_spacing_angstrom"].get<double>(), 3.30, 1e-12);
  EXPECT_NEAR(three["interlayer_spacing_angstrom"].get<double>(), 3.35, 1e-12);
  const double membrane4 = (four["bonded_eV"].get<double>() - 4 * 1.4);
  const double curve4 = ownRun.bonded[3] * units::kHartreeInEv - 4 * 1.4;  // the curve keeps Z0
  EXPECT_NEAR(membrane4 / curve4, std::pow(3.30 / 3.35, 2), 1e-12);
  EXPECT_NEAR(three["bonded_eV"].get<double>(), ownRun.bonded[2] * units::kHartreeInEv, 1e-9);
  expectError(head + "poisson_ratio = 0.2\n[[stack]]\nlayers = 1\nscan = \"missing.json\"\n", {"missing.json"});
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mesochain::beam
