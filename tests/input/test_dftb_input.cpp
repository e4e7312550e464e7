// The mapping of DFTB+'s input onto the cell settings (input/hsd/dftb_input.hpp): k-point
// schemes, units, defaults, dispersion parameters, the task; and the errors for keywords
// outside the subset, wrong types, units DFTB+ does not accept and missing files.
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "hsd_support.hpp"
#include "input/hsd/dftb_input.hpp"
#include "input/hsd/dftbplus_units.hpp"
#include "objective/core/uff_parameters.hpp"
#include "input/cell_calculator.hpp"

using namespace mesochain;
using namespace mesochain::input::hsd;
using mesochain::testing::methaneInput;

using mesochain::testing::errorOf;

namespace {

// A methane input with `hamiltonianExtra` inside Hamiltonian = DFTB { ... } and `rest` after it.
std::string methane(const std::string& hamiltonianExtra, const std::string& rest = "",
                    const std::string& filling = "Filling = Fermi { Temperature [K] = 300 }") {
  return "Geometry = GenFormat {\n  <<< \"geo.gen\"\n}\n"
         "Hamiltonian = DFTB {\n"
         "  MaxAngularMomentum { C = \"p\"; H = \"s\" }\n  " + filling + "\n"
         "  SlaterKosterFiles = Type2FileNames {\n"
         "    Prefix = \"/work/shared/params/pbc-0-3/\"\n    Separator = \"-\"\n    Suffix = \".skf\"\n  }\n" +
         hamiltonianExtra + "\n}\n" + rest;
}

objective::CellInput read(const std::string& name, const std::string& text) {
  return readDftbInput(methaneInput(name, text));
}

// A (5,5) input with the geometry of tests/data/dftbplus/`geometryCase` and `kpoints`, in the
// temporary folder `name`.
objective::CellInput cnt55Input(const std::string& name, const std::string& geometryCase, const std::string& kpoints) {
  const std::string d = mesochain::testing::hsdTempDir(name);
  mesochain::testing::writeText(d + "/geo.gen", mesochain::testing::readText(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/" + geometryCase + "/geo.gen"));
  mesochain::testing::writeText(d + "/dftb_in.hsd", mesochain::testing::localPrefix(
      "Geometry = GenFormat { <<< \"geo.gen\" }\nHamiltonian = DFTB {\n  MaxAngularMomentum { C = \"p\" }\n"
      "  Filling = Fermi { Temperature [Kelvin] = 1000 }\n"
      "  SlaterKosterFiles = Type2FileNames { Prefix = \"/work/shared/params/pbc-0-3/\"; Separator = \"-\"; Suffix = \".skf\" }\n"
      "  KPointsAndWeights = " + kpoints + "\n}\n"));
  return readDftbInput(d + "/dftb_in.hsd");
}

// A helical (5,5)-motif input (the geometry of tests/data/dftbplus/cnt55_helical) with `kpoints`.
objective::CellInput helical(const std::string& name, const std::string& kpoints) {
  return cnt55Input(name, "cnt55_helical", kpoints);
}
}  // namespace

TEST(DftbInput, DefaultsAndTaskAreDftbPlus) {
  const auto in = read("defaults", methane("", "Analysis { PrintForces = No }\n"));
  EXPECT_EQ(in.task.type, "energy");
  EXPECT_FALSE(in.scc.enabled);
  EXPECT_EQ(in.dispersion.model(), "none");
  EXPECT_EQ(in.band.helicalKPoints, 1);
  EXPECT_EQ(in.maxAngularMomentum.at("C"), 1);
  EXPECT_EQ(in.maxAngularMomentum.at("H"), 0);
  EXPECT_EQ(in.parameterFiles.size(), 4u);
  // Temperature [K] with DFTB+'s k_B (3.16681534524639e-6 Ha/K, not CODATA's).
  EXPECT_DOUBLE_EQ(in.band.electronicTemperature, 300 * 3.16681534524639e-6);
  // SCC = Yes alone: DFTB+'s SCCTolerance 1e-5 and 100 iterations, charges only.
  const auto scc = read("scc-defaults", methane("SCC = Yes"));
  EXPECT_TRUE(scc.scc.enabled);
  EXPECT_EQ(scc.scc.chargeTolerance, 1e-5);
  EXPECT_EQ(scc.scc.maxIterations, 100);
  EXPECT_EQ(scc.scc.energyTolerance, 1.0);
  EXPECT_EQ(scc.scc.ewaldTolerance, dftb::SccSettings{}.ewaldTolerance);  // mesochain's default
  const auto ewald = read("scc-ewald", methane("SCC = Yes\n  EwaldTolerance = 1e-12\n  EwaldParameter = 0.3"));
  EXPECT_EQ(ewald.scc.ewaldTolerance, 1e-12);
  // A relaxation: DFTB+'s defaults, or the given force in its unit.
  const auto lbfgs = read("lbfgs", methane("", "Driver = LBFGS {}\n"));
  EXPECT_EQ(lbfgs.task.type, "relax");
  EXPECT_EQ(lbfgs.task.forceTolerance, 1e-4);
  EXPECT_EQ(lbfgs.task.maxSteps, 200);
  const auto cg = read("cg", methane("", "Driver = ConjugateGradient {\n  MaxForceComponent [eV/AA] = 0.01\n  MaxSteps = 50\n}\n"));
  EXPECT_EQ(cg.task.type, "relax");
  EXPECT_DOUBLE_EQ(cg.task.forceTolerance, 0.01 / 27.2113845 * 0.529177249);
  EXPECT_EQ(cg.task.maxSteps, 50);
  EXPECT_EQ(read("none", methane("", "Driver = {}\nAnalysis { PrintForces = Yes }\n")).task.type, "forces");
}

TEST(DftbInput, TemperatureUnitsAreDftbPlusUnits) {
  // No unit: Hartree, as in DFTB+.
  EXPECT_EQ(read("t-au", methane("", "", "Filling = Fermi { Temperature = 0.001 }")).band.electronicTemperature, 0.001);
  EXPECT_DOUBLE_EQ(read("t-ev", methane("", "", "Filling = Fermi { Temperature [eV] = 0.1 }")).band.electronicTemperature,
                   0.1 / 27.2113845);
  const std::string m = errorOf([] { read("t-bad", methane("", "", "Filling = Fermi { Temperature [Angstrom] = 300 }")); });
  EXPECT_NE(m.find("line 6"), std::string::npos) << m;
  EXPECT_NE(m.find("[Angstrom]"), std::string::npos) << m;
  EXPECT_NE(m.find("kelvin"), std::string::npos) << m;  // the accepted units are listed
  // DFTB+'s default of 0 K is outside what mesochain can fill.
  EXPECT_NE(errorOf([] { read("t-zero", methane("", "", "Filling = Fermi { Temperature = 0 }")); }).find("Temperature"),
            std::string::npos);
  EXPECT_NE(errorOf([] { read("t-none", methane("", "", "")); }).find("no Filling"), std::string::npos);
}

TEST(DftbInput, HelicalKPointsMapOntoTheMidpointGrid) {
  // DFTB+: k1 = (i + 1/2)/(2N), i < N, all k2: half of the 2N-point midpoint grid.
  EXPECT_EQ(helical("hu40", "HelicalUniform { 40 0.5 }").band.helicalKPoints, 80);
  EXPECT_EQ(helical("hu40", "HelicalUniform { 40 0.5 }").band.angular.samples, 0);
  const std::string m = errorOf([] { helical("hu0", "HelicalUniform { 40 0.0 }"); });
  EXPECT_NE(m.find("shift 0"), std::string::npos) << m;
  EXPECT_NE(m.find("line 6"), std::string::npos) << m;
  // C_5: N2 = 5 is every mu; N2 = 1 samples mu = floor(5/2) = 2, i.e. k2 shift 2/5.
  const auto all = helical("hs-all", "HelicalSampled { 20 5 0.5 0.0 }");
  EXPECT_EQ(all.band.helicalKPoints, 40);
  EXPECT_EQ(all.band.angular.samples, 0);
  const auto one = helical("hs-one", "HelicalSampled { 20 1 0.5 0.4 }");
  EXPECT_EQ(one.band.angular.samples, 1);
  EXPECT_NE(errorOf([] { helical("hs-shift", "HelicalSampled { 20 1 0.5 0.0 }"); }).find("angular shift"),
            std::string::npos);
  EXPECT_NE(errorOf([] { helical("hs-div", "HelicalSampled { 20 2 0.5 0.0 }"); }).find("divisor"), std::string::npos);
  EXPECT_NE(errorOf([] { helical("sf", "SupercellFolding { 1 0 0 0 1 0 0 0 4 0 0 0.5 }"); }).find("SupercellFolding"),
            std::string::npos);
}

TEST(DftbInput, SupercellFoldingNeedsTheMidpointShift) {
  auto input = [](const std::string& folding) {
    return cnt55Input("folding", "cnt55_translational",
                      "SupercellFolding {\n    1 0 0\n    0 1 0\n    0 0 " + folding + "\n  }");
  };
  EXPECT_EQ(input("16\n 0.0 0.0 0.5").band.helicalKPoints, 16);
  EXPECT_EQ(input("5\n 0.0 0.0 0.0").band.helicalKPoints, 5);  // odd N: the midpoint grid holds k = 0
  std::string m = errorOf([&] { input("16\n 0.0 0.0 0.0"); });
  EXPECT_NE(m.find("0.5 for N even"), std::string::npos) << m;
  m = errorOf([&] { input("16\n 0.5 0.0 0.5"); });
  EXPECT_NE(m.find("along a and b"), std::string::npos) << m;
}

TEST(DftbInput, KeywordsOutsideTheSubsetAreErrorsWithTheirLine) {
  std::string m = errorOf([] { read("third", methane("  ThirdOrderFull = Yes")); });
  EXPECT_NE(m.find("line 12"), std::string::npos) << m;
  EXPECT_NE(m.find("ThirdOrderFull"), std::string::npos) << m;
  EXPECT_NE(m.find("SlaterKosterFiles"), std::string::npos) << m;  // the allowed keywords
  m = errorOf([] { read("top", methane("", "ExcitedState { }\n")); });
  EXPECT_NE(m.find("ExcitedState"), std::string::npos) << m;
  m = errorOf([] { read("wrongtype", methane("  SCC = Maybe")); });
  EXPECT_NE(m.find("'maybe'"), std::string::npos) << m;
  EXPECT_NE(m.find("Yes or No"), std::string::npos) << m;
  m = errorOf([] { read("scctol", methane("  SCCTolerance = 1e-8")); });
  EXPECT_NE(m.find("with SCC = No"), std::string::npos) << m;
  m = errorOf([] { read("ewaldtol", methane("  EwaldTolerance = 1e-8")); });
  EXPECT_NE(m.find("with SCC = No"), std::string::npos) << m;
  m = errorOf([] { read("ewaldrange", methane("  SCC = Yes\n  EwaldTolerance = 1e-15")); });
  EXPECT_NE(m.find("line 13"), std::string::npos) << m;
  EXPECT_NE(m.find("[1e-13, 1e-2]"), std::string::npos) << m;
  m = errorOf([] { read("ewaldalpha", methane("  SCC = Yes\n  EwaldParameter = -0.3")); });
  EXPECT_NE(m.find("EwaldParameter"), std::string::npos) << m;
  EXPECT_NE(m.find(">= 0"), std::string::npos) << m;
  m = errorOf([] { read("mixer", methane("  SCC = Yes\n  Mixer = Broyden { MixingParameter = 0.1 }")); });
  EXPECT_NE(m.find("Mixer"), std::string::npos) << m;
  m = errorOf([] { read("twice", methane("  SCC = Yes\n  SCC = No")); });
  EXPECT_NE(m.find("a second time"), std::string::npos) << m;
  m = errorOf([] { read("driver", methane("", "Driver = VelocityVerlet {}\n")); });
  EXPECT_NE(m.find("VelocityVerlet"), std::string::npos) << m;
  m = errorOf([] { read("omp", methane("", "Parallel { UseOmpThreads = No }\n")); });
  EXPECT_NE(m.find("UseOmpThreads"), std::string::npos) << m;
  m = errorOf([] { read("parser", methane("", "ParserOptions { ParserVersion = 15 }\n")); });
  EXPECT_NE(m.find("15"), std::string::npos) << m;
  m = errorOf([] { read("oldforces", methane("", "Analysis { CalculateForces = Yes }\n")); });
  EXPECT_NE(m.find("PrintForces"), std::string::npos) << m;
}

TEST(DftbInput, TablesNameTheMissingFile) {
  std::string text = methane("");
  text.replace(text.find("Suffix = \".skf\""), 15, "Suffix = \".none\"");
  const std::string m = errorOf([&] { read("missing-skf", text); });
  EXPECT_NE(m.find("C-C.none"), std::string::npos) << m;
  EXPECT_NE(m.find("line 7"), std::string::npos) << m;
  // Explicit pairs: every ordered pair, existing files.
  const std::string p = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/";
  std::string explicitText = methane("");
  const auto from = explicitText.find("SlaterKosterFiles = Type2FileNames");
  const auto to = explicitText.find("}\n", from) + 2;
  explicitText.replace(from, to - from,
                       "SlaterKosterFiles {\n    C-C = \"" + p + "C-C.skf\"\n    C-H = \"" + p + "C-H.skf\"\n    H-C = \"" + p +
                           "H-C.skf\"\n    H-H = \"" + p + "H-H.skf\"\n  }\n");
  EXPECT_EQ(read("explicit-skf", explicitText).parameterFiles.at("H-C"), p + "H-C.skf");
  explicitText.replace(explicitText.find("    H-H"), explicitText.find("\n", explicitText.find("    H-H")) - explicitText.find("    H-H"), "");
  EXPECT_NE(errorOf([&] { read("explicit-missing", explicitText); }).find("H-H"), std::string::npos);
}

TEST(DftbInput, LennardJonesParametersAsDftbPlusConvertsThem) {
  // UFFParameters {}: Rappe et al. 1992 values with DFTB+'s Å and kcal/mol.
  const auto uff = read("uff", methane("  Dispersion = LennardJones { Parameters = UFFParameters {} }"));
  EXPECT_EQ(uff.dispersion.model(), "lj");
  EXPECT_TRUE(uff.dispersion.lj.ewald);
  ASSERT_EQ(uff.dispersion.lj.elements.size(), 2u);
  EXPECT_DOUBLE_EQ(dftb::ljElements(uff.dispersion.lj).at("C").r0, 3.851 / 0.529177249);
  EXPECT_DOUBLE_EQ(dftb::ljElements(uff.dispersion.lj).at("C").epsilon, 0.105 * 0.0015946683859874898);
  EXPECT_DOUBLE_EQ(dftb::ljElements(uff.dispersion.lj).at("H").r0, 2.886 / 0.529177249);
  EXPECT_DOUBLE_EQ(dftb::ljElements(uff.dispersion.lj).at("H").epsilon, 0.044 * 0.0015946683859874898);
  // Explicit values in their units (Bohr and Hartree without one).
  const auto ex = read("lj-explicit", methane("  Dispersion = LennardJones {\n    Parameters {\n"
                                              "      C { Distance [AA] = 3.80; Energy [kcal/mol] = 0.069 }\n"
                                              "      H { Distance = 5.0; Energy = 1e-4 }\n    }\n  }"));
  EXPECT_DOUBLE_EQ(dftb::ljElements(ex.dispersion.lj).at("C").r0, 3.80 / 0.529177249);
  EXPECT_DOUBLE_EQ(dftb::ljElements(ex.dispersion.lj).at("C").epsilon, 0.069 * 0.0015946683859874898);
  EXPECT_EQ(dftb::ljElements(ex.dispersion.lj).at("H").r0, 5.0);
  EXPECT_EQ(dftb::ljElements(ex.dispersion.lj).at("H").epsilon, 1e-4);
  const std::string m = errorOf([] {
    read("lj-partial", methane("  Dispersion = LennardJones {\n    Parameters {\n      C { Distance = 7; Energy = 1e-4 }\n    }\n  }"));
  });
  EXPECT_NE(m.find("no parameters for H"), std::string::npos) << m;
}

TEST(DftbInput, UnitsAreDftbPlusConstants) {
  EXPECT_DOUBLE_EQ(*unitFactor(UnitKind::Length, "Angstrom"), 1 / 0.529177249);
  EXPECT_DOUBLE_EQ(*unitFactor(UnitKind::Length, "pm"), 0.01 / 0.529177249);
  EXPECT_DOUBLE_EQ(*unitFactor(UnitKind::Energy, "Kelvin"), 3.16681534524639e-6);
  EXPECT_DOUBLE_EQ(*unitFactor(UnitKind::Energy, "Ry"), 0.5);
  EXPECT_FALSE(unitFactor(UnitKind::Energy, "nm"));   // a wavelength: not converted
  EXPECT_FALSE(unitFactor(UnitKind::Length, "kelvin"));
  // DFTB+'s Bohr differs from CODATA 2018's by 7.2e-8 relative, its kcal/mol by 6.7e-4.
  EXPECT_NEAR(kDftbPlusAngstromInBohr / units::kAngstromInBohr - 1, -7.2e-8, 0.1e-8);
  EXPECT_NEAR(kDftbPlusKcalPerMolInHartree / units::kKcalPerMolInHartree - 1, 6.7e-4, 0.1e-4);
}

TEST(DftbInput, InlineGeometryEqualsTheIncludedFile) {
  const std::string gen = mesochain::testing::readText(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/ch4/geo.gen");
  std::string text = methane("");
  text.replace(text.find("  <<< \"geo.gen\"\n"), 16, gen);
  const auto inline_ = read("inline-gen", text);
  const auto included = read("included-gen", methane(""));
  ASSERT_EQ(inline_.cell.atomCount(), 5);
  EXPECT_TRUE(inline_.cell.positions == included.cell.positions);
  EXPECT_EQ(inline_.cell.speciesNames, included.cell.speciesNames);
  // An error in an inline .gen line names the line of the .hsd (line 1 is "Geometry = ...",
  // the atom lines follow the count and element lines).
  std::string bad = text;
  bad.replace(bad.find("    3  2"), 8, "    3  x");
  const std::string m = errorOf([&] { read("inline-bad", bad); });
  EXPECT_NE(m.find("dftb_in.hsd, line 6"), std::string::npos) << m;
}

TEST(DftbInput, UffDispersionOfAMoleculeIsTheSumOverPairs) {
  // Methane with UFFParameters {}: the dispersion energy is the sum over the 10 pairs of the
  // UFF-type potential (Zhechkov et al. 2005; switched polynomial inside 2^(-1/6) r0) with
  // geometric means of Rappe et al.'s values, in DFTB+'s units.
  const auto in = read("uff-energy", methane("  Dispersion = LennardJones { Parameters = UFFParameters {} }"));
  const dftb::Result r = objective::makeCalculator(in).evaluate(in.cell, {true, false});
  auto pair = [](double eps, double r0, double d) {
    const double rs = std::pow(2.0, -1.0 / 6.0) * r0;
    if (d >= rs) return eps * (std::pow(r0 / d, 12) - 2 * std::pow(r0 / d, 6));
    return 396.0 / 25.0 * eps - std::pow(2.0, 5.0 / 6.0) * 672.0 / 25.0 * eps * std::pow(d / r0, 5) +
           std::pow(2.0, 2.0 / 3.0) * 552.0 / 25.0 * eps * std::pow(d / r0, 10);
  };
  const double kcal = 0.0015946683859874898, bohr = 0.529177249;
  auto eps = [&](const std::string& el) { return (el == "C" ? 0.105 : 0.044) * kcal; };
  auto r0 = [&](const std::string& el) { return (el == "C" ? 3.851 : 2.886) / bohr; };
  double expected = 0;
  for (int i = 0; i < in.cell.atomCount(); ++i)
    for (int j = i + 1; j < in.cell.atomCount(); ++j) {
      const std::string a = in.cell.speciesOf(i), b = in.cell.speciesOf(j);
      expected += pair(std::sqrt(eps(a) * eps(b)), std::sqrt(r0(a) * r0(b)),
                       (in.cell.positions.col(i) - in.cell.positions.col(j)).norm());
    }
  EXPECT_NEAR(r.energies.at("dispersion"), expected, 1e-12 * std::abs(expected));
  EXPECT_NE(expected, 0.0);
}

TEST(DftbInput, Type2FileNamesWithLowerCaseTypeNames) {
  // Prefix + a + Separator + b + Suffix with the element names lower-cased; the prefix relative
  // to the folder of the input.
  const std::string d = mesochain::testing::hsdTempDir("lowercase");
  std::filesystem::create_directories(d + "/skf");
  for (const char* pair : {"C-C", "C-H", "H-C", "H-H"}) {
    std::string name = pair;  // "C-H" -> "c_h"
    for (char& c : name) c = c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::filesystem::path target = std::filesystem::path(d) / "skf" / (name + ".table");
    std::filesystem::copy_file(std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/" + pair + ".skf", target,
                               std::filesystem::copy_options::overwrite_existing);
  }
  std::string text = methane("");
  const auto from = text.find("SlaterKosterFiles = Type2FileNames");
  const auto to = text.find("}\n", from) + 2;
  text.replace(from, to - from,
               "SlaterKosterFiles = Type2FileNames {\n    Prefix = \"skf/\"\n    Separator = \"_\"\n"
               "    Suffix = \".table\"\n    LowerCaseTypeName = Yes\n  }\n");
  const std::string path = methaneInput("lowercase", text);
  const auto in = readDftbInput(path);
  EXPECT_EQ(in.parameterFiles.at("C-H"), d + "/skf/c_h.table");
  EXPECT_EQ(in.parameterFiles.at("H-H"), d + "/skf/h_h.table");
}
