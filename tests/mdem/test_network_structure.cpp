// Bundles and orientation of a network (contacts/network_structure.hpp) on a configuration
// counted by hand: tubes A and B side by side along x (wall gap 0.3 nm), tube C along y across
// both, 0.45 nm above them.
#include <gtest/gtest.h>

#include "contact_fixture.hpp"
#include "mdem/contacts/network_structure.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

TEST(MdemNetworkStructure, BundlesAndOrientationOfACountedConfiguration) {
  Scene s = tubeScene({"bonds", "vdw_contact"});
  const double d = 2.0 * kTubeRadius;
  addTube(s, 3, Vec3(0.0, 0.0, 0.0), Vec3::UnitX());          // A: elements 0-2, x in [-1, 5]
  addTube(s, 3, Vec3(0.0, d + 0.3, 0.0), Vec3::UnitX());      // B: elements 3-5
  addTube(s, 3, Vec3(2.0, -2.0, d + 0.45), Vec3::UnitY());    // C: elements 6-8, over A_1 and B_1
  s.run.timeStepFraction = 0.5;
  Simulation sim(s);
  ASSERT_NE(sim.contactNeighbourhood(), nullptr);
  const NetworkStructure n = networkStructure(*sim.contactNeighbourhood(), sim.bodies(), 0.5, 10.0 * 3.14159265358979 / 180.0, 0);
  // A-B: each element faces its partner (gap 0.3) and touches the partner's neighbours end to
  // end (gap 0.3 at the shared end): 3 + 2 x 2 aligned pairs. C crosses A_1 and B_1 at 0.45 nm;
  // its other closest approaches are 0.57-0.71 nm.
  EXPECT_EQ(n.aligned, 7);
  EXPECT_EQ(n.contacts, 9);
  EXPECT_EQ(n.bundles, 1);
  EXPECT_EQ(n.largestBundle, 6);
  EXPECT_DOUBLE_EQ(n.meanBundle, 6.0);
  // Six elements along x, three along y: Q = diag(2/3, 1/3).
  EXPECT_NEAR(n.orderParameter, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(n.axisAlignment, 1.0 / 3.0, 1e-12);
  const NetworkStructure y = networkStructure(*sim.contactNeighbourhood(), sim.bodies(), 0.5, 10.0 * 3.14159265358979 / 180.0, 1);
  EXPECT_NEAR(y.axisAlignment, -1.0 / 3.0, 1e-12);
}

}  // namespace
}  // namespace mesochain::mdem
