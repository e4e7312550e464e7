#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "input/xyz_file.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kAngstromInBohr;
using units::kPi;

namespace {

const std::string kData = std::string(MESOCHAIN_TEST_DATA) + "/xyz/";
const double kBond = 1.42 * kAngstromInBohr;

std::string xyzError(const std::string& text) {
  std::istringstream in(text);
  try {
    readXyz(in, "bad.xyz");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(XyzFile, RoundTripWithSymmetryEnergyAndForces) {
  const ObjectiveCell cell = buildNanotubeHelical(8, 2, kBond);
  Eigen::Matrix3Xd forces(3, 2);
  forces << 0.01, -0.02, 0.0, 0.003, 1e-5, -1e-5;
  std::stringstream io;
  writeXyz(io, cell, {-11.25, &forces});
  const std::string text = io.str();
  EXPECT_NE(text.find("Properties=species:S:1:pos:R:3:forces:R:3"), std::string::npos);
  const XyzFrame back = readXyz(io, "roundtrip.xyz");
  EXPECT_TRUE(back.hasSymmetry);
  EXPECT_LT((back.cell.positions - cell.positions).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(back.cell.symmetry.translation(), cell.symmetry.translation(), 1e-12);
  EXPECT_NEAR(back.cell.symmetry.twist(), cell.symmetry.twist(), 1e-12);
  EXPECT_EQ(back.cell.symmetry.rotationOrder(), 2);
  ASSERT_TRUE(back.energy.has_value());
  EXPECT_NEAR(*back.energy, -11.25, 1e-12);
  EXPECT_LT((back.forces - forces).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(XyzFile, ReadsPlainLatticeAndRingFiles) {
  const XyzFrame plain = readXyzFile(kData + "water_plain.xyz");
  EXPECT_FALSE(plain.hasSymmetry);
  EXPECT_EQ(plain.cell.atomCount(), 3);
  EXPECT_EQ(plain.cell.speciesNames, (std::vector<std::string>{"O", "H"}));
  EXPECT_TRUE(plain.cell.symmetry.isRing());
  const XyzFrame chain = readXyzFile(kData + "carbyne_lattice.xyz");
  EXPECT_TRUE(chain.hasSymmetry);
  EXPECT_NEAR(chain.cell.symmetry.translation(), 2.56 * kAngstromInBohr, 1e-12);
  EXPECT_NEAR(chain.cell.positions(2, 1), 1.28 * kAngstromInBohr, 1e-12);
  const XyzFrame ring = readXyzFile(kData + "ring_c6.xyz");
  EXPECT_TRUE(ring.cell.symmetry.isRing());
  EXPECT_EQ(ring.cell.symmetry.rotationOrder(), 6);
}

TEST(XyzFile, UnrollGivesPlainAtoms) {
  const ObjectiveCell helical = buildNanotubeHelical(5, 5, kBond);
  const ObjectiveCell u = unroll(helical, -2, 3);
  EXPECT_EQ(u.atomCount(), 6 * 5 * 2);
  EXPECT_TRUE(u.symmetry.isRing());  // gamma != 0: a finite piece
  EXPECT_NO_THROW(u.validate("unrolled", 0.5 * kAngstromInBohr));
  const ObjectiveCell trans = buildNanotubeTranslational(5, 5, kBond, true);
  const ObjectiveCell v = unroll(trans, 0, 2);
  EXPECT_EQ(v.atomCount(), 3 * 5 * 4);
  EXPECT_FALSE(v.symmetry.isRing());
  EXPECT_NEAR(v.symmetry.translation(), 3 * trans.symmetry.translation(), 1e-12);
  // The periodic unrolled tube is a valid cell and reads back from the written file.
  EXPECT_NO_THROW(v.validate("unrolled", 0.5 * kAngstromInBohr));
  const auto path = std::filesystem::temp_directory_path() / "mesochain_unrolled.xyz";
  writeUnrolledXyzFile(path.string(), trans, 0, 2);
  const XyzFrame back = readXyzFile(path.string());
  EXPECT_EQ(back.cell.atomCount(), 60);
  EXPECT_NEAR(back.cell.symmetry.translation(), v.symmetry.translation(), 1e-12);
  std::filesystem::remove(path);
  // A ring unrolls to its N_a copies whatever the zeta range.
  ObjectiveCell ring = readXyzFile(kData + "ring_c6.xyz").cell;
  EXPECT_EQ(unroll(ring, -5, 5).atomCount(), 6);
}

TEST(XyzFile, ErrorsNameTheFileAndLine) {
  struct Case {
    std::string text, where;
  };
  const Case cases[] = {
      {"", "line 1"},
      {"two\nx\n", "line 1"},
      {"2\ncomment\nC 0 0 0\n", "line 4"},
      {"1\ncomment\nC 0 0 zz\n", "line 3"},
      {"1\ncomment\nc 0 0 0\n", "line 3"},
      {"1\ncomment\nC 0 0 0\nC 1 1 1\n", "line 4"},
      {"1\nmesochain:translation=2.0 mesochain:twist=10\nC 1 0 0\n", "line 2"},
      {"1\nmesochain:translation=2.0 mesochain:twist=10 mesochain:rotation_order=0\nC 1 0 0\n",
       "line 2"},
      {"1\nmesochain:translation=0 mesochain:twist=10 mesochain:rotation_order=4\nC 1 0 0\n",
       "line 2"},
      {"1\nmesochain:transl=2.0\nC 1 0 0\n", "line 2"},
      {"1\nLattice=\"10 0 0 0 10 0 0 1 3\"\nC 1 0 0\n", "line 2"},
      {"1\nProperties=species:S:1:pos:R:3:forces:R:3\nC 1 0 0\n", "line 3"},
      {"1\nProperties=pos:R:3\nC 1 0 0\n", "line 2"},
      {"1\nenergy=abc\nC 1 0 0\n", "line 2"},
  };
  for (const Case& c : cases) {
    const std::string msg = xyzError(c.text);
    EXPECT_NE(msg.find("bad.xyz"), std::string::npos) << c.text << " -> " << msg;
    EXPECT_NE(msg.find(c.where), std::string::npos) << c.text << " -> " << msg;
  }
}
