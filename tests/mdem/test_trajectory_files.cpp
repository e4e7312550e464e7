// The mDEM trajectory files as the standard tools read them: the extended XYZ by the rules of
// ASE's reader (species a chemical symbol, Properties columns, key=value comment line with the
// units) and OVITO's column names; the ParaView series file (.pvd) with the times in ns, also
// after a resume; glyph size and shape arrays in the VTK frames.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/output.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;
namespace fs = std::filesystem;

// A minimal extended-XYZ reader with ASE's rules (ase.io.extxyz, read for its rules): line 1 the
// atom count; line 2 key=value pairs, a value in double quotes may hold spaces; Properties is
// name:type:columns triples with type S, R, I or L; per atom, as many whitespace-separated
// tokens as columns in total; species must be a chemical symbol (ase.Atoms rejects others with
// KeyError, the failure of issue 18) and pos must be R:3.
struct ExtXyzFrame {
  std::map<std::string, std::string> info;
  std::vector<std::pair<std::string, int>> columns;  // name, count
  std::vector<std::map<std::string, std::vector<std::string>>> atoms;
};

std::map<std::string, std::string> keyValues(const std::string& line) {
  std::map<std::string, std::string> kv;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && line[i] == ' ') ++i;
    if (i >= line.size()) break;
    const std::size_t eq = line.find('=', i);
    if (eq == std::string::npos) throw std::runtime_error("a comment token without '=': " + line.substr(i));
    const std::string key = line.substr(i, eq - i);
    i = eq + 1;
    std::string value;
    if (i < line.size() && line[i] == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string::npos) throw std::runtime_error("an unclosed quote");
      value = line.substr(i + 1, close - i - 1);
      i = close + 1;
    } else {
      const std::size_t end = line.find(' ', i);
      value = line.substr(i, end == std::string::npos ? std::string::npos : end - i);
      i = end == std::string::npos ? line.size() : end;
    }
    if (kv.count(key)) throw std::runtime_error("a duplicate key " + key);
    kv[key] = value;
  }
  return kv;
}

bool isChemicalSymbol(const std::string& s) {
  static const std::set<std::string> symbols = {
      "H",  "He", "Li", "Be", "B",  "C",  "N",  "O",  "F",  "Ne", "Na", "Mg", "Al", "Si", "P",  "S",  "Cl", "Ar",
      "K",  "Ca", "Sc", "Ti", "V",  "Cr", "Mn", "Fe", "Co", "Ni", "Cu", "Zn", "Ga", "Ge", "As", "Se", "Br", "Kr",
      "Rb", "Sr", "Y",  "Zr", "Nb", "Mo", "Tc", "Ru", "Rh", "Pd", "Ag", "Cd", "In", "Sn", "Sb", "Te", "I",  "Xe",
      "Cs", "Ba", "La", "Ce", "Pr", "Nd", "Pm", "Sm", "Eu", "Gd", "Tb", "Dy", "Ho", "Er", "Tm", "Yb", "Lu", "Hf",
      "Ta", "W",  "Re", "Os", "Ir", "Pt", "Au", "Hg", "Tl", "Pb", "Bi", "Po", "At", "Rn", "Fr", "Ra", "Ac", "Th",
      "Pa", "U",  "Np", "Pu", "Am", "Cm", "Bk", "Cf", "Es", "Fm", "Md", "No", "Lr", "Rf", "Db", "Sg", "Bh", "Hs",
      "Mt", "Ds", "Rg", "Cn", "Nh", "Fl", "Mc", "Lv", "Ts", "Og", "X"};
  return symbols.count(s) > 0;
}

std::vector<ExtXyzFrame> readExtXyz(std::istream& in) {
  std::vector<ExtXyzFrame> frames;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    ExtXyzFrame f;
    const int n = std::stoi(line);
    std::getline(in, line);
    f.info = keyValues(line);
    if (!f.info.count("Properties")) throw std::runtime_error("no Properties");
    std::stringstream props(f.info.at("Properties"));
    std::vector<std::string> parts;
    for (std::string p; std::getline(props, p, ':');) parts.push_back(p);
    if (parts.size() % 3 != 0) throw std::runtime_error("Properties not in name:type:count triples");
    int total = 0;
    for (std::size_t k = 0; k < parts.size(); k += 3) {
      if (std::string("SRIL").find(parts[k + 1]) == std::string::npos || parts[k + 1].size() != 1)
        throw std::runtime_error("a column type " + parts[k + 1]);
      f.columns.emplace_back(parts[k], std::stoi(parts[k + 2]));
      total += std::stoi(parts[k + 2]);
    }
    for (int a = 0; a < n; ++a) {
      if (!std::getline(in, line)) throw std::runtime_error("fewer atom lines than the count");
      std::istringstream row(line);
      std::vector<std::string> tokens;
      for (std::string t; row >> t;) tokens.push_back(t);
      if (static_cast<int>(tokens.size()) != total)
        throw std::runtime_error(fmt::format("{} tokens on an atom line, {} columns", tokens.size(), total));
      std::map<std::string, std::vector<std::string>> atom;
      std::size_t at = 0;
      for (const auto& [name, count] : f.columns)
        for (int c = 0; c < count; ++c) atom[name].push_back(tokens[at++]);
      if (!atom.count("species") || !isChemicalSymbol(atom["species"][0]))
        throw std::runtime_error("species '" + (atom.count("species") ? atom["species"][0] : "") +
                                 "' is not a chemical symbol (ase.Atoms raises KeyError)");
      if (!atom.count("pos") || atom["pos"].size() != 3) throw std::runtime_error("no pos:R:3");
      f.atoms.push_back(atom);
    }
    frames.push_back(f);
  }
  return frames;
}

