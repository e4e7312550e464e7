// Bricks and their mDEM export: the inertia of the block matches a direct sum over point
// masses filling it; the unit constants match CODATA's atomic units; the exported model and
// cantilever scene, read by mdem's own reader, give the same k_n, k_s, mass, inertia and
// section; and the static cantilever twists and bends as the per-cell constants K and D_s say
// (phi = M N_cells / K and phi = M N_cells T0^2 / D_s in atomic units).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "beam/beam_model.hpp"
#include "beam_constants_support.hpp"
#include "beam/brick.hpp"
#include "beam/mdem_export.hpp"
#include "common/units.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::beam {
namespace {

namespace fs = std::filesystem;

using testing::collapsedTubeConstants;

TEST(BeamBrick, InertiaMatchesASumOverPointMasses) {
  const Beam beam = rectangleMeasuredThickness(collapsedTubeConstants(), 6.4, "test");
  const int n = 5;
  const double cellMass = 120 * units::si::kCarbonMassDalton;
  const Brick b = discretise(beam, n, cellMass, "test");
  EXPECT_DOUBLE_EQ(b.length, n * beam.cellLength);
  EXPECT_DOUBLE_EQ(b.mass, n * cellMass);
  EXPECT_DOUBLE_EQ(b.normalStiffness, beam.young / b.length);
  EXPECT_DOUBLE_EQ(b.shearStiffness, beam.shear / b.length);
  // Equal point masses at the centres of an M^3 grid of sub-blocks: sum m_i (y^2 + z^2), ...
  const int m = 60;
  const double ext[3] = {beam.thickness, beam.width, b.length};
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const double mi = b.mass / (double(m) * m * m);
  std::vector<double> c[3];
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < m; ++k) c[a].push_back((k + 0.5) / m * ext[a] - 0.5 * ext[a]);
  for (double x : c[0])
    for (double y : c[1])
      for (double z : c[2]) sum += mi * Eigen::Vector3d(y * y + z * z, x * x + z * z, x * x + y * y);
  // The midpoint sum of x^2 over M cells of [-a/2, a/2] is M a^2 (1 - 1/M^2) / 12: the sum
  // falls short of the integral by exactly the relative amount 1 / M^2 on every axis.
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(sum[a] / b.inertia[a], 1.0 - 1.0 / (m * m), 1e-12) << a;
}

TEST(BeamBrick, RoundBeamBecomesAnEquivalentCylinder) {
  BeamConstants c;
  c.cellLength = 4.65;
  const double r = 12.8, t = 6.4, y = 0.03, g = 0.012, pi = 3.14159265358979323846;
  const double i = pi * r * t * (r * r + t * t / 4.0);
  c.stretch = y * 2.0 * pi * r * t * c.cellLength;
  c.bendSoft = c.bendHard = y * i * c.cellLength;
  c.twist = g * 2.0 * i / c.cellLength;
  const Beam beam = annulus(c, t, "test");
  const Brick b = discretise(beam, 4, 100.0, "test");
  EXPECT_GT(b.radius, 0.0);
  // The bond of the equivalent disc keeps Y A, Y I and G J.
  EXPECT_NEAR(b.young * b.section.area / (beam.young * beam.section.area), 1.0, 1e-12);
  EXPECT_NEAR(b.young * b.section.ix / (beam.young * beam.section.ix), 1.0, 1e-12);
  EXPECT_NEAR(b.shear * b.section.polar / (beam.shear * beam.section.polar), 1.0, 1e-12);
}

TEST(BeamUnits, AtomicUnitsOfPressureAndMass) {
  // CODATA 2018: atomic unit of pressure E_h / a_0^3 = 2.942 101 5697e13 Pa; 12.011 u in ag.
  EXPECT_NEAR(units::si::kHartreePerBohr3InMPa / 2.9421015697e7, 1.0, 1e-9);
  EXPECT_NEAR(units::si::kCarbonMassDalton * units::si::kDaltonInAttogram / 1.99447e-5, 1.0, 1e-5);
  EXPECT_NEAR(units::si::kHartreeInZeptojoule, 4.3597447222071e3, 1e-9);
}

