// The element length of the buckypaper model is a discretisation choice, not physics: a straight
// (10,10) tube of 40 nm built from the 2-nm elements of examples/buckypaper-model.toml and from
// the 4-nm elements of bench/elemlen-2026-12-02/buckypaper-model-4nm.toml (docs/benchmarks.md,
// "The element length") bends, twists and stretches as the same Euler-Bernoulli / axial rod (E I = E pi R^4/4, G J = G pi R^4/2, E A = E pi R^2 of the disc
// section, mass per length 0.0064862 ag / 2 nm). The bond stiffnesses follow from the rest length
// (k = E/L per unit area, BondType::stiffnessFor), so a model file whose length, mass or moduli
// disagree fails: the static cantilever (mdem/cantilever_check.hpp, within 1 %), the first
// bending frequency against the tip-mass cantilever, and the first axial frequency of the
// clamped rod against the continuum with the same tip mass (both within 1 % at these lengths:
// the lumping differs at O((L/l)^2)).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "mdem/cantilever_check.hpp"
#include "mdem/normal_modes.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::mdem {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.678;                    // nm, the (10,10) tube
constexpr double kYoung = 1.0e6, kShear = 0.4e6;     // MPa = pN/nm^2
constexpr double kMassPerLength = 0.0064862 / 2.0;   // ag/nm
constexpr double kTubeLength = 40.0;                 // nm, clamped centre to tip centre

// A clamped straight filament of the model's elements, kTubeLength from the clamped element's
// centre to the tip's, with a tip moment bending it about x and twisting it about z.
Scene cantilever(const std::string& model, double elementLength) {
  const int count = static_cast<int>(std::lround(kTubeLength / elementLength)) + 1;
  const fs::path dir = fs::temp_directory_path() / ("element-length-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "cantilever.toml";
  std::ofstream(file) << "format = 1\nmodel = \"" << std::string(MESOCHAIN_SOURCE_DIR) + "/" + model
                      << "\"\neffects = [\"bonds\", \"local_damping\"]\n\n[[filaments]]\nelement_type = \"cnt1010\"\nbond_type = \"cnt\"\n"
                      << "count = " << count << "\ndirection = [0.0, 0.0, 1.0]\n\n[[fixed]]\nelement = 0\ndofs = [\"all\"]\n\n"
                      << "[[loads]]\nelement = -1\nmoment_pN_nm = [20.0, 0.0, 40.0]\nframe = \"fixed\"\n\n"
                      << "[local_damping]\nalpha = 0.7\n\n[run]\ntime_step_fraction = 0.5\nsteps = 1\n";
  Scene s = loadScene(file.string());
  fs::remove_all(dir);
  return s;
}

// First axial angular frequency (rad/ns) of a rod of length l clamped at one end with a tip mass
// M: beta l tan(beta l) = mu l / M, omega = beta sqrt(E A / mu) (Blevins, Formulas for Natural
// Frequency and Mode Shape, longitudinal rod with a tip mass; pi/2 without it).
double axialFrequencyTheory(double tipMass) {
  const double ratio = kMassPerLength * kTubeLength / tipMass;
  double lo = 1e-9, hi = 0.5 * kPi - 1e-12;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::tan(mid) > ratio ? hi : lo) = mid;
  }
  const double bl = 0.5 * (lo + hi);
  return bl / kTubeLength * std::sqrt(kYoung * kPi * kRadius * kRadius / kMassPerLength);
}

class MdemElementLength : public ::testing::TestWithParam<std::pair<const char*, double>> {};

TEST_P(MdemElementLength, TubeBendsTwistsAndStretchesAsTheSameRod) {
  const auto [model, elementLength] = GetParam();
  const Scene s = cantilever(model, elementLength);
  ASSERT_EQ(s.elementTypes.size(), 1u);
  EXPECT_DOUBLE_EQ(s.elementTypes[0].length, elementLength) << model;
  EXPECT_NEAR(s.elementTypes[0].mass / elementLength, kMassPerLength, 1e-6 * kMassPerLength) << model;

  CantileverTheory theory;
  theory.bendingStiffness = kYoung * kPi * std::pow(kRadius, 4) / 4.0;
  theory.torsionalStiffness = kShear * kPi * std::pow(kRadius, 4) / 2.0;
  theory.massPerLength = kMassPerLength;
  theory.tolerance = 0.01;
  const CantileverCheck c = checkCantilever(s, theory);
  EXPECT_NEAR(c.length, kTubeLength, 1e-9);
  EXPECT_TRUE(c.relaxed) << model;
  ASSERT_EQ(c.quantities.size(), 3u);
  for (const CantileverQuantity& q : c.quantities)
    EXPECT_LT(std::abs(q.relativeDifference()), theory.tolerance) << model << " " << q.name << " " << q.measured
                                                                  << " against " << q.theory;
  EXPECT_NEAR(c.frequency / c.frequencyTheory, 1.0, 0.01) << model << " " << c.frequency << " " << c.frequencyTheory;

  // Axial: every element but the clamped one free along the axis (z) only.
  std::vector<bool> dofs(6 * s.bodies.size(), false);
  for (int i = 1; i < s.bodies.size(); ++i) dofs[6 * i + 2] = true;
  const double omega = eigenfrequencies(s.bodies, s.bonds, dofs)[0];
  const double tipMass = 0.5 * s.bodies.mass[s.bodies.size() - 1];
  EXPECT_NEAR(omega / axialFrequencyTheory(tipMass), 1.0, 0.01) << model << " " << omega;
}

INSTANTIATE_TEST_SUITE_P(TwoAndFourNanometres, MdemElementLength,
                         ::testing::Values(std::make_pair("examples/buckypaper-model.toml", 2.0),
                                           std::make_pair("bench/elemlen-2026-12-02/buckypaper-model-4nm.toml", 4.0)));

}  // namespace
}  // namespace mesochain::mdem
