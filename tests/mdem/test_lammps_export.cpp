// The bpm/rotational export of `mesochain-bench dem --lammps` (mdem/lammps_export.hpp): the bond
// coefficients are the parallel bond's small-deformation stiffnesses, checked against the closed
// forms of a rectangular section; the spheres carry the elements' masses; bonds of different
// stiffness are refused.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mdem/lammps_export.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {
namespace {

namespace fs = std::filesystem;

constexpr double kThickness = 0.8, kWidth = 2.4, kLength = 2.0, kMass = 0.01;
constexpr double kYoung = 1e6, kShear = 0.4e6;  // MPa

Scene chains(int filaments, int perFilament) {
  Scene s;
  ElementType t;
  t.name = "brick", t.thickness = kThickness, t.width = kWidth, t.length = kLength, t.mass = kMass;
  s.elementTypes.push_back(t);
  BondType b;
  b.name = "cnt", b.fromModuli = true, b.youngModulus = kYoung, b.shearModulus = kShear;
  s.bondTypes.push_back(b);
  for (int k = 0; k < filaments; ++k) {
    FilamentSpec f;
    f.count = perFilament;
    f.start = {5.0 * k, 0.0, 0.0};
    addFilament(s, f);
  }
  s.bodies.velocity[1] = Vec3(0.1, -0.2, 0.3);
  return s;
}

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(MdemLammpsExport, BpmBondCoefficientsAreTheParallelBondsStiffnesses) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mesochain-bpm-export-{}", ::getpid());
  fs::create_directories(dir);
  const Scene s = chains(3, 4);
  writeLammpsBpmChains(s, 2.5e-5, (dir / "chains").string());

  // Closed forms of the rectangular section (thickness along body x, width along y) and the bond
  // stiffness per area k_n = E / L, k_s = G / L.
  const double area = kThickness * kWidth;
  const double ix = kThickness * std::pow(kWidth, 3) / 12.0, iy = kWidth * std::pow(kThickness, 3) / 12.0;
  const double kn = kYoung / kLength, ks = kShear / kLength;
  double kr = 0, kShearBond = 0, kt = 0, kb = 0, step = 0;
  for (const std::string& l : lines(dir / "chains.settings")) {
    std::istringstream in(l);
    std::string word;
    in >> word;
    if (word == "bond_coeff") {
      int type;
      in >> type >> kr >> kShearBond >> kt >> kb;
      EXPECT_EQ(type, 1);
    }
    if (word == "timestep") in >> step;
  }
  EXPECT_NEAR(kr, kn * area, 1e-6 * kn * area);
  EXPECT_NEAR(kShearBond, ks * area, 1e-6 * ks * area);
  EXPECT_NEAR(kt, ks * (ix + iy), 1e-6 * ks * (ix + iy));
  EXPECT_NEAR(kb, kn * 0.5 * (ix + iy), 1e-6 * kn * ix);
  EXPECT_DOUBLE_EQ(step, 2.5e-5);

  // The data file: 12 spheres, 9 bonds, three molecules; mass = density * 4/3 pi r^3 with the
  // diameter the rest length; the velocity of element 2 (id 2) as given.
  const std::vector<std::string> data = lines(dir / "chains.data");
  int atoms = -1, bonds = -1;
  std::size_t atomSection = 0, velocitySection = 0;
  for (std::size_t k = 0; k < data.size(); ++k) {
    if (data[k].find(" atoms") != std::string::npos && atoms < 0) atoms = std::stoi(data[k]);
    if (data[k].find(" bonds") != std::string::npos && bonds < 0) bonds = std::stoi(data[k]);
    if (data[k].rfind("Atoms", 0) == 0) atomSection = k;
    if (data[k].rfind("Velocities", 0) == 0) velocitySection = k;
  }
  EXPECT_EQ(atoms, 12);
  EXPECT_EQ(bonds, 9);
  ASSERT_GT(atomSection, 0u);
  ASSERT_GT(velocitySection, atomSection);
  int molecules = 0;
  for (int i = 0; i < 12; ++i) {
    std::istringstream in(data[atomSection + 2 + i]);
    int id, molecule, type;
    double diameter, density, x, y, z;
    in >> id >> molecule >> type >> diameter >> density >> x >> y >> z;
    EXPECT_EQ(id, i + 1);
    EXPECT_EQ(molecule, i / 4 + 1);
    molecules = std::max(molecules, molecule);
    EXPECT_DOUBLE_EQ(diameter, kLength);
    const double r = 0.5 * diameter;
    EXPECT_NEAR(density * 4.0 / 3.0 * M_PI * r * r * r, kMass, 1e-10 * kMass);
    EXPECT_NEAR(z, s.bodies.position[i].z(), 1e-8);
  }
  EXPECT_EQ(molecules, 3);
  std::istringstream v(data[velocitySection + 3]);
  int id;
  double vx, vy, vz;
  v >> id >> vx >> vy >> vz;
  EXPECT_EQ(id, 2);
  EXPECT_DOUBLE_EQ(vx, 0.1);
  EXPECT_DOUBLE_EQ(vy, -0.2);
  EXPECT_DOUBLE_EQ(vz, 0.3);
  fs::remove_all(dir);
}

TEST(MdemLammpsExport, BpmExportRefusesBondsOfDifferentStiffness) {
  Scene s = chains(2, 3);
  s.bonds.back().k.kn *= 2.0;
  const fs::path prefix = fs::temp_directory_path() / fmt::format("mesochain-bpm-refused-{}", ::getpid());
  try {
    writeLammpsBpmChains(s, 1e-5, prefix.string());
    FAIL() << "bonds of two stiffnesses were exported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("one rest length, stiffness and section"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(prefix.string() + ".data"));
}

}  // namespace
}  // namespace mesochain::mdem