TEST(MdemTrajectoryFiles, ExtendedXyzFollowsTheAseRules) {
  Scene s = filament(3);
  s.elementTypes[0].name = "collapsed_cnt";
  s.bodies.velocity[1] = Vec3(0.5, -1.5, 2.0);
  std::ostringstream text;
  writeXyzFrame(text, s.bodies, s.elementTypes, 0.25, 10);
  writeXyzFrame(text, s.bodies, s.elementTypes, 0.5, 20);  // a trajectory: frames appended
  std::istringstream in(text.str());
  std::vector<ExtXyzFrame> frames;
  ASSERT_NO_THROW(frames = readExtXyz(in)) << text.str();
  ASSERT_EQ(frames.size(), 2u);
  const ExtXyzFrame& f = frames[0];
  EXPECT_EQ(f.info.at("Time"), "0.25");
  EXPECT_EQ(f.info.at("Step"), "10");
  EXPECT_EQ(f.info.at("pbc"), "F F F");
  EXPECT_NE(f.info.at("units").find("pos:nm"), std::string::npos);
  EXPECT_NE(f.info.at("units").find("velo:nm/ns"), std::string::npos);
  EXPECT_NE(f.info.at("units").find("Time:ns"), std::string::npos);
  ASSERT_EQ(f.atoms.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const auto& a = f.atoms[i];
    EXPECT_EQ(a.at("species")[0], "C");
    EXPECT_EQ(a.at("type_name")[0], "collapsed_cnt");  // the element type, in its own column
    EXPECT_EQ(a.at("type_id")[0], "0");
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(std::stod(a.at("pos")[c]), s.bodies.position[i][c], 1e-9);
      EXPECT_NEAR(std::stod(a.at("velo")[c]), s.bodies.velocity[i][c], 1e-7);
    }
    // OVITO's columns: orientation x y z w (unit quaternion) and the half extents.
    ASSERT_EQ(a.at("orientation").size(), 4u);
    double norm = 0;
    for (const std::string& q : a.at("orientation")) norm += std::stod(q) * std::stod(q);
    EXPECT_NEAR(norm, 1.0, 1e-10);
    EXPECT_NEAR(std::stod(a.at("aspherical_shape")[2]), 0.5 * kL, 1e-9);
  }
}

TEST(MdemTrajectoryFiles, TheReaderCatchesABrokenColumn) {
  // The reader above is strict enough to fail: a type name with a space (which the scene reader
  // refuses, mdem/scene_file.cpp) would give one token too many on the atom line.
  Scene s = filament(1);
  s.elementTypes[0].name = "two words";
  std::ostringstream text;
  writeXyzFrame(text, s.bodies, s.elementTypes, 0, 0);
  std::istringstream in(text.str());
  EXPECT_THROW(readExtXyz(in), std::runtime_error);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(MdemTrajectoryFiles, SeriesFileHasTheTimesAndSurvivesAResume) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mesochain-pvd-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string prefix = (dir / "frame").string();
  Scene s = filament(2);
  const double times[3] = {0.0, 0.0125, 0.025};
  {
    VtkSeries series(prefix, 0);
    for (int k = 0; k < 2; ++k) {
      const std::string p = fmt::format("{}_{:06d}.vtk", prefix, k);
      writeVtkFrame(p, s.bodies, {}, times[k]);
      series.add(p, times[k]);
    }
  }
  // A resumed run: the two frames on disk are read back, the third is added.
  VtkSeries resumed(prefix, 2);
  const std::string p2 = fmt::format("{}_{:06d}.vtk", prefix, 2);
  writeVtkFrame(p2, s.bodies, {}, times[2]);
  resumed.add(p2, times[2]);
  const std::string xml = slurp(prefix + ".pvd");
  const std::regex dataset(R"re(<DataSet timestep="([^"]+)" part="0" file="([^"]+)"/>)re");
  std::vector<std::pair<double, std::string>> got;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), dataset); it != std::sregex_iterator(); ++it)
    got.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
  ASSERT_EQ(got.size(), 3u) << xml;
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(got[k].first, times[k]);
    EXPECT_EQ(got[k].second, fmt::format("frame_{:06d}.vtk", k));  // relative to the .pvd
    EXPECT_TRUE(fs::exists(dir / got[k].second));
  }
  EXPECT_NE(xml.find("type=\"Collection\""), std::string::npos);
  EXPECT_FALSE(fs::exists(prefix + ".pvd.tmp." + std::to_string(::getpid())));  // written atomically
  fs::remove_all(dir);
}

TEST(MdemTrajectoryFiles, VtkFramesCarryGlyphSizeAndShape) {
  Scene s = filament(2);
  VtkFields fields;
  for (int i = 0; i < 2; ++i) {
    fields.halfExtents.push_back(s.elementTypes[0].halfExtents());
    fields.shape.push_back(0);
  }
  const fs::path path = fs::temp_directory_path() / fmt::format("mesochain-glyph-{}.vtk", ::getpid());
  writeVtkFrame(path.string(), s.bodies, {}, 0.0, fields);
  const std::string text = slurp(path);
  fs::remove(path);
  const auto at = text.find("VECTORS half_extents_nm double\n");
  ASSERT_NE(at, std::string::npos);
  std::istringstream in(text.substr(at + std::string("VECTORS half_extents_nm double\n").size()));
  double x, y, z;
  in >> x >> y >> z;
  EXPECT_DOUBLE_EQ(x, 0.5 * kH);
  EXPECT_DOUBLE_EQ(y, 0.5 * kW);
  EXPECT_DOUBLE_EQ(z, 0.5 * kL);
  EXPECT_NE(text.find("SCALARS shape int 1"), std::string::npos);
}

}  // namespace
}  // namespace mesochain::mdem
