// The settings keys of the extended XYZ comment line (input/xyz_settings.hpp) and the
// cell reader on an in-memory document (input/cell_document.hpp).
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_document.hpp"
#include "input/xyz_file.hpp"
#include "input/xyz_settings.hpp"

using namespace mesochain;
using namespace mesochain::objective;

namespace {

const std::string kCells = std::string(MESOCHAIN_TEST_DATA) + "/cell/";

std::string commentLine(const CellInput& in) {
  std::ostringstream out;
  XyzExtras extras;
  extras.energy = -1.5;
  extras.settings = &in;
  writeXyz(out, in.cell, extras);
  std::istringstream lines(out.str());
  std::string count, comment;
  std::getline(lines, count);
  std::getline(lines, comment);
  return comment;
}

bool hasToken(const std::string& line, const std::string& token) {
  return (" " + line + " ").find(" " + token + " ") != std::string::npos;
}

}  // namespace

TEST(XyzSettings, RecordsTheCellFileSettingsAndReadsBack) {
  const CellInput chain = readCellFile(kCells + "ch_chain_bohr.toml");
  const std::string c = commentLine(chain);
  EXPECT_TRUE(hasToken(c, "mesochain:kpoints.helical=8")) << c;
  EXPECT_TRUE(hasToken(c, "mesochain:kpoints.angular=all")) << c;
  EXPECT_TRUE(hasToken(c, "mesochain:electrons.temperature=300")) << c;
  EXPECT_TRUE(hasToken(c, "mesochain:parameters.set=pbc-0-3")) << c;
  EXPECT_TRUE(hasToken(c, "mesochain:dispersion.model=none")) << c;
  EXPECT_TRUE(hasToken(c, "mesochain:scc.enabled=F")) << c;
  // H-H is given explicitly but is the set's own table: not repeated.
  EXPECT_EQ(c.find("mesochain:parameters.H-H"), std::string::npos) << c;
  std::istringstream io(std::to_string(chain.cell.atomCount()) + "\n" + c + "\nC 0 0 0\nH 0 0 1.1\n");
  const XyzFrame back = readXyz(io, "settings.xyz");
  EXPECT_TRUE(back.hasSymmetry);

  const CellInput ring = readCellFile(kCells + "inline_ring.toml");
  const std::string r = commentLine(ring);
  EXPECT_EQ(r.find("kpoints.helical"), std::string::npos) << r;  // a ring has no kappa
  EXPECT_TRUE(hasToken(r, "mesochain:parameters.max_angular_momentum.C=p")) << r;
  EXPECT_TRUE(hasToken(r, "mesochain:parameters.C-C=" + ring.parameterFiles.at("C-C"))) << r;
  EXPECT_TRUE(hasToken(r, "mesochain:dispersion.model=lj")) << r;
  EXPECT_TRUE(hasToken(r, "mesochain:dispersion.cutoff=25")) << r;
  EXPECT_TRUE(hasToken(r, "mesochain:dispersion.summation=cutoff")) << r;
}

TEST(XyzSettings, UnknownMesochainKeysAreStillErrors) {
  std::istringstream io(
      "1\nmesochain:translation=0 mesochain:twist=0 mesochain:rotation_order=1 "
      "mesochain:kpoint=4\nC 0 0 0\n");
  try {
    readXyz(io, "typo.xyz");
    FAIL() << "mesochain:kpoint accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesochain:kpoint"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(isXyzSettingsKey("mesochain:kpoints."));
  EXPECT_FALSE(isXyzSettingsKey("mesochain:task.type"));
  EXPECT_TRUE(isXyzSettingsKey("mesochain:scc.mixer"));
}

TEST(CellDocument, InMemoryDocumentReadsLikeTheFileAndNamesKeysWithoutLines) {
  const CellInput file = readCellFile(kCells + "ch_chain_bohr.toml");
  toml::value doc = toml::table{};
  doc["format"] = 1;
  doc["geometry"] = toml::table{{"unit", "bohr"},
                                {"atoms", toml::array{toml::array{"C", 0.0, 0.0, 0.0},
                                                      toml::array{"H", 0.0, 0.0, 2.1}}}};
  doc["symmetry"] = toml::table{{"translation", 2.5}, {"twist", 0}, {"rotation_order", 1}};
  doc["kpoints"] = toml::table{{"helical", 8}};
  doc["electrons"] = toml::table{{"temperature", 300}};
  doc["parameters"] = toml::table{{"set", "pbc-0-3"}};
  const CellInput mem = readCellDocument(doc, "<dict>");
  EXPECT_EQ(mem.band.helicalKPoints, file.band.helicalKPoints);
  EXPECT_EQ(mem.parameterFiles, file.parameterFiles);
  EXPECT_EQ(mem.band.electronicTemperature, file.band.electronicTemperature);
  EXPECT_EQ(mem.cell.positions, file.cell.positions);
  EXPECT_EQ(mem.cell.symmetry.translation(), file.cell.symmetry.translation());

  doc["kpoints"] = toml::table{{"helical", 0}};
  try {
    readCellDocument(doc, "<dict>");
    FAIL() << "helical = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "<dict>");
    EXPECT_EQ(e.where(), "key kpoints.helical");  // no "(line 1)" for a value built in memory
  }
}
