// Bundles and orientation of a network (contacts/network_structure.hpp) on a configuration
// counted by hand: tubes A and B side by side along x (wall gap 0.3 nm), tube C along y across
// both, 0.45 nm above them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "contact_fixture.hpp"
#include "mdem/contacts/bundle_sizes.hpp"
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
  // The same bundles from the positions alone (a cell list instead of the contact neighbour
  // list: what the film report and a tensile stage's JSON use): one bundle of six elements, C's
  // three in none. Only crossings below the aligned angle join: with every angle admitted, C_1 does.
  const BundleSizeDistribution fromPositions = sceneBundleSizes(s, 0.5, 10.0 * 3.14159265358979 / 180.0, s.contacts.excludeWithin);
  EXPECT_EQ(fromPositions.elements, 9);
  EXPECT_EQ(fromPositions.bundles, 1);
  EXPECT_EQ(fromPositions.largest, 6);
  EXPECT_EQ(fromPositions.elementsInBundles, 6);
  ASSERT_EQ(fromPositions.bundlesInClass.size(), 2u);  // classes [2, 4), [4, 8)
  EXPECT_EQ(fromPositions.bundlesInClass[0], 0);
  EXPECT_EQ(fromPositions.bundlesInClass[1], 1);
  EXPECT_DOUBLE_EQ(fromPositions.elementFractionInClass[1], 6.0 / 9.0);
  const BundleSizeDistribution all = sceneBundleSizes(s, 0.5, 91.0 * 3.14159265358979 / 180.0, s.contacts.excludeWithin);
  EXPECT_EQ(all.largest, 8);  // C_1 joins A and B; C_0 and C_2 touch nothing below 0.5 nm
  EXPECT_EQ(all.bundles, 1);
}

// Size classes [2^k, 2^(k+1)): chains of 2, 3, 4, 7, 8 and 16 elements (each element joined to
// the next) and three loose elements, counted by hand.
TEST(MdemNetworkStructure, BundleSizeClassesOfChainsCountedByHand) {
  std::vector<std::pair<int, int>> pairs;
  int next = 0;
  for (int size : {2, 3, 4, 7, 8, 16}) {
    for (int k = 1; k < size; ++k) pairs.emplace_back(next + k, next + k - 1);  // either order
    next += size;
  }
  const int elements = next + 3;  // 43
  const BundleSizeDistribution d = bundleSizeDistribution(elements, pairs);
  EXPECT_EQ(d.bundles, 6);
  EXPECT_EQ(d.elementsInBundles, 40);
  EXPECT_EQ(d.largest, 16);
  EXPECT_DOUBLE_EQ(d.mean, 40.0 / 6.0);
  EXPECT_EQ(d.bundlesInClass, (std::vector<int>{2, 2, 1, 1}));  // {2,3}, {4,7}, {8}, {16}
  ASSERT_EQ(d.elementFractionInClass.size(), 4u);
  EXPECT_DOUBLE_EQ(d.elementFractionInClass[0], 5.0 / 43.0);
  EXPECT_DOUBLE_EQ(d.elementFractionInClass[1], 11.0 / 43.0);
  EXPECT_DOUBLE_EQ(d.elementFractionInClass[2], 8.0 / 43.0);
  EXPECT_DOUBLE_EQ(d.elementFractionInClass[3], 16.0 / 43.0);
  const nlohmann::ordered_json j = bundleSizesJson(d);
  EXPECT_EQ(j["classes"][3]["from_elements"], 16);
  EXPECT_EQ(j["classes"][3]["to_elements_exclusive"], 32);
  EXPECT_EQ(j["classes"][1]["bundles"], 2);
  // No aligned pair: no bundle, no class.
  const BundleSizeDistribution none = bundleSizeDistribution(5, {});
  EXPECT_EQ(none.bundles, 0);
  EXPECT_TRUE(none.bundlesInClass.empty());
}

}  // namespace
}  // namespace mesochain::mdem
