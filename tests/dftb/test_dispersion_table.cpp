// The [dispersion] table (dftb/dispersion_table.hpp): every variant of both models written as its
// entries reads back to the same settings, the entries carry the file's units, and the reader
// keeps the keys of one model out of the other.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/dispersion_table.hpp"

using namespace mesochain;
using namespace mesochain::dftb;

namespace {

const std::vector<std::string> kSpecies{"C", "H"};

DispersionTable readText(const std::string& body) {
  std::istringstream in("[dispersion]\n" + body);
  const toml::value doc = toml::parse(in, "table.toml");
  const TomlTable t("table.toml", toml::find(doc, "dispersion"), "dispersion");
  DispersionTable d;
  readDispersionTable(t, kSpecies, d);
  return d;
}

// Equal to the last bits a Å <-> Bohr or kcal/mol <-> Hartree conversion may change.
void expectSame(const DispersionTable& a, const DispersionTable& b, const std::string& body) {
  auto near = [](double x, double y) { return std::abs(x - y) <= 1e-14 * std::max(1.0, std::abs(x)); };
  EXPECT_EQ(a.model(), b.model()) << body;
  EXPECT_EQ(a.ljParameters, b.ljParameters) << body;
  EXPECT_EQ(a.lj.enabled, b.lj.enabled) << body;
  EXPECT_TRUE(near(a.lj.epsilon, b.lj.epsilon) && near(a.lj.r0, b.lj.r0) && near(a.lj.cutoff, b.lj.cutoff)) << body;
  EXPECT_EQ(a.lj.ewald, b.lj.ewald) << body;
  EXPECT_EQ(a.lj.ewaldTolerance, b.lj.ewaldTolerance) << body;
  EXPECT_EQ(a.lj.elements, b.lj.elements) << body;
  ASSERT_EQ(a.lj.elementEpsilon.size(), b.lj.elementEpsilon.size()) << body;
  for (std::size_t k = 0; k < a.lj.elementEpsilon.size(); ++k)
    EXPECT_TRUE(near(a.lj.elementEpsilon[k], b.lj.elementEpsilon[k]) && near(a.lj.elementR0[k], b.lj.elementR0[k]))
        << body;
  EXPECT_EQ(a.kc.enabled, b.kc.enabled) << body;
  EXPECT_EQ(a.kc.parameters, b.kc.parameters) << body;
  EXPECT_TRUE(near(a.kc.cutoff, b.kc.cutoff) && near(a.kc.taperStart, b.kc.taperStart) &&
              near(a.kc.bondCutoff, b.kc.bondCutoff))
      << body;
}

}  // namespace

TEST(DispersionTable, EveryVariantReadsBackFromItsEntries) {
  for (const char* body :
       {"model = \"none\"\n", "model = \"lj\"\n",
        "model = \"lj\"\nepsilon = 0.1\nr0 = 3.5\ncutoff = 20\nsummation = \"ewald\"\newald_tolerance = 1e-10\n",
        "model = \"lj\"\nparameters = \"uff\"\n",
        "model = \"lj\"\nelements = { C = { epsilon = 0.07, r0 = 3.8 }, H = { epsilon = 0.05, r0 = 3.0 } }\n",
        "model = \"kc\"\n",
        "model = \"kc\"\nparameters = \"ouyang2018\"\ncutoff = 14\ntaper_start = 2.5\nbond_cutoff = 1.8\n"}) {
    const DispersionTable d = readText(body);
    const std::string written = tomlTableText(dispersionTableEntries(d));
    expectSame(readText(written), d, std::string(body) + "--- written as ---\n" + written);
  }
}

TEST(DispersionTable, EntriesAreInTheFileUnits) {
  const DispersionTable d = readText("model = \"lj\"\nepsilon = 0.1\nr0 = 3.5\ncutoff = 20\n");
  EXPECT_NEAR(d.lj.epsilon, 0.1 * units::kKcalPerMolInHartree, 1e-18);
  EXPECT_NEAR(d.lj.r0, 3.5 * units::kAngstromInBohr, 1e-13);
  bool sawR0 = false;
  for (const SettingEntry& e : dispersionTableEntries(d)) {
    if (e.key == "r0") {
      sawR0 = true;
      EXPECT_NEAR(e.value.as_floating(), 3.5, 1e-13);
      EXPECT_EQ(e.comment, "Å");
    }
    if (e.key == "epsilon") {
      EXPECT_NEAR(e.value.as_floating(), 0.1, 1e-15);
    }
  }
  EXPECT_TRUE(sawR0);
}

TEST(DispersionTable, KeysOfTheOtherModelAreRefused) {
  EXPECT_THROW(readText("model = \"kc\"\nepsilon = 0.1\n"), InputError);
  EXPECT_THROW(readText("model = \"lj\"\nbond_cutoff = 1.7\n"), InputError);
  EXPECT_THROW(readText("model = \"none\"\ncutoff = 10\n"), InputError);
  try {
    readText("model = \"lj\"\nparameters = \"kc2005\"\n");
    ADD_FAILURE() << "parameters = \"kc2005\" with model = \"lj\" was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dispersion.parameters"), std::string::npos) << e.what();
  }
}