class BeamExport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beam-export-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

TEST_F(BeamExport, MdemReadsTheModelAndTheScene) {
  const BeamConstants c = collapsedTubeConstants();
  const Beam beam = rectangleFourConstants(c, "test");
  const Brick b = discretise(beam, 5, 120 * units::si::kCarbonMassDalton, "test");
  MdemExportOptions o;
  // Small rotations: twist and bend together couple at second order (relative O(phi)).
  o.tipRotation = 1e-3;
  write(o.modelFile, mdemModelToml(b, o, "test model\nsecond line"));
  const std::string scenePath = write("cantilever.toml", cantileverSceneToml(b, o));
  const mdem::Scene s = mdem::loadScene(scenePath);

  const double nm = units::si::kBohrInNm, nm2 = nm * nm, nm4 = nm2 * nm2;
  ASSERT_EQ(s.elementTypes.size(), 1u);
  const mdem::ElementType& t = s.elementTypes[0];
  EXPECT_EQ(t.name, o.elementType);
  EXPECT_NEAR(t.thickness / (beam.thickness * nm), 1.0, 1e-14);
  EXPECT_NEAR(t.width / (beam.width * nm), 1.0, 1e-14);
  EXPECT_NEAR(t.length / (b.length * nm), 1.0, 1e-14);
  EXPECT_NEAR(t.mass / (b.mass * units::si::kDaltonInAttogram), 1.0, 1e-14);
  const mdem::Vec3 inertia = t.principalInertia();
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(inertia[a] / (b.inertia[a] * units::si::kDaltonInAttogram * nm2), 1.0, 1e-13) << a;
  ASSERT_EQ(s.bodies.size(), o.elements);
  ASSERT_EQ(s.bonds.size(), std::size_t(o.elements - 1));
  const mdem::Bond& bond = s.bonds[0];
  EXPECT_NEAR(bond.k.kn / (b.normalStiffness * units::si::kHartreePerBohr4InMPaPerNm), 1.0, 1e-12);
  EXPECT_NEAR(bond.k.ks / (b.shearStiffness * units::si::kHartreePerBohr4InMPaPerNm), 1.0, 1e-12);
  EXPECT_NEAR(bond.section.area / (b.section.area * nm2), 1.0, 1e-13);
  EXPECT_NEAR(bond.section.ix / (b.section.ix * nm4), 1.0, 1e-13);
  EXPECT_NEAR(bond.section.iy / (b.section.iy * nm4), 1.0, 1e-13);
  EXPECT_NEAR(bond.section.j / (b.section.polar * nm4), 1.0, 1e-13);

  // Static cantilever under the scene's tip moments, relaxed by the scene's own damping.
  mdem::Simulation sim(s);
  const mdem::Load& load = s.boundary.loads.at(0);
  double f = 0, m = 0;
  int block = 0;
  for (; block < 1000; ++block) {
    sim.run(200);
    std::tie(f, m) = sim.residual();
    if (m < 1e-8 * load.moment.norm()) break;
  }
  ASSERT_LT(block, 1000) << "not relaxed: residual moment " << m << " pN nm";
  const int tip = o.elements - 1;
  const double cells = (o.elements - 1) * b.cellsPerBrick;
  const double toHartree = 1.0 / units::si::kHartreeInZeptojoule;  // pN nm -> Hartree
  const double twist = load.moment.z() * toHartree * cells / c.twist;
  const double bend = load.moment.y() * toHartree * cells * c.cellLength * c.cellLength / c.bendSoft;
  EXPECT_NEAR(twist, o.tipRotation, 1e-9);  // the scene sized its loads for this rotation
  EXPECT_NEAR(bend, o.tipRotation, 1e-9);
  const mdem::Vec3 rot = sim.bodies().accumulatedRotation[tip];
  EXPECT_NEAR(rot.z() / twist, 1.0, 2e-3);
  EXPECT_NEAR(rot.y() / bend, 1.0, 2e-3);
}

}  // namespace
}  // namespace mesochain::beam
