// [dispersion] per-element Lennard-Jones parameters of the cell file: parameters = "uff" (the
// UFF table, Rappe et al. 1992, with the cell file's CODATA units), explicit elements = {...},
// the errors for mixing them or leaving an element out, and the writer's round trip.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_file.hpp"
#include "objective/core/uff_parameters.hpp"

using namespace mesochain;
using namespace mesochain::objective;
namespace fs = std::filesystem;

namespace {
fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / (std::string("mesochain_disp_") + info->name() + "_" +
                                                   std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A C-H chain cell file with `dispersion` as the body of its [dispersion] table.
CellInput readWith(const std::string& dispersion) {
  const fs::path p = scratch() / "ch.toml";
  std::ofstream(p) << "format = 1\n[geometry]\nunit = \"angstrom\"\n"
                      "atoms = [[\"C\", 0.0, 0.0, 0.0], [\"H\", 1.09, 0.0, 0.0]]\n"
                      "[symmetry]\ntranslation = 2.5\ntwist = 0\nrotation_order = 1\n"
                      "[kpoints]\nhelical = 4\n[electrons]\ntemperature = 300\n"
                      "[parameters]\nset = \"pbc-0-3\"\n[dispersion]\nmodel = \"lj\"\n"
                   << dispersion;
  return readCellFile(p.string());
}

std::string errorOf(const std::string& dispersion) {
  try {
    readWith(dispersion);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(CellFileDispersion, UffParametersForEveryElement) {
  const CellInput in = readWith("parameters = \"uff\"\n");
  EXPECT_EQ(in.dispersion.ljParameters, "uff");
  ASSERT_EQ(in.dispersion.lj.elements.size(), 2u);
  // Rappe et al. 1992, Table 1: C 3.851 Å / 0.105 kcal/mol, H 2.886 Å / 0.044 kcal/mol.
  EXPECT_DOUBLE_EQ(dftb::ljElements(in.dispersion.lj).at("C").r0, 3.851 * units::kAngstromInBohr);
  EXPECT_DOUBLE_EQ(dftb::ljElements(in.dispersion.lj).at("C").epsilon, 0.105 * units::kKcalPerMolInHartree);
  EXPECT_DOUBLE_EQ(dftb::ljElements(in.dispersion.lj).at("H").r0, 2.886 * units::kAngstromInBohr);
  EXPECT_DOUBLE_EQ(dftb::ljElements(in.dispersion.lj).at("H").epsilon, 0.044 * units::kKcalPerMolInHartree);
  EXPECT_EQ(in.dispersion.lj.epsilon, 0.0);
  ASSERT_TRUE(uffParameters("Kr"));
  EXPECT_FALSE(uffParameters("Rb"));  // beyond the table: explicit values needed
}

TEST(CellFileDispersion, ExplicitElements) {
  const CellInput in =
      readWith("elements = { C = { epsilon = 0.069, r0 = 3.80 }, H = { epsilon = 0.05, r0 = 3.0 } }\n");
  EXPECT_DOUBLE_EQ(dftb::ljElements(in.dispersion.lj).at("C").epsilon, 0.069 * units::kKcalPerMolInHartree);
  EXPECT_DOUBLE_EQ(dftb::ljElements(in.dispersion.lj).at("H").r0, 3.0 * units::kAngstromInBohr);
  EXPECT_TRUE(in.dispersion.ljParameters.empty());
}

TEST(CellFileDispersion, ErrorsNameTheKey) {
  EXPECT_NE(errorOf("parameters = \"uff\"\nepsilon = 0.1\n").find("epsilon"), std::string::npos);
  EXPECT_NE(errorOf("parameters = \"uff\"\nelements = { C = { epsilon = 0.1, r0 = 3 } }\n").find("both"),
            std::string::npos);
  EXPECT_NE(errorOf("parameters = \"mmff\"\n").find("\"mmff\""), std::string::npos);
  std::string m = errorOf("elements = { C = { epsilon = 0.069, r0 = 3.80 } }\n");
  EXPECT_NE(m.find("no entry for element H"), std::string::npos) << m;
  m = errorOf("elements = { C = { epsilon = 0.069, r0 = 3.8 }, H = { epsilon = 0.05, r0 = 3 }, N = { epsilon = 1, r0 = 3 } }\n");
  EXPECT_NE(m.find("not in the cell"), std::string::npos) << m;
  m = errorOf("elements = { C = { epsilon = 0.069 }, H = { epsilon = 0.05, r0 = 3 } }\n");
  EXPECT_NE(m.find("dispersion.elements.C.r0"), std::string::npos) << m;
  m = errorOf("elements = { C = { epsilon = -1, r0 = 3 }, H = { epsilon = 0.05, r0 = 3 } }\n");
  EXPECT_NE(m.find("positive"), std::string::npos) << m;
}

TEST(CellFileDispersion, WriterRoundTrip) {
  for (const char* body : {"parameters = \"uff\"\nsummation = \"ewald\"\n",
                           "elements = { C = { epsilon = 0.069, r0 = 3.80 }, H = { epsilon = 0.05, r0 = 3.0 } }\n"}) {
    const CellInput in = readWith(body);
    const fs::path out = scratch() / "written.toml";
    writeCellFile(out.string(), in);
    const CellInput back = readCellFile(out.string());
    EXPECT_EQ(back.dispersion.ljParameters, in.dispersion.ljParameters);
    EXPECT_EQ(back.dispersion.lj.ewald, in.dispersion.lj.ewald);
    ASSERT_EQ(back.dispersion.lj.elements.size(), in.dispersion.lj.elements.size());
    for (const auto& [el, p] : dftb::ljElements(in.dispersion.lj)) {
      EXPECT_NEAR(dftb::ljElements(back.dispersion.lj).at(el).epsilon, p.epsilon, 1e-18) << el;
      EXPECT_NEAR(dftb::ljElements(back.dispersion.lj).at(el).r0, p.r0, 1e-14) << el;
    }
  }
}
