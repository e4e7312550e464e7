// VTK frames carry per-bond loads and per-element energies (output.hpp): a stretched bond's
// normal force is k_n A d (closed form), and the element energies add up to the energy the
// effects store.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/output.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// The values of a VTK SCALARS block `name` (after its LOOKUP_TABLE line).
std::vector<double> scalars(const std::string& text, const std::string& name, std::size_t count) {
  std::istringstream in(text.substr(text.find("SCALARS " + name)));
  std::string line;
  std::getline(in, line), std::getline(in, line);
  std::vector<double> v(count);
  for (double& x : v) in >> x;
  return v;
}

TEST(MdemVtkFields, BondLoadsAndElementEnergies) {
  Scene s = filament(3);
  s.run.timeStepFraction = 0.5;
  const double stretch = 1e-3;  // nm, element 2 pulled along the chain
  s.bodies.position[2].z() += stretch;
  Simulation sim(s);
  VtkFields fields;
  fields.elementEnergy.assign(3, 0.0);
  for (const EffectPtr& e : sim.effects()) {
    e->addElementEnergies(sim.state(), fields.elementEnergy);
    if (e->bondList()) fields.bondLoads = e->bondLoads(sim.state());
  }
  const std::string path = (std::filesystem::temp_directory_path() / "mesochain-vtk-fields.vtk").string();
  writeVtkFrame(path, sim.bodies(), sim.bonds(), sim.time(), fields);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  ASSERT_NE(text.find("CELL_DATA 5"), std::string::npos);  // 3 vertex cells + 2 bonds
  const std::vector<double> normal = scalars(text, "normal_force_pN", 5);
  const double kn = kYoung / kL;  // k_n = Y / l (MPa/nm = pN/nm^3)
  EXPECT_EQ(normal[0], 0.0);
  EXPECT_NEAR(normal[3], 0.0, 1e-9);                           // bond 0-1 unstrained
  EXPECT_NEAR(normal[4], kn * area() * stretch, 1e-6 * kn * area() * stretch);  // bond 1-2 in tension
  const std::vector<double> energy = scalars(text, "energy_zJ", 3);
  EXPECT_NEAR(energy[0] + energy[1] + energy[2], sim.energies().potential(), 1e-12 * sim.energies().potential());
  EXPECT_EQ(energy[0], 0.0);
  EXPECT_NEAR(energy[1], energy[2], 1e-12 * energy[2]);  // the strained bond's halves
}

}  // namespace
}  // namespace mesochain::mdem
