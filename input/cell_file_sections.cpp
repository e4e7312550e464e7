#include "input/cell_file_sections.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/collapsed_tube_builder.hpp"
#include "input/gen_file.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "input/text_reader.hpp"
#include "input/xyz_file.hpp"

namespace mesochain::objective::detail {

namespace fs = std::filesystem;
using units::kAngstromInBohr;
using units::kBohrInAngstrom;
using units::kDegree;

namespace {

// Inline atoms = [ ["C", x, y, z], ... ] in the given unit.
ObjectiveCell readInlineAtoms(const TomlTable& g) {
  const std::string unit = g.string("unit", "unit = \"angstrom\" or \"bohr\" for inline atoms");
  if (unit != "angstrom" && unit != "bohr")
    g.fail("unit", "\"" + unit + "\"", "\"angstrom\" or \"bohr\"");
  const double scale = unit == "angstrom" ? kAngstromInBohr : 1.0;
  ObjectiveCell cell;
  for (const TomlRow& atom : g.rows("atoms", 4, "an array of atoms [\"Element\", x, y, z] with x, y, z in " + unit, "atom")) {
    const std::string element = atom.string(0);
    if (!isElementName(element)) atom.fail("element \"" + element + "\"");
    const Eigen::Vector3d x(atom.number(1), atom.number(2), atom.number(3));
    cell.addAtom(element, x * scale);
  }
  return cell;
}

// [geometry]: returns the cell and whether the geometry carried its own symmetry.
ObjectiveCell readGeometry(const TomlTable& g, const std::string& cellPath, bool& carries) {
  g.allowOnly({"file", "atoms", "unit"});
  if (g.has("file") == g.has("atoms"))
    g.fail(g.has("file") ? "atoms" : "file",
           g.has("file") ? "both file and atoms" : "neither file nor atoms",
           "either file = \"x.gen\" (or .xyz) or inline atoms = [[\"C\", x, y, z], ...]");
  if (g.has("atoms")) {
    carries = false;
    return readInlineAtoms(g);
  }
  if (g.has("unit"))
    g.fail("unit", "unit together with file", "no unit: .gen and .xyz coordinates are always in Å");
  const std::string file = g.string("file", "the path of a .gen or .xyz file");
  const fs::path p = fs::path(cellPath).parent_path() / file;
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".gen" && ext != ".xyz")
    g.fail("file", "\"" + file + "\"", "a file ending in .gen or .xyz");
  std::error_code ec;
  if (!fs::is_regular_file(p, ec))
    g.fail("file", "\"" + file + "\", which does not exist (looked for " + p.string() + ")",
           "an existing geometry file (the path is relative to the cell file)");
  if (ext == ".gen") {
    GenGeometry gen = readGenFile(p.lexically_normal().string());
    carries = gen.type != GenType::Cluster;
    return std::move(gen.cell);
  }
  XyzFrame frame = readXyzFile(p.lexically_normal().string());
  carries = frame.hasSymmetry;
  return std::move(frame.cell);
}

struct SymmetryKeys {
  std::optional<double> translation;  // Å
  std::optional<double> twist;        // degrees
  std::optional<long> rotationOrder;
};

SymmetryKeys readSymmetryKeys(const TomlTable& s) {
  s.allowOnly({"translation", "twist", "rotation_order"});
  SymmetryKeys k;
  if (s.has("translation")) {
    k.translation = s.number("translation", "a translation >= 0 (Å; 0 closes a ring)");
    if (*k.translation < 0.0)
      s.fail("translation", fmt::format("{} Å", *k.translation),
             "a translation >= 0 (Å; 0 closes a ring)");
  }
  if (s.has("twist")) k.twist = s.number("twist", "a twist angle (degrees)");
  if (s.has("rotation_order")) {
    const char* expected = "an integer rotation order N_a from 1 to 1000000000";
    k.rotationOrder = s.integer("rotation_order", expected);
    if (*k.rotationOrder < 1 || *k.rotationOrder > 1000000000L)
      s.fail("rotation_order", std::to_string(*k.rotationOrder), expected);
  }
  return k;
}

// Distance of an angle (degrees) from the nearest multiple of `step` degrees.
double offMultiple(double angle, double step) {
  const double m = angle / step;
  return std::abs(m - std::round(m)) * step;
}

Symmetry symmetryFromKeys(const TomlTable& s, const SymmetryKeys& k) {
  for (const char* key : {"translation", "twist", "rotation_order"})
    if (!s.has(key))
      s.missing(key,
                "translation (Å), twist (degrees) and rotation_order: the geometry has "
                "no symmetry of its own");
  const int na = static_cast<int>(*k.rotationOrder);
  if (*k.translation == 0.0 && offMultiple(*k.twist, 360.0 / na) > 1e-9 * 360.0)
    s.fail("twist", fmt::format("{} degrees with translation = 0", *k.twist),
           fmt::format("a multiple of 360/N_a = {} degrees (translation 0 is a closed ring of "
                       "N_a = {} copies)",
                       360.0 / na, na));
  return Symmetry::fromParameters(*k.translation * kAngstromInBohr, *k.twist * kDegree, na,
                                  s.source().c_str());
}

// Keys given together with a geometry file that has its own symmetry must agree with it.
void checkAgreement(const TomlTable& s, const SymmetryKeys& k, const Symmetry& g,
                    const std::string& file) {
  const double tg = g.translation() * kBohrInAngstrom;
  const int na = g.rotationOrder();
  const double twg = g.isRing() ? 360.0 / na : g.twist() / kDegree;
  const std::string expected = "the value in " + file + " (or leave the key out)";
  if (k.translation && std::abs(*k.translation - tg) > 1e-6)
    s.fail("translation", fmt::format("{} Å, but {} has {} Å", *k.translation, file, tg), expected);
  if (k.rotationOrder && *k.rotationOrder != na)
    s.fail("rotation_order", fmt::format("{}, but {} has {}", *k.rotationOrder, file, na),
           expected);
  // Twists that differ by a multiple of 360/N_a describe the same group.
  if (k.twist && offMultiple(*k.twist - twg, 360.0 / na) > 1e-6)
    s.fail(
        "twist",
        fmt::format("{} degrees, but {} has {} degrees (modulo 360/{})", *k.twist, file, twg, na),
        expected);
}

double readBondLength(const TomlTable& b) {
  double bond = kDefaultBondLengthAngstrom;
  if (b.has("bond_length")) {
    bond = b.number("bond_length", "a positive bond length (Å)");
    if (!(bond > 0.0))
      b.fail("bond_length", fmt::format("{} Å", bond), "a positive bond length (Å)");
  }
  return bond * kAngstromInBohr;
}

ObjectiveCell readNanotubeBuilder(const TomlTable& b) {
  b.allowOnly({"type", "n", "m", "cell", "bond_length", "use_rotation"});
  const long n = b.integer("n", "the chiral index 1 <= n <= 10000");
  if (n < 1 || n > 10000) b.fail("n", std::to_string(n), "the chiral index 1 <= n <= 10000");
  const long m = b.integer("m", "the chiral index 0 <= m <= 10000");
  if (m < 0 || m > 10000) b.fail("m", std::to_string(m), "the chiral index 0 <= m <= 10000");
  const std::string kind = b.string("cell", "\"helical\" or \"translational\"");
  if (kind != "helical" && kind != "translational")
    b.fail("cell", "\"" + kind + "\"", "\"helical\" or \"translational\"");
  const double bond = readBondLength(b);
  bool rotation = false;
  if (b.has("use_rotation")) {
    if (kind != "translational")
      b.fail("use_rotation", "use_rotation with cell = \"helical\"",
             "use_rotation only with cell = \"translational\" (the helical cell always uses "
             "the rotation)");
    rotation = b.boolean("use_rotation", "true or false");
  }
  const int ni = static_cast<int>(n), mi = static_cast<int>(m);
  return kind == "helical" ? buildNanotubeHelical(ni, mi, bond)
                           : buildNanotubeTranslational(ni, mi, bond, rotation);
}

// walls = [[n1, m1], [n2, m2], ...]
std::vector<std::pair<int, int>> readWalls(const TomlTable& b) {
  const char* expected = "walls = [[n, m], ...] with at least one pair of chiral indices";
  std::vector<std::pair<int, int>> walls;
  for (const TomlRow& w : b.rows("walls", 2, expected, "wall")) {
    const long n = w.integer(0), m = w.integer(1);
    if (n < 1 || n > 10000 || m < 0 || m > 10000)
      w.fail(fmt::format("({}, {})", n, m), "chiral indices 1 <= n, 0 <= m <= 10000");
    walls.emplace_back(static_cast<int>(n), static_cast<int>(m));
  }
  return walls;
}

ObjectiveCell readMultiWallBuilder(const TomlTable& b) {
  b.allowOnly({"type", "walls", "bond_length", "rotation_order"});
  long order = 1;
  if (b.has("rotation_order")) {
    const char* expected = "an integer >= 1 that divides gcd(n, m) of every wall (the sector of 2 pi / order)";
    order = b.integer("rotation_order", expected);
    if (order < 1 || order > 10000) b.fail("rotation_order", std::to_string(order), expected);
  }
  return buildMultiWallSector(readWalls(b), readBondLength(b), static_cast<int>(order));
}

// A positive length in Å (with a default), returned in Bohr.
double readPositiveLength(const TomlTable& b, const char* key, double defaultAngstrom,
                          const char* meaning) {
  double x = defaultAngstrom;
  if (b.has(key)) {
    x = b.number(key, fmt::format("a positive {} (Å)", meaning));
    if (!(x > 0.0)) b.fail(key, fmt::format("{} Å", x), fmt::format("a positive {} (Å)", meaning));
  }
  return x * kAngstromInBohr;
}

ObjectiveCell readCollapsedBuilder(const TomlTable& b) {
  b.allowOnly({"type", "walls", "bond_length", "interlayer", "bulb_radius", "transition_radius"});
  CollapseShape shape;
  shape.interlayer = readPositiveLength(b, "interlayer", kDefaultCollapseInterlayerAngstrom,
                                        "distance between the flat faces");
  shape.bulbRadius = readPositiveLength(b, "bulb_radius", kDefaultCollapseBulbRadiusAngstrom,
                                        "bulb radius of the innermost wall");
  shape.transitionRadius =
      readPositiveLength(b, "transition_radius", kDefaultCollapseTransitionRadiusAngstrom,
                         "transition radius of the outermost wall");
  if (!(shape.bulbRadius > shape.interlayer / 2))
    b.fail("bulb_radius", fmt::format("{} Å", shape.bulbRadius * kBohrInAngstrom),
           "a bulb radius larger than half the interlayer distance");
  return buildCollapsedTube(readWalls(b), readBondLength(b), shape);
}

// The sheet direction along the arc: direction = "armchair" | "zigzag" | "chiral", the last
// with chiral = [n, m] (0 <= m <= n, not both 0).
ChiralIndices readSheetDirection(const TomlTable& b) {
  const char* directions = "\"armchair\", \"zigzag\" or \"chiral\" (along the arc)";
  const std::string dir = b.string("direction", directions);
  if (dir != "armchair" && dir != "zigzag" && dir != "chiral")
    b.fail("direction", "\"" + dir + "\"", directions);
  if (dir != "chiral") {
    if (b.has("chiral"))
      b.fail("chiral", describe(b.at("chiral")) + " with direction = \"" + dir + "\"",
             "no chiral key, or direction = \"chiral\" with chiral = [n, m]");
    return chiralIndices(dir == "armchair" ? Direction::Armchair : Direction::Zigzag);
  }
  const char* expected = "chiral indices [n, m] (integers, 0 <= m <= n, not both 0)";
  if (!b.has("chiral")) b.missing("chiral", std::string("with direction = \"chiral\": ") + expected);
  const std::vector<long> nm = b.integers("chiral", expected);
  if (nm.size() != 2) b.fail("chiral", fmt::format("{} integers", nm.size()), expected);
  const long n = nm[0], m = nm[1];
  if (n < 1 || m < 0 || m > n || n > 10000)
    b.fail("chiral", fmt::format("[{}, {}]", n, m),
           std::string(expected) + ", n <= 10000 (m > n is the mirror image of [m, n])");
  return {static_cast<int>(n), static_cast<int>(m)};
}

ObjectiveCell readGrapheneRingBuilder(const TomlTable& b) {
  b.allowOnly({"type", "layers", "direction", "chiral", "rotation_order", "cells_along_arc",
               "interlayer", "bond_length"});
  const long layers = b.integer("layers", "1 <= layers <= 1000");
  if (layers < 1 || layers > 1000) b.fail("layers", std::to_string(layers), "1 <= layers <= 1000");
  const ChiralIndices dir = readSheetDirection(b);
  const long na = b.integer("rotation_order", "the number of sectors 3 <= N_a <= 1e7");
  if (na < 3 || na > 10000000) b.fail("rotation_order", std::to_string(na), "3 <= N_a <= 1e7");
  long cells = 1;
  if (b.has("cells_along_arc")) {
    cells = b.integer("cells_along_arc", "a number of cells 1..1000");
    if (cells < 1 || cells > 1000) b.fail("cells_along_arc", std::to_string(cells), "1..1000");
  }
  double interlayer = 3.35;
  if (b.has("interlayer")) {
    interlayer = b.number("interlayer", "a positive interlayer spacing (Å)");
    if (!(interlayer > 0.0)) b.fail("interlayer", fmt::format("{} Å", interlayer), "a positive spacing (Å)");
  }
  return buildGrapheneRingSector(static_cast<int>(layers), dir, static_cast<int>(na),
                                 static_cast<int>(cells), interlayer * kAngstromInBohr,
                                 readBondLength(b));
}

ObjectiveCell readBuilder(const TomlTable& b) {
  const char* types = "\"nanotube\", \"multiwall\", \"collapsed\" or \"graphene_ring\"";
  const std::string type = b.string("type", std::string("type = ") + types);
  if (type == "nanotube") return readNanotubeBuilder(b);
  if (type == "multiwall") return readMultiWallBuilder(b);
  if (type == "collapsed") return readCollapsedBuilder(b);
  if (type == "graphene_ring") return readGrapheneRingBuilder(b);
  b.fail("type", "\"" + type + "\"", types);
}

}  // namespace

