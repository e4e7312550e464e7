// VTK frames carry per-bond loads and per-element energies (output.hpp): a stretched bond's
// normal force is k_n A d and a bent bond's moment k_n I theta (closed forms), and the element
// energies add up to the energy the effects store, the van der Waals contacts' included.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "contact_fixture.hpp"
#include "mdem/output.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// The frame of `sim`'s state as text, with the loads and energies every effect reports.
std::string frameText(const Simulation& sim, const char* name) {
  VtkFields fields;
  fields.elementEnergy.assign(sim.bodies().size(), 0.0);
  for (const EffectPtr& e : sim.effects()) {
    e->addElementEnergies(sim.state(), fields.elementEnergy);
    if (e->bondList()) fields.bondLoads = e->bondLoads(sim.state());
  }
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  writeVtkFrame(path, sim.bodies(), sim.bonds(), sim.time(), fields);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  return text;
}

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
  const Simulation sim(s);
  const std::string text = frameText(sim, "mesochain-vtk-fields.vtk");
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

// Element 2 turned by a small angle about the thickness axis x, then about the width axis y:
// the bond 1-2 carries the bending moment k_n I_x theta, then k_n I_y theta (k_n = Y / l; the
// brick's I_x = h w^3/12 and I_y = w h^3/12 differ 9-fold, so the axes cannot be mixed up);
// bond 0-1 none. Moment and twist are the tracked rotation's, exact for a turn about one axis.
TEST(MdemVtkFields, BentBondCarriesItsBendingMoment) {
  const double theta = 2e-3;  // rad
  for (const auto& [axis, inertia] : {std::pair{Vec3::UnitX(), inertiaX()}, std::pair{Vec3::UnitY(), inertiaY()}}) {
    Scene s = filament(3);
    s.run.timeStepFraction = 0.5;
    s.bodies.orientation[2] = axisAngle(axis, theta) * s.bodies.orientation[2];
    const Simulation sim(s);
    const std::string text = frameText(sim, "mesochain-vtk-bent.vtk");
    const std::vector<double> moment = scalars(text, "bending_moment_pN_nm", 5);
    const std::vector<double> twist = scalars(text, "twisting_moment_pN_nm", 5);
    const double expected = kYoung / kL * inertia * theta;
    EXPECT_NEAR(moment[3], 0.0, 1e-9 * expected);
    EXPECT_NEAR(moment[4], expected, 1e-6 * expected) << axis.transpose();
    EXPECT_NEAR(twist[4], 0.0, 1e-9 * expected);
  }
}

// Two straight tubes crossing at right angles, 0.3 nm apart at the crossing over the middle of
// each, and a third far away: the per-element energies add up to the stored potential (bonds
// and van der Waals); the far tube's are exactly zero; the crossing's mirror x -> 4 - x maps
// elements 0 and 2 of the lower tube onto each other, so their energies agree; the binding is
// carried by the elements at the crossing.
TEST(MdemVtkFields, ContactEnergiesPerElementAddUpToTheVanDerWaalsEnergy) {
  Scene s = tubeScene({"bonds", "vdw_contact"});
  const double d = 2.0 * kTubeRadius + 0.3;
  addTube(s, 3, Vec3(0.0, 0.0, 0.0), Vec3::UnitX());   // elements 0-2, centres x = 0, 2, 4
  addTube(s, 3, Vec3(2.0, -2.0, d), Vec3::UnitY());    // elements 3-5, centres y = -2, 0, 2
  addTube(s, 3, Vec3(0.0, 30.0, 0.0), Vec3::UnitX());  // elements 6-8, out of reach
  s.run.timeStepFraction = 0.5;
  const Simulation sim(s);
  const double vdw = sim.energies()["vdw"];
  ASSERT_LT(vdw, 0.0);
  const std::string text = frameText(sim, "mesochain-vtk-contact.vtk");
  const std::vector<double> energy = scalars(text, "energy_zJ", 9);
  double sum = 0.0;
  for (double e : energy) sum += e;
  EXPECT_NEAR(sum, sim.energies().potential(), 1e-10 * std::abs(vdw));
  EXPECT_NEAR(sim.energies().potential(), vdw, 1e-9 * std::abs(vdw));  // straight, unstrained bonds
  for (int i = 6; i < 9; ++i) EXPECT_EQ(energy[i], 0.0) << i;
  EXPECT_NEAR(energy[0], energy[2], 1e-9 * std::abs(vdw));
  EXPECT_NEAR(energy[3], energy[5], 1e-9 * std::abs(vdw));
  EXPECT_LT(energy[1], energy[0]);  // the crossing binds most
  EXPECT_LT(energy[4], energy[3]);
  EXPECT_LT(energy[1] + energy[4], 0.5 * vdw);
}

}  // namespace
}  // namespace mesochain::mdem
