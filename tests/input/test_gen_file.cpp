#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/gen_file.hpp"
#include "objective/core/nanotube_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kAngstromInBohr;
using units::kPi;

namespace {

const std::string kData = std::string(MESOCHAIN_TEST_DATA) + "/gen/";

// Reads `text` as bad.gen and returns the InputError message ("" when none).
std::string genError(const std::string& text) {
  std::istringstream in(text);
  try {
    readGen(in, "bad.gen");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectSameCell(const ObjectiveCell& a, const ObjectiveCell& b, double tol) {
  ASSERT_EQ(a.atomCount(), b.atomCount());
  EXPECT_EQ(a.speciesNames, b.speciesNames);
  EXPECT_EQ(a.species, b.species);
  EXPECT_LT((a.positions - b.positions).cwiseAbs().maxCoeff(), tol);
  EXPECT_NEAR(a.symmetry.translation(), b.symmetry.translation(), tol);
  EXPECT_NEAR(a.symmetry.twist(), b.symmetry.twist(), tol);
  EXPECT_EQ(a.symmetry.rotationOrder(), b.symmetry.rotationOrder());
}

}  // namespace

TEST(GenFile, ReadsHelicalFileAndSubtractsTheOrigin) {
  const GenGeometry g = readGenFile(kData + "cnt10_0_helical.gen");
  EXPECT_EQ(g.type, GenType::Helical);
  const ObjectiveCell ref = buildNanotubeHelical(10, 0, 1.42 * kAngstromInBohr);
  expectSameCell(g.cell, ref, 1e-9);
  EXPECT_NEAR(g.cell.symmetry.twist(), kPi / 10, 1e-12);
}

TEST(GenFile, ReadsClusterSupercellAndFractional) {
  const GenGeometry c = readGenFile(kData + "methane.gen");
  EXPECT_EQ(c.type, GenType::Cluster);
  EXPECT_EQ(c.cell.atomCount(), 5);
  EXPECT_EQ(c.cell.speciesOf(1), "H");
  EXPECT_TRUE(c.cell.symmetry.isRing());
  EXPECT_EQ(c.cell.symmetry.rotationOrder(), 1);
  const GenGeometry s = readGenFile(kData + "carbyne_chain.gen");
  const GenGeometry f = readGenFile(kData + "carbyne_chain_frac.gen");
  for (const GenGeometry* g : {&s, &f}) {
    EXPECT_NEAR(g->cell.symmetry.translation(), 2.56 * kAngstromInBohr, 1e-12);
    EXPECT_EQ(g->cell.symmetry.twist(), 0.0);
    EXPECT_EQ(g->cell.symmetry.rotationOrder(), 1);
  }
  // The fractional file has its origin at the box centre: same Cartesian cell.
  EXPECT_LT((s.cell.positions - f.cell.positions).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GenFile, RoundTripsClusterSupercellHelicalAndRing) {
  ObjectiveCell cluster = readGenFile(kData + "methane.gen").cell;
  ObjectiveCell periodic = buildNanotubeTranslational(5, 5, 1.42 * kAngstromInBohr);
  ObjectiveCell helical = buildNanotubeHelical(6, 4, 1.42 * kAngstromInBohr);
  ObjectiveCell ring = helical;
  ring.symmetry = Symmetry::ring(12);
  const std::pair<const ObjectiveCell*, GenType> cases[] = {{&cluster, GenType::Cluster},
                                                            {&periodic, GenType::Supercell},
                                                            {&helical, GenType::Helical},
                                                            {&ring, GenType::Helical}};
  for (const auto& [cell, type] : cases) {
    std::stringstream io;
    writeGen(io, *cell);
    const GenGeometry back = readGen(io, "roundtrip.gen");
    EXPECT_EQ(back.type, type);
    expectSameCell(back.cell, *cell, 1e-12);
    EXPECT_EQ(back.cell.symmetry.isRing(), cell->symmetry.isRing());
  }
  const auto path = std::filesystem::temp_directory_path() / "mesochain_gen_roundtrip.gen";
  writeGenFile(path.string(), helical);
  expectSameCell(readGenFile(path.string()).cell, helical, 1e-12);
  std::filesystem::remove(path);
}

TEST(GenFile, ErrorsNameTheFileAndLine) {
  const std::string ok = "2 H\nC\n1 1 3 0 0\n2 1 0 3 1\n0 0 0\n2.0 10.0 3\n";
  EXPECT_EQ(genError(ok), "");
  struct Case {
    std::string text, where;
  };
  const Case cases[] = {
      {"", "line 1"},                                                      // empty file
      {"2 Q\nC\n", "line 1"},                                              // unknown type
      {"x H\nC\n", "line 1"},                                              // bad atom count
      {"2 H\nC c\n", "line 2"},                                            // bad element name
      {"2 H\nC C\n1 1 3 0 0\n", "line 2"},                                 // duplicate element
      {"2 H\nC\n1 1 3 0 0\n2 2 0 3 1\n0 0 0\n2 10 3\n", "line 4"},         // element index 2
      {"2 H\nC\n1 1 3 0 0\n2 1 0 x 1\n0 0 0\n2 10 3\n", "line 4"},         // bad number
      {"2 H\nC\n1 1 3 0 0\n2 1 0 nan 1\n0 0 0\n2 10 3\n", "line 4"},       // not finite
      {"2 H\nC\n1 1 3 0 0\n2 1 0 3 1 7\n0 0 0\n2 10 3\n", "line 4"},       // trailing field
      {"2 H\nC\n1 1 3 0 0\n", "line 4"},                                   // too few atoms
      {"2 H\nC\n1 1 3 0 0\n2 1 0 3 1\n0 0 0\n2 10 0\n", "line 6"},         // rotation order 0
      {"2 H\nC\n1 1 3 0 0\n2 1 0 3 1\n0 0 0\n2 10 2.5\n", "line 6"},       // non-integer order
      {"2 H\nC\n1 1 3 0 0\n2 1 0 3 1\n0 0 0\n0 10 4\n", "line 6"},         // ring with bad twist
      {"2 H\nC\n1 1 3 0 0\n2 1 0 3 1\n0 0 0\n-2 10 4\n", "line 6"},        // negative T
      {"2 H\nC\n1 1 3 0 0\n2 1 0 3 1\n0 0 0\n2 10 3\n9 9 9\n", "line 7"},  // superfluous
      {"2 C\nC H\n1 1 3 0 0\n2 1 0 3 1\n", "line 2"},                      // H unused
      {"2 S\nC\n1 1 0 0 0\n2 1 0 0 1.3\n0 0 0\n20 0 1\n0 20 0\n0 0 2.6\n", "line 6"},
      {"2 S\nC\n1 1 0 0 0\n2 1 0 0 1.3\n0 0 0\n20 0 0\n0 20 0\n0 1 2.6\n", "line 8"},
  };
  for (const Case& c : cases) {
    const std::string msg = genError(c.text);
    EXPECT_NE(msg.find("bad.gen"), std::string::npos) << c.text << " -> " << msg;
    EXPECT_NE(msg.find(c.where), std::string::npos) << c.text << " -> " << msg;
  }
  // The tilted lattice file says why S cells must be periodic along z only.
  try {
    readGenFile(kData + "tilted_lattice.gen");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("periodic along z only"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("tilted_lattice.gen, line 8"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(readGenFile(kData + "does_not_exist.gen"), InputError);
}

// A 3-D periodic S file (graphite-like: a = 2.46 Å, b = 4.26 Å) read as an objective cell would
// silently be a 1-D chain; it is refused naming the short vector. Vacuum of 10 Å or more is
// accepted, in Cartesian and fractional files (the gap is measured on the atoms' extent).
TEST(GenFile, ShortLateralVectorsAreRefused) {
  const std::string atoms = "2 S\nC\n1 1 0 0 0\n2 1 1.42 0 0\n0 0 0\n";
  const std::string crystal = genError(atoms + "2.46 0 0\n0 4.26 0\n0 0 6.7\n");
  EXPECT_NE(crystal.find("bad.gen, line 6"), std::string::npos) << crystal;
  EXPECT_NE(crystal.find("2-D or 3-D periodic crystal"), std::string::npos) << crystal;
  // b alone short: named at its line.
  const std::string slab = genError(atoms + "30 0 0\n0 4.26 0\n0 0 6.7\n");
  EXPECT_NE(slab.find("bad.gen, line 7"), std::string::npos) << slab;
  EXPECT_NE(slab.find("b (lattice vector 2)"), std::string::npos) << slab;
  // The atoms span 1.42 Å along x: |a| = 11.3 leaves 9.88 Å (refused), 11.5 leaves 10.08 Å.
  EXPECT_NE(genError(atoms + "11.3 0 0\n0 20 0\n0 0 6.7\n"), "");
  EXPECT_EQ(genError(atoms + "11.5 0 0\n0 20 0\n0 0 6.7\n"), "");
  EXPECT_EQ(genError("2 F\nC\n1 1 0 0 0\n2 1 0.1 0 0\n0 0 0\n20 0 0\n0 20 0\n0 0 2.56\n"), "");
  EXPECT_NE(genError("2 F\nC\n1 1 0 0 0\n2 1 0.6 0 0\n0 0 0\n20 0 0\n0 20 0\n0 0 2.56\n"), "");
}
