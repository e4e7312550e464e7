// The [builder] table of a cell file: multi-walled tubes and bent graphene stacks, and their
// errors.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_file.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
namespace fs = std::filesystem;

namespace {
CellInput readText(const std::string& builder) {
  const fs::path p = fs::temp_directory_path() /
                     ("mesochain_builder_" + std::to_string(getpid()) + ".toml");
  std::ofstream(p) << "format = 1\n" << builder
                   << "\n[kpoints]\nhelical = 8\n[electrons]\ntemperature = 300.0\n"
                      "[parameters]\nset = \"pbc-0-3\"\n";
  CellInput in = readCellFile(p.string());
  fs::remove(p);
  return in;
}
}  // namespace

TEST(CellFileBuilders, MultiWallEqualsTheLibraryBuilder) {
  const CellInput in = readText("[builder]\ntype = \"multiwall\"\nwalls = [[5, 5], [10, 10]]\n");
  const ObjectiveCell ref =
      buildMultiWallTranslational({{5, 5}, {10, 10}}, 1.42 * units::kAngstromInBohr);
  ASSERT_EQ(in.cell.atomCount(), ref.atomCount());
  EXPECT_EQ(in.cell.atomCount(), 60);
  EXPECT_LT((in.cell.positions - ref.positions).cwiseAbs().maxCoeff(), 1e-12);
}

// rotation_order = 5: the C5 sector of every wall (28 + 32 atoms), as buildMultiWallSector.
TEST(CellFileBuilders, MultiWallSectorEqualsTheLibraryBuilder) {
  const CellInput in =
      readText("[builder]\ntype = \"multiwall\"\nwalls = [[35, 35], [40, 40]]\nrotation_order = 5\n");
  const ObjectiveCell ref = buildMultiWallSector({{35, 35}, {40, 40}}, 1.42 * units::kAngstromInBohr, 5);
  ASSERT_EQ(in.cell.atomCount(), 60);
  ASSERT_EQ(in.cell.atomCount(), ref.atomCount());
  EXPECT_LT((in.cell.positions - ref.positions).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(in.cell.symmetry.rotationOrder(), 5);
}

TEST(CellFileBuilders, GrapheneRingEqualsTheLibraryBuilder) {
  const CellInput in = readText(
      "[builder]\ntype = \"graphene_ring\"\nlayers = 3\ndirection = \"armchair\"\n"
      "rotation_order = 200\ninterlayer = 3.4\n");
  const ObjectiveCell ref = buildGrapheneRingSector(
      3, Direction::Armchair, 200, 1, 3.4 * units::kAngstromInBohr, 1.42 * units::kAngstromInBohr);
  ASSERT_EQ(in.cell.atomCount(), ref.atomCount());
  EXPECT_LT((in.cell.positions - ref.positions).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(in.cell.symmetry.rotationOrder(), 200);
}

TEST(CellFileBuilders, BadBuilderInputNamesTheKey) {
  auto message = [](const std::string& builder) {
    try {
      readText(builder);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("[builder]\ntype = \"multiwall\"\nwalls = [[5, 5], [7]]\n").find("walls"),
            std::string::npos);
  EXPECT_NE(message("[builder]\ntype = \"multiwall\"\nwalls = [[5, 5], [10, 0]]\n").find("commensurate"),
            std::string::npos);
  EXPECT_NE(message("[builder]\ntype = \"graphene_ring\"\nlayers = 2\ndirection = \"diagonal\"\n"
                    "rotation_order = 100\n").find("direction"),
            std::string::npos);
  EXPECT_NE(message("[builder]\ntype = \"graphene_ring\"\nlayers = 2\ndirection = \"zigzag\"\n"
                    "rotation_order = 100\nspacing = 3.4\n").find("spacing"),
            std::string::npos);
  EXPECT_NE(message("[builder]\ntype = \"helix\"\n").find("type"), std::string::npos);
  EXPECT_NE(message("[builder]\ntype = \"multiwall\"\nwalls = [[35, 35], [40, 40]]\nrotation_order = 0\n")
                .find("rotation_order"),
            std::string::npos);
  EXPECT_NE(message("[builder]\ntype = \"multiwall\"\nwalls = [[35, 35], [40, 40]]\nrotation_order = 7\n")
                .find("divisor of gcd"),
            std::string::npos);
}

TEST(CellFileBuilders, ChiralGrapheneRingEqualsTheLibraryBuilder) {
  const CellInput in = readText(
      "[builder]\ntype = \"graphene_ring\"\nlayers = 2\ndirection = \"chiral\"\nchiral = [4, 2]\n"
      "rotation_order = 40\ncells_along_arc = 2\ninterlayer = 3.4\nbond_length = 1.43\n");
  // [4, 2] is reduced to the primitive direction (2, 1): 28 atoms per layer and cell.
  const ObjectiveCell ref = buildGrapheneRingSector(
      2, ChiralIndices{2, 1}, 40, 2, 3.4 * units::kAngstromInBohr, 1.43 * units::kAngstromInBohr);
  ASSERT_EQ(in.cell.atomCount(), 2 * 2 * 28);
  ASSERT_EQ(in.cell.atomCount(), ref.atomCount());
  EXPECT_LT((in.cell.positions - ref.positions).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(in.cell.symmetry.rotationOrder(), 40);
  EXPECT_NEAR(in.cell.symmetry.translation(), ref.symmetry.translation(), 1e-12);
}

TEST(CellFileBuilders, BadChiralIndicesNameTheFileAndKey) {
  auto message = [](const std::string& keys) {
    try {
      readText("[builder]\ntype = \"graphene_ring\"\nlayers = 2\nrotation_order = 100\n" + keys);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const char* bad[] = {
      "direction = \"chiral\"\nchiral = [-2, 1]\n",   // negative
      "direction = \"chiral\"\nchiral = [2, -1]\n",   // negative
      "direction = \"chiral\"\nchiral = [0, 0]\n",    // no direction
      "direction = \"chiral\"\nchiral = [1, 2]\n",    // m > n
      "direction = \"chiral\"\nchiral = [2]\n",       // not a pair
      "direction = \"chiral\"\nchiral = [2.0, 1]\n",  // not integers
      "direction = \"chiral\"\nchiral = \"2,1\"\n",   // not an array
      "direction = \"chiral\"\n",                     // missing
      "direction = \"armchair\"\nchiral = [2, 1]\n",  // chiral without direction = "chiral"
  };
  for (const char* keys : bad) {
    const std::string e = message(keys);
    EXPECT_NE(e.find("chiral"), std::string::npos) << keys << ": " << e;
    EXPECT_NE(e.find("mesochain_builder_"), std::string::npos) << keys << ": " << e;  // the file
    EXPECT_NE(e.find("builder.chiral"), std::string::npos) << keys << ": " << e;      // the key
  }
}
