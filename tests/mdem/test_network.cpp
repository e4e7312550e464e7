// Random networks: no overlaps, a fixed seed reproduces a network exactly (and another seed does
// not), wavy tubes stay connected, unpackable densities and overlapping tubes are clear errors.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "contact_fixture.hpp"
#include "mdem/contacts/network_generator.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

NetworkSpec film(std::uint64_t seed, double waviness) {
  NetworkSpec n;
  n.tubes = 25, n.elementsPerTube = 6;
  n.size = Vec3(60.0, 60.0, 4.0);
  n.waviness = waviness;
  n.seed = seed;
  return n;
}

TEST(MdemNetwork, FixedSeedReproducesTheNetworkWithoutOverlaps) {
  Scene a = tubeScene({"bonds"}), b = tubeScene({"bonds"}), c = tubeScene({"bonds"});
  generateNetwork(a, film(42, 0.15));
  generateNetwork(b, film(42, 0.15));
  generateNetwork(c, film(43, 0.15));
  ASSERT_EQ(a.bodies.size(), 150);
  EXPECT_EQ(a.bonds.size(), 25u * 5u);
  bool differs = false;
  for (int i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies.position[i], b.bodies.position[i]);  // bitwise
    EXPECT_EQ(a.bodies.orientation[i].w, b.bodies.orientation[i].w);
    differs |= (a.bodies.position[i] - c.bodies.position[i]).norm() > 1e-6;
    EXPECT_GE(a.bodies.position[i].x(), 0.0);
    EXPECT_LE(a.bodies.position[i].y(), 60.0);
  }
  EXPECT_TRUE(differs);
  EXPECT_NO_THROW(checkNoOverlaps(a, 0.3 - 1e-9));
  // Wavy tubes: the ends of consecutive elements meet (bond rest length = element length).
  for (const Bond& bd : a.bonds) EXPECT_LT(bd.restLength, kSegmentLength + 1e-9);
}

TEST(MdemNetwork, UnpackableDensityIsAClearError) {
  Scene s = tubeScene({"bonds"});
  NetworkSpec n = film(1, 0.0);
  n.tubes = 2000;  // footprint far above the film area
  try {
    generateNetwork(s, n);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("network.tubes"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("can be packed"), std::string::npos) << e.what();
  }
  // Below the footprint bound but too dense for random sequential placement: still an error,
  // after a bounded number of attempts (no hang).
  n.tubes = 200, n.attemptsPerTube = 50;
  Scene s2 = tubeScene({"bonds"});
  EXPECT_THROW(generateNetwork(s2, n), InputError);
}

TEST(MdemNetwork, OverlappingTubesAreAClearError) {
  Scene s = tubeScene({"bonds"});
  addTube(s, 3, Vec3::Zero(), Vec3::UnitX());
  addTube(s, 3, Vec3(1.0, 1.0, 0.0), Vec3::UnitY());  // crosses the first one through its wall
  try {
    checkNoOverlaps(s, 0.3);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("overlapping"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mesochain::mdem