void readStructure(const TomlTable& root, CellInput& in) {
  const auto geometry = root.table("geometry");
  const auto builder = root.table("builder");
  const auto symmetry = root.table("symmetry");
  if (geometry && builder)
    root.fail("builder", "both [geometry] and [builder]", "one of [geometry] or [builder]");
  if (!geometry && !builder)
    root.missing("geometry", "a table [geometry] (file or inline atoms) or [builder]");
  if (builder) {
    if (symmetry)
      root.fail("symmetry", "[symmetry] together with [builder]",
                "no [symmetry]: the builder sets the symmetry of the cell it builds");
    in.cell = readBuilder(*builder);
    return;
  }
  bool carries = false;
  in.cell = readGeometry(*geometry, in.source, carries);
  if (carries) {
    if (symmetry)
      checkAgreement(*symmetry, readSymmetryKeys(*symmetry), in.cell.symmetry,
                     geometry->string("file", "a geometry file"));
    return;
  }
  if (!symmetry)
    root.missing("symmetry",
                 "a table [symmetry] with translation (Å), twist (degrees) and rotation_order "
                 "(translation = 0, twist = 0, rotation_order = 1 is an isolated cluster)");
  in.cell.symmetry = symmetryFromKeys(*symmetry, readSymmetryKeys(*symmetry));
}

}  // namespace mesochain::objective::detail
