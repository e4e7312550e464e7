// Random networks: no overlaps, a fixed seed reproduces a network exactly (and another seed does
// not), wavy tubes stay connected, unpackable densities and overlapping tubes are clear errors.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "contact_fixture.hpp"
#include "mdem/contacts/network_generator.hpp"
#include "mdem/scene_file.hpp"

#include <filesystem>
#include <fstream>

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

std::string writeNetworkScene(const std::string& name, const std::string& networkKeys) {
  const std::string path = (std::filesystem::temp_directory_path() / ("mdem-network-" + name + ".toml")).string();
  std::ofstream(path) << R"(format = 1
effects = ["bonds"]
)" + std::string(testing::kTubeModelToml) + R"([network]
element_type = "cnt1010"
bond_type = "cnt"
size_nm = [60.0, 60.0, 4.0]
tube_length_nm = 12.0
)" + networkKeys + R"(
[run]
time_step_fraction = 0.5
steps = 1
)";
  return path;
}

TEST(MdemNetwork, SceneTableGeneratesTheSameNetwork) {
  const Scene fromFile = loadScene(writeNetworkScene("same", "tubes = 25\nshape = \"wavy\"\nwaviness_deg = 8.594366926962348\nseed = 42"));
  Scene direct = tubeScene({"bonds"});
  direct.elementTypes[0].mass = 0.0064823;
  generateNetwork(direct, film(42, 8.594366926962348 * units::kPi / 180.0));
  ASSERT_EQ(fromFile.bodies.size(), direct.bodies.size());
  for (int i = 0; i < direct.bodies.size(); ++i) EXPECT_EQ(fromFile.bodies.position[i], direct.bodies.position[i]);
  EXPECT_EQ(fromFile.filmSize, Vec3(60.0, 60.0, 4.0));
  // Areal density 0.02 ug/cm^2 = 2e-4 ag/nm^2, over 3600 nm^2: 0.72 ag = 18.5 tubes of
  // 6 x 0.0064823 ag -> 19 tubes.
  const Scene dense = loadScene(writeNetworkScene("areal", "areal_density_ug_per_cm2 = 0.02"));
  EXPECT_EQ(dense.bodies.size(), 19 * 6);
}

TEST(MdemNetwork, BadNetworkKeysAreClearErrors) {
  auto expectError = [](const std::string& keys, const char* key) {
    try {
      loadScene(writeNetworkScene("bad", keys));
      ADD_FAILURE() << "no error for " << keys;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  expectError("", "tubes");                                  // neither count nor density
  expectError("tubes = 3\nareal_density_ug_per_cm2 = 0.1", "tubes");
  expectError("tubes = 3\nwaviness_deg = 5", "waviness_deg");  // straight tubes
  expectError("tubes = 3\nshape = \"curly\"", "shape");
  expectError("tubes = 3000", "network.tubes");              // cannot be packed
}

}  // namespace
}  // namespace mesochain::mdem
