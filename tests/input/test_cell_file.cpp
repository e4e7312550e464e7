#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_file.hpp"
#include "objective/core/nanotube_builder.hpp"

using namespace mesochain;
using namespace mesochain::objective;
namespace fs = std::filesystem;
using units::kAngstromInBohr;

namespace {

const std::string kSource = MESOCHAIN_SOURCE_DIR;
const std::string kData = std::string(MESOCHAIN_TEST_DATA) + "/cell/";

// A fresh directory per test.
fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       (std::string("mesochain_") + info->name() + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

void expectSameInput(const CellInput& a, const CellInput& b) {
  ASSERT_EQ(a.cell.atomCount(), b.cell.atomCount());
  EXPECT_EQ(a.cell.speciesNames, b.cell.speciesNames);
  EXPECT_EQ(a.cell.species, b.cell.species);
  EXPECT_LT((a.cell.positions - b.cell.positions).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(a.cell.symmetry.translation(), b.cell.symmetry.translation(), 1e-12);
  EXPECT_NEAR(a.cell.symmetry.twist(), b.cell.symmetry.twist(), 1e-12);
  EXPECT_EQ(a.cell.symmetry.rotationOrder(), b.cell.symmetry.rotationOrder());
  EXPECT_EQ(a.band.helicalKPoints, b.band.helicalKPoints);
  EXPECT_EQ(a.band.angular.samples, b.band.angular.samples);
  EXPECT_NEAR(a.band.electronicTemperature, b.band.electronicTemperature, 1e-15);
  EXPECT_EQ(a.parameterFiles, b.parameterFiles);
  EXPECT_EQ(a.parameterSet, b.parameterSet);
  EXPECT_EQ(a.maxAngularMomentum, b.maxAngularMomentum);
  EXPECT_EQ(a.dispersion.model(), b.dispersion.model());
  EXPECT_NEAR(a.dispersion.lj.epsilon, b.dispersion.lj.epsilon, 1e-15);
  EXPECT_NEAR(a.dispersion.lj.r0, b.dispersion.lj.r0, 1e-12);
  EXPECT_NEAR(a.dispersion.lj.cutoff, b.dispersion.lj.cutoff, 1e-12);
  EXPECT_NEAR(a.dispersion.kc.cutoff, b.dispersion.kc.cutoff, 1e-12);
  EXPECT_EQ(a.dispersion.lj.ewald, b.dispersion.lj.ewald);
  EXPECT_EQ(a.dispersion.kc.parameters, b.dispersion.kc.parameters);
  EXPECT_NEAR(a.dispersion.kc.taperStart, b.dispersion.kc.taperStart, 1e-12);
  EXPECT_NEAR(a.dispersion.kc.bondCutoff, b.dispersion.kc.bondCutoff, 1e-12);
  EXPECT_EQ(a.scc.enabled, b.scc.enabled);
  EXPECT_EQ(a.scc.chargeTolerance, b.scc.chargeTolerance);
  EXPECT_EQ(a.scc.energyTolerance, b.scc.energyTolerance);
  EXPECT_EQ(a.scc.maxIterations, b.scc.maxIterations);
  EXPECT_EQ(a.scc.mixer, b.scc.mixer);
  EXPECT_EQ(a.scc.mixing, b.scc.mixing);
  EXPECT_EQ(a.scc.ewaldTolerance, b.scc.ewaldTolerance);
  EXPECT_EQ(a.scc.stopIfUnconverged, b.scc.stopIfUnconverged);
  EXPECT_EQ(a.task.type, b.task.type);
  EXPECT_EQ(a.task.forceTolerance, b.task.forceTolerance);
  EXPECT_EQ(a.task.maxSteps, b.task.maxSteps);
  EXPECT_EQ(a.task.relaxTranslation, b.task.relaxTranslation);
}

const std::string kBase = R"(format = 1
[geometry]
unit = "angstrom"
atoms = [ ["C", 3.0, 0.0, 0.0], ["C", 2.0, 2.0, 1.0] ]
[symmetry]
translation = 2.5
twist = 10.0
rotation_order = 3
[kpoints]
helical = 4
[electrons]
temperature = 300
[parameters]
set = "pbc-0-3"
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

}  // namespace

TEST(CellFile, ReadsTheExamples) {
  const CellInput in = readCellFile(kSource + "/examples/cnt55.toml");
  const ObjectiveCell ref = buildNanotubeHelical(5, 5, 1.42 * kAngstromInBohr);
  EXPECT_EQ(in.cell.atomCount(), 2);
  EXPECT_LT((in.cell.positions - ref.positions).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(in.cell.symmetry.rotationOrder(), 5);
  EXPECT_EQ(in.band.helicalKPoints, 64);
  EXPECT_EQ(in.band.angular.samples, 0);
  EXPECT_NEAR(in.band.electronicTemperature, 300 * units::kBoltzmannHartreePerKelvin, 1e-15);
  EXPECT_EQ(in.parameterSet, "pbc-0-3");
  ASSERT_EQ(in.parameterFiles.size(), 1u);
  EXPECT_TRUE(fs::equivalent(in.parameterFiles.at("C-C"), kSource + "/params/pbc-0-3/C-C.skf"));
  EXPECT_EQ(in.dispersion.model(), "none");
  EXPECT_EQ(in.task.type, "relax");
  EXPECT_TRUE(in.task.relaxTranslation);
  EXPECT_EQ(in.task.maxSteps, 500);
  EXPECT_DOUBLE_EQ(in.task.forceTolerance, 1e-4);

  const CellInput gen = readCellFile(kSource + "/examples/cnt55_from_gen.toml");
  CellInput same = in;
  same.source = gen.source;
  expectSameInput(gen, same);
}

TEST(CellFile, ReadsSccAndWritesItBack) {
  const CellInput in = readCellFile(kSource + "/examples/benzene_scc.toml");
  EXPECT_TRUE(in.scc.enabled);
  EXPECT_DOUBLE_EQ(in.scc.chargeTolerance, 1e-9);
  EXPECT_DOUBLE_EQ(in.scc.energyTolerance, 1e-8);  // default
  EXPECT_EQ(in.scc.maxIterations, 100);
  EXPECT_EQ(in.scc.mixer, "broyden");
  EXPECT_DOUBLE_EQ(in.scc.mixing, 0.2);
  EXPECT_TRUE(in.scc.stopIfUnconverged);
  EXPECT_EQ(in.parameterFiles.size(), 4u);
  const fs::path dir = scratch();
  writeCellFile((dir / "again.toml").string(), in);
  CellInput back = readCellFile((dir / "again.toml").string());
  back.source = in.source;
  expectSameInput(in, back);
  fs::remove_all(dir);
}

TEST(CellFile, ReadsInlineAtomsExplicitTablesAndDispersion) {
  const CellInput ring = readCellFile(kData + "inline_ring.toml");
  EXPECT_TRUE(ring.cell.symmetry.isRing());
  EXPECT_EQ(ring.cell.symmetry.rotationOrder(), 12);
  EXPECT_NEAR(ring.cell.positions(0, 0), 2.74 * kAngstromInBohr, 1e-12);
  EXPECT_TRUE(fs::equivalent(ring.parameterFiles.at("C-C"), kSource + "/params/pbc-0-3/C-C.skf"));
  EXPECT_EQ(ring.maxAngularMomentum.at("C"), 1);
  EXPECT_EQ(ring.dispersion.model(), "lj");
  EXPECT_NEAR(ring.dispersion.lj.epsilon, 0.069 * units::kKcalPerMolInHartree, 1e-15);
  EXPECT_NEAR(ring.dispersion.lj.r0, 3.80 * kAngstromInBohr, 1e-12);
  EXPECT_NEAR(ring.dispersion.lj.cutoff, 25.0 * kAngstromInBohr, 1e-12);
  EXPECT_EQ(ring.task.type, "forces");

  const CellInput chain = readCellFile(kData + "ch_chain_bohr.toml");
  EXPECT_EQ(chain.cell.speciesNames, (std::vector<std::string>{"C", "H"}));
  EXPECT_DOUBLE_EQ(chain.cell.positions(2, 1), 2.1);  // Bohr as given
  EXPECT_NEAR(chain.cell.symmetry.translation(), 2.5 * kAngstromInBohr, 1e-12);
  EXPECT_EQ(chain.parameterFiles.size(), 4u);
  // "H-H" is not next to the cell file: it resolves against the project root.
  EXPECT_TRUE(fs::equivalent(chain.parameterFiles.at("H-H"), kSource + "/params/pbc-0-3/H-H.skf"));
  EXPECT_EQ(chain.task.type, "energy");  // no [task]: documented default
}

TEST(CellFile, BuilderTranslationalCell) {
  const fs::path dir = scratch();
  writeText(dir / "tube.toml", R"(format = 1
[builder]
type = "nanotube"
n = 10
m = 0
cell = "translational"
use_rotation = true
[kpoints]
helical = 8
[electrons]
temperature = 300
[parameters]
set = "pbc-0-3"
)");
  const CellInput in = readCellFile((dir / "tube.toml").string());
  EXPECT_EQ(in.cell.atomCount(), 4);  // 40 atoms / C_10
  EXPECT_EQ(in.cell.symmetry.rotationOrder(), 10);
  EXPECT_EQ(in.cell.symmetry.twist(), 0.0);
  fs::remove_all(dir);
}

// [dispersion] model = "kc": defaults (the parameter set's cutoff and taper, resolved in dftb/,
// stay unset here), explicit keys, and the round trip through writeCellFile.
TEST(CellFile, ReadsAndWritesKolmogorovCrespi) {
  const fs::path dir = scratch();
  writeText(dir / "kc.toml", kBase + "[dispersion]\nmodel = \"kc\"\n");
  const CellInput plain = readCellFile((dir / "kc.toml").string());
  EXPECT_EQ(plain.dispersion.model(), "kc");
  EXPECT_EQ(plain.dispersion.kc.parameters, "kc2005");
  EXPECT_EQ(plain.dispersion.kc.cutoff, 0.0);
  EXPECT_LT(plain.dispersion.kc.taperStart, 0.0);
  EXPECT_NEAR(plain.dispersion.kc.bondCutoff, 1.7 * kAngstromInBohr, 1e-12);
  writeText(dir / "kc2.toml", kBase + "[dispersion]\nmodel = \"kc\"\nparameters = \"ouyang2018\"\n"
                                      "cutoff = 14\ntaper_start = 2.5\nbond_cutoff = 1.8\n");
  const CellInput in = readCellFile((dir / "kc2.toml").string());
  EXPECT_EQ(in.dispersion.kc.parameters, "ouyang2018");
  EXPECT_NEAR(in.dispersion.kc.cutoff, 14.0 * kAngstromInBohr, 1e-12);
  EXPECT_NEAR(in.dispersion.kc.taperStart, 2.5 * kAngstromInBohr, 1e-12);
  EXPECT_NEAR(in.dispersion.kc.bondCutoff, 1.8 * kAngstromInBohr, 1e-12);
  for (const CellInput* c : {&plain, &in}) {
    const std::string out = (dir / "written.toml").string();
    writeCellFile(out, *c);
    expectSameInput(readCellFile(out), *c);
  }
  fs::remove_all(dir);
}

TEST(CellFile, RoundTrips) {
  const fs::path dir = scratch();
  for (const std::string& f : {kSource + "/examples/cnt55.toml", kData + "inline_ring.toml",
                               kData + "ch_chain_bohr.toml"}) {
    const CellInput in = readCellFile(f);
    const std::string out = (dir / "written.toml").string();
    writeCellFile(out, in);
    const CellInput back = readCellFile(out);
    SCOPED_TRACE(f);
    expectSameInput(back, in);
  }
  fs::remove_all(dir);
}

TEST(CellFile, EveryErrorNamesTheFileAndTheKeyOrLine) {
  const fs::path dir = scratch();
  fs::copy_file(kSource + "/examples/cnt55.gen", dir / "cnt55.gen");
  writeText(dir / "broken.gen", "2 H\nC\n1 1 3 0 0\n2 1 0 3 x\n0 0 0\n2 10 3\n");
  writeText(dir / "ok.toml", kBase);
  EXPECT_NO_THROW(readCellFile((dir / "ok.toml").string()));
  const std::string genCell = R"(format = 1
[geometry]
file = "cnt55.gen"
[symmetry]
twist = 30.0
[kpoints]
helical = 4
[electrons]
temperature = 300
[parameters]
set = "pbc-0-3"
)";
  const std::string builder =
      replaced(replaced(kBase,
                        "[geometry]\nunit = \"angstrom\"\natoms = [ [\"C\", 3.0, 0.0, 0.0], "
                        "[\"C\", 2.0, 2.0, 1.0] ]\n",
                        "[builder]\ntype = \"nanotube\"\nn = 5\nm = 0\ncell = \"zigzag\"\n"),
               "[symmetry]\ntranslation = 2.5\ntwist = 10.0\nrotation_order = 3\n", "");
  struct Case {
    std::string name, text;
    std::vector<std::string> expect;  // substrings of the message besides the file name
  };
  const std::vector<Case> cases = {
      {"unknown top key",
       replaced(kBase, "format = 1\n", "format = 1\ncolour = 1\n"),
       {"key colour (line 2)", "symmetry"}},
      {"unknown table key",
       replaced(kBase, "rotation_order = 3\n", "rotation_order = 3\npitch = 1\n"),
       {"symmetry.pitch (line 9)", "translation, twist, rotation_order"}},
      {"wrong type",
       replaced(kBase, "twist = 10.0", "twist = \"10\""),
       {"symmetry.twist (line 7)"}},
      {"missing table", replaced(kBase, "[electrons]\ntemperature = 300\n", ""), {"electrons"}},
      {"missing key", replaced(kBase, "twist = 10.0\n", ""), {"symmetry.twist", "line 5"}},
      {"order zero",
       replaced(kBase, "rotation_order = 3", "rotation_order = 0"),
       {"symmetry.rotation_order (line 8)"}},
      {"ring twist",
       replaced(kBase, "translation = 2.5", "translation = 0.0"),
       {"symmetry.twist (line 7)", "360/N_a"}},
      {"nan",
       replaced(kBase, "twist = 10.0", "twist = nan"),
       {"symmetry.twist (line 7)", "finite"}},
      {"inf temperature",
       replaced(kBase, "temperature = 300", "temperature = inf"),
       {"electrons.temperature (line 12)"}},
      {"zero temperature",
       replaced(kBase, "temperature = 300", "temperature = 0"),
       {"electrons.temperature (line 12)"}},
      // Positive but below what Fermi filling resolves (a wrong electron count), or NaN-making.
      {"temperature 1e-13 K",
       replaced(kBase, "temperature = 300", "temperature = 1e-13"),
       {"electrons.temperature (line 12)", "1e-13 K", "from 0.01 K to 100000 K"}},
      {"temperature 1e-307 K",
       replaced(kBase, "temperature = 300", "temperature = 1e-307"),
       {"electrons.temperature (line 12)", "from 0.01 K"}},
      {"temperature 1e6 K",
       replaced(kBase, "temperature = 300", "temperature = 1e6"),
       {"electrons.temperature (line 12)", "to 100000 K"}},
      {"helical k-points beyond the limit",
       replaced(kBase, "helical = 4", "helical = 2000000000"),
       {"kpoints.helical (line 10)", "from 1 to 1000000"}},
      {"dispersion cutoff of 1e6 Å",
       kBase + "[dispersion]\nmodel = \"lj\"\ncutoff = 1e6\n",
       {"dispersion.cutoff", "at most 1000 Å"}},
      {"format", replaced(kBase, "format = 1", "format = 2"), {"key format (line 1)"}},
      {"syntax", replaced(kBase, "twist = 10.0", "twist = "), {"line 7", "TOML"}},
      {"missing file",
       replaced(kBase,
                "unit = \"angstrom\"\natoms = [ [\"C\", 3.0, 0.0, 0.0], [\"C\", 2.0, 2.0, 1.0] ]",
                "file = \"nope.gen\""),
       {"geometry.file (line 3)", "does not exist"}},
      {"bad extension",
       replaced(kBase,
                "unit = \"angstrom\"\natoms = [ [\"C\", 3.0, 0.0, 0.0], [\"C\", 2.0, 2.0, 1.0] ]",
                "file = \"cnt55.pdb\""),
       {"geometry.file (line 3)", ".gen or .xyz"}},
      {"too close",
       replaced(kBase, "[\"C\", 2.0, 2.0, 1.0]", "[\"C\", 3.2, 0.0, 0.0]"),
       {"atom 1 and atom 2", "0.50 Å"}},
      {"image too close",
       replaced(kBase, "translation = 2.5", "translation = 0.3"),
       {"image", "0.50 Å"}},
      {"no table",
       replaced(kBase, "[\"C\", 2.0, 2.0, 1.0]", "[\"Si\", 2.0, 2.0, 1.0]"),
       {"parameters.set (line 14)", "C-Si"}},
      {"unknown set", replaced(kBase, "pbc-0-3", "mio-9"), {"parameters.set (line 14)", "pbc-0-3"}},
      {"missing table path", kBase + "\"C-C\" = \"nope.skf\"\n", {"parameters.C-C (line 15)"}},
      {"pair not in cell",
       kBase + "\"C-N\" = \"params/pbc-0-3/C-N.skf\"\n",
       {"parameters.C-N (line 15)"}},
      {"unknown parameters key", kBase + "foo = 1\n", {"parameters.foo (line 15)"}},
      {"shell of absent element",
       kBase + "max_angular_momentum = { N = \"p\" }\n",
       {"parameters.max_angular_momentum.N (line 15)"}},
      {"bad shell",
       kBase + "max_angular_momentum = { C = \"x\" }\n",
       {"parameters.max_angular_momentum.C (line 15)"}},
      {"no parameters",
       replaced(kBase, "[parameters]\nset = \"pbc-0-3\"\n", ""),
       {"key parameters"}},
      {"no unit", replaced(kBase, "unit = \"angstrom\"\n", ""), {"geometry.unit", "line 2"}},
      {"bad atom",
       replaced(kBase, "[\"C\", 2.0, 2.0, 1.0]", "[\"C\", 2.0, 2.0]"),
       {"geometry.atoms, atom 2 (line 4)"}},
      {"no kpoints", replaced(kBase, "[kpoints]\nhelical = 4\n", ""), {"key kpoints"}},
      {"bad angular",
       replaced(kBase, "helical = 4", "helical = 4\nangular = \"some\""),
       {"kpoints.angular (line 11)"}},
      {"dispersion none with epsilon",
       kBase + "[dispersion]\nmodel = \"none\"\nepsilon = 0.1\n",
       {"dispersion.epsilon (line 17)"}},
      {"dispersion model",
       kBase + "[dispersion]\nmodel = \"d3\"\n",
       {"dispersion.model (line 16)"}},
      {"kc with an lj key",
       kBase + "[dispersion]\nmodel = \"kc\"\nepsilon = 0.1\n",
       {"dispersion.epsilon (line 17)", "model = \"kc\""}},
      {"lj with a kc key",
       kBase + "[dispersion]\nmodel = \"lj\"\nbond_cutoff = 1.7\n",
       {"dispersion.bond_cutoff (line 17)"}},
      {"kc parameter set",
       kBase + "[dispersion]\nmodel = \"kc\"\nparameters = \"kc2006\"\n",
       {"dispersion.parameters (line 17)", "kc2005"}},
      {"kc cutoff without taper start",
       kBase + "[dispersion]\nmodel = \"kc\"\ncutoff = 20\n",
       {"dispersion.cutoff (line 17)", "taper_start"}},
      {"kc taper start beyond the cutoff",
       kBase + "[dispersion]\nmodel = \"kc\"\ncutoff = 20\ntaper_start = 21\n",
       {"dispersion.taper_start (line 18)", "below the cutoff"}},
      {"kc cutoff of 1000 Å",
       kBase + "[dispersion]\nmodel = \"kc\"\ncutoff = 1000\ntaper_start = 0\n",
       {"dispersion.cutoff (line 17)", "[7, 100]"}},
      {"kc bond cutoff at second neighbours",
       kBase + "[dispersion]\nmodel = \"kc\"\nbond_cutoff = 2.5\n",
       {"dispersion.bond_cutoff (line 17)", "2.2"}},
      {"energy with max_steps",
       kBase + "[task]\ntype = \"energy\"\nmax_steps = 3\n",
       {"task.max_steps (line 17)"}},
      {"bad task", kBase + "[task]\ntype = \"md\"\n", {"task.type (line 16)"}},
      {"scc unknown key", kBase + "[scc]\nenabled = true\nmix = 0.1\n", {"scc.mix"}},
      {"scc mixer", kBase + "[scc]\nmixer = \"anderson\"\n", {"scc.mixer (line 16)"}},
      {"scc tolerance beyond double precision",
       kBase + "[scc]\ncharge_tolerance = 1e-16\n",
       {"scc.charge_tolerance (line 16)", "1e-13"}},
      {"scc mixing", kBase + "[scc]\nmixing = 1.5\n", {"scc.mixing (line 16)"}},
      {"negative tolerance",
       kBase + "[task]\ntype = \"relax\"\nforce_tolerance = -1\n",
       {"task.force_tolerance (line 17)"}},
      {"relax translation of ring",
       replaced(replaced(replaced(kBase, "translation = 2.5", "translation = 0.0"), "twist = 10.0",
                         "twist = 120.0"),
                "helical = 4", "angular = \"all\"") +
           "[task]\ntype = \"relax\"\nrelax_translation = true\n",
       {"task.relax_translation (line 17)"}},
      {"helical k-points for a ring",
       replaced(replaced(kBase, "translation = 2.5", "translation = 0.0"), "twist = 10.0",
                "twist = 120.0"),
       {"kpoints.helical (line 10)"}},
      {"geometry and builder", kBase + "[builder]\ntype = \"nanotube\"\n", {"builder"}},
      {"builder cell kind", builder, {"builder.cell (line 6)"}},
      {"builder with symmetry",
       replaced(builder, "cell = \"zigzag\"", "cell = \"helical\"") +
           "[symmetry]\nrotation_order = 5\n",
       {"symmetry", "builder"}},
      {"disagreeing symmetry", genCell, {"symmetry.twist (line 5)", "cnt55.gen"}},
      {"error inside the gen file",
       replaced(genCell, "cnt55.gen", "broken.gen"),
       {"broken.gen, line 4"}},
  };
  for (const Case& c : cases) {
    const fs::path p = dir / "case.toml";
    writeText(p, c.text);
    try {
      readCellFile(p.string());
      ADD_FAILURE() << c.name << ": no error";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(c.name == "error inside the gen file" ? "broken.gen" : "case.toml"),
                std::string::npos)
          << c.name << ": " << msg;
      for (const auto& s : c.expect)
        EXPECT_NE(msg.find(s), std::string::npos) << c.name << ": '" << s << "' not in: " << msg;
    }
  }
  EXPECT_THROW(readCellFile((dir / "missing.toml").string()), InputError);
  fs::remove_all(dir);
}
