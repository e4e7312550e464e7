#include "input/xyz_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/text_reader.hpp"
#include "input/xyz_settings.hpp"

namespace mesochain::objective {

using detail::TextLine;
using detail::TextReader;
using units::kAngstromInBohr;
using units::kBohrInAngstrom;
using units::kDegree;

namespace {

// eV/Å in Hartree/Bohr.
constexpr double kEvPerAngstromInHartreePerBohr = units::kEvInHartree * units::kBohrInAngstrom;

// key=value pairs of an extxyz comment line; values may be "double quoted". Words without '='
// (free text) are skipped.
std::map<std::string, std::string> parseComment(const TextReader& r, const TextLine& line) {
  std::map<std::string, std::string> kv;
  const std::string& s = line.text;
  std::size_t i = 0;
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (i < s.size()) {
    while (i < s.size() && blank(s[i])) ++i;
    if (i >= s.size()) break;
    std::size_t j = i;
    while (j < s.size() && !blank(s[j]) && s[j] != '=') ++j;
    const std::string key = s.substr(i, j - i);
    std::size_t k = j;
    while (k < s.size() && blank(s[k])) ++k;
    if (k >= s.size() || s[k] != '=') {  // a bare word
      i = j;
      continue;
    }
    ++k;
    while (k < s.size() && blank(s[k])) ++k;
    std::string value;
    if (k < s.size() && s[k] == '"') {
      const std::size_t end = s.find('"', k + 1);
      if (end == std::string::npos)
        r.fail(line, "an unterminated quoted value for key '" + key + "'",
               "key=\"value\" pairs on the comment line");
      value = s.substr(k + 1, end - k - 1);
      i = end + 1;
    } else {
      std::size_t e = k;
      while (e < s.size() && !blank(s[e])) ++e;
      value = s.substr(k, e - k);
      i = e;
    }
    if (key.empty()) r.fail(line, "a value without a key", "key=value pairs");
    if (kv.count(key)) r.fail(line, "key '" + key + "' twice", "each key once");
    kv[key] = value;
  }
  return kv;
}

double commentReal(const TextReader& r, const TextLine& line, const std::string& key,
                   const std::string& value, const std::string& what) {
  double v = 0.0;
  if (!detail::parseReal(value, v) || !std::isfinite(v))
    r.fail(line, fmt::format("{}={}", key, value), what);
  return v;
}

struct Column {
  std::string name;
  char type = 'R';
  int count = 1;
  int first = 0;  // first field of this property on an atom line
};

std::vector<Column> parseProperties(const TextReader& r, const TextLine& line,
                                    const std::string& spec) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t colon = spec.find(':', start);
    parts.push_back(spec.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  const std::string expected = "Properties=name:type:count:... (e.g. species:S:1:pos:R:3)";
  if (parts.size() % 3 != 0) r.fail(line, "Properties=" + spec, expected);
  std::vector<Column> cols;
  int field = 0;
  for (std::size_t k = 0; k < parts.size(); k += 3) {
    long count = 0;
    if (parts[k + 1].size() != 1 ||
        std::string("SRIL").find(parts[k + 1][0]) == std::string::npos ||
        !detail::parseInteger(parts[k + 2], count) || count < 1 || count > 100)
      r.fail(line, "Properties=" + spec, expected);
    cols.push_back({parts[k], parts[k + 1][0], static_cast<int>(count), field});
    field += static_cast<int>(count);
  }
  return cols;
}

const Column* findColumn(const std::vector<Column>& cols, const std::string& name) {
  for (const auto& c : cols)
    if (c.name == name) return &c;
  return nullptr;
}

// A Lattice periodic along z only: returns T = |c| (Bohr).
double latticePeriod(const TextReader& r, const TextLine& line, const std::string& value) {
  const std::vector<std::string> f = detail::splitFields(value);
  const std::string expected =
      "Lattice=\"ax ay az bx by bz cx cy cz\" (Å) with a and b perpendicular to z and c along z "
      "(mesochain cells are periodic along z only)";
  if (f.size() != 9) r.fail(line, "Lattice=\"" + value + "\"", expected);
  double v[9];
  for (int k = 0; k < 9; ++k)
    if (!detail::parseReal(f[k], v[k]) || !std::isfinite(v[k]))
      r.fail(line, "Lattice=\"" + value + "\"", expected);
  const double tol = 1e-6;
  if (std::abs(v[2]) > tol || std::abs(v[5]) > tol || std::hypot(v[6], v[7]) > tol ||
      !(std::abs(v[8]) > tol))
    r.fail(line, "Lattice=\"" + value + "\"", expected);
  return std::abs(v[8]) * kAngstromInBohr;
}

}  // namespace

XyzFrame readXyz(std::istream& in, const std::string& source) {
  TextReader r(source, in);
  XyzFrame out;
  const TextLine head = r.expect("the number of atoms", false);
  r.requireFields(head, 1, "the number of atoms");
  const long natoms = r.atomCount(head, 0);
  TextLine comment;
  if (!r.nextRaw(comment))
    throw InputError(source, fmt::format("line {}", head.number + 1), "the end of the file",
                     "the comment line");
  const auto kv = parseComment(r, comment);

  // Columns of the atom lines.
  std::vector<Column> cols = {{"species", 'S', 1, 0}, {"pos", 'R', 3, 1}};
  bool exactColumns = false;
  for (const auto& [key, value] : kv)
    if (key == "Properties" || key == "properties") {
      cols = parseProperties(r, comment, value);
      exactColumns = true;
    }
  const Column* sp = findColumn(cols, "species");
  const Column* pos = findColumn(cols, "pos");
  const Column* frc = findColumn(cols, "forces");
  if (!sp || sp->type != 'S' || sp->count != 1 || !pos || pos->type != 'R' || pos->count != 3 ||
      (frc && (frc->type != 'R' || frc->count != 3)))
    r.fail(comment, "Properties without species:S:1 and pos:R:3",
           "species:S:1 and pos:R:3 (and optionally forces:R:3)");
  const std::size_t nfields = static_cast<std::size_t>(cols.back().first + cols.back().count);

  // Each atom takes a line: a count beyond the lines left fails at the first missing line,
  // so never allocate more than the file can fill.
  const long capacity = std::min<long>(natoms, static_cast<long>(r.remaining()));
  ObjectiveCell& cell = out.cell;
  cell.positions.resize(3, capacity);
  if (frc) out.forces.resize(3, capacity);
  for (long a = 0; a < natoms; ++a) {
    TextLine line;
    if (!r.nextRaw(line) || line.tokens.empty())
      throw InputError(source, fmt::format("line {}", head.number + 2 + a),
                       line.number ? "a blank line" : "the end of the file",
                       fmt::format("atom {} of {}", a + 1, natoms));
    r.requireFields(line, nfields, "the columns of Properties", exactColumns);
    const std::string& el = line.tokens[sp->first];
    if (!detail::isElementName(el))
      r.fail(line, "element '" + el + "'", "an element symbol such as C or Si");
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k) x[k] = r.real(line, pos->first + k, "a coordinate (Å)");
    auto it = std::find(cell.speciesNames.begin(), cell.speciesNames.end(), el);
    if (it == cell.speciesNames.end()) it = cell.speciesNames.insert(it, el);
    cell.species.push_back(static_cast<int>(it - cell.speciesNames.begin()));
    cell.positions.col(a) = x * kAngstromInBohr;
    if (frc)
      for (int k = 0; k < 3; ++k)
        out.forces(k, a) =
            r.real(line, frc->first + k, "a force (eV/Å)") * kEvPerAngstromInHartreePerBohr;
  }
  r.expectEnd(fmt::format("the end of the file after {} atoms", natoms), false);

  // Symmetry and energy from the comment line.
  const char* keys[3] = {"mesochain:translation", "mesochain:twist", "mesochain:rotation_order"};
  int found = 0;
  for (const auto& entry : kv) {
    const std::string& key = entry.first;  // (clang 14 cannot capture a structured binding)
    if (isXyzSettingsKey(key)) continue;
    if (key.rfind("mesochain:", 0) == 0 &&
        std::find_if(keys, keys + 3, [&](const char* k) { return key == k; }) == keys + 3)
      r.fail(comment, "key '" + key + "'",
             "mesochain:translation, mesochain:twist, mesochain:rotation_order or a settings "
             "key mesochain:<kpoints|electrons|parameters|dispersion|scc>.<key>");
    if (key.rfind("mesochain:", 0) == 0) ++found;
  }
  if (found > 0 && found < 3)
    r.fail(comment, fmt::format("{} of the 3 mesochain: symmetry keys", found),
           "all of mesochain:translation (Å), mesochain:twist (degrees) and "
           "mesochain:rotation_order");
  if (found == 3) {
    const double t = commentReal(r, comment, keys[0], kv.at(keys[0]), "a translation >= 0 (Å)");
    const double tw = commentReal(r, comment, keys[1], kv.at(keys[1]), "a twist (degrees)");
    long na = 0;
    if (!detail::parseInteger(kv.at(keys[2]), na) || na < 1 || na > 1000000000L)
      r.fail(comment, std::string(keys[2]) + "=" + kv.at(keys[2]), "an integer from 1 to 1000000000");
    if (t < 0.0) r.fail(comment, fmt::format("{}={}", keys[0], t), "a translation >= 0 (Å)");
    if (t == 0.0) {
      const double m = tw * static_cast<double>(na) / 360.0;
      if (std::abs(m - std::round(m)) > 1e-9)
        r.fail(comment, fmt::format("translation 0 with a twist of {} degrees", tw),
               fmt::format("a twist that is a multiple of 360/{} degrees (a closed ring)", na));
    }
    cell.symmetry = Symmetry::fromParameters(t * kAngstromInBohr, tw * kDegree,
                                             static_cast<int>(na), source.c_str());
    out.hasSymmetry = true;
  } else {
    for (const auto& [key, value] : kv)
      if (key == "Lattice" || key == "lattice") {
        cell.symmetry = Symmetry::screw(latticePeriod(r, comment, value), 0.0, 1);
        out.hasSymmetry = true;
      }
  }
  if (auto it = kv.find("energy"); it != kv.end())
    out.energy =
        commentReal(r, comment, "energy", it->second, "an energy (eV)") * units::kEvInHartree;
  return out;
}

XyzFrame readXyzFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "the geometry file cannot be opened (does it exist?)");
  return readXyz(in, path);
}

namespace {

void writeAtoms(std::ostream& out, const ObjectiveCell& cell, const Eigen::Vector3d& shift,
                const Eigen::Matrix3Xd* forces) {
  for (int a = 0; a < cell.atomCount(); ++a) {
    const Eigen::Vector3d x = cell.positions.col(a) * kBohrInAngstrom + shift;
    out << fmt::format("{:<3s} {:>24} {:>24} {:>24}", cell.speciesOf(a), x.x(), x.y(), x.z());
    if (forces) {
      const Eigen::Vector3d f = forces->col(a) / kEvPerAngstromInHartreePerBohr;
      out << fmt::format(" {:>24} {:>24} {:>24}", f.x(), f.y(), f.z());
    }
    out << "\n";
  }
}

}  // namespace

void writeXyz(std::ostream& out, const ObjectiveCell& cell, const XyzExtras& extras) {
  if (extras.forces && extras.forces->cols() != cell.atomCount())
    throw std::invalid_argument("writeXyz: forces do not match the atoms");
  const Symmetry& s = cell.symmetry;
  const double twist = s.isRing() ? 360.0 / s.rotationOrder() : s.twist() / kDegree;
  out << cell.atomCount() << "\n";
  out << "Properties=species:S:1:pos:R:3" << (extras.forces ? ":forces:R:3" : "");
  out << fmt::format(
      " mesochain:translation={} mesochain:twist={} "
      "mesochain:rotation_order={}",
      s.translation() * kBohrInAngstrom, twist, s.rotationOrder());
  if (extras.settings) out << xyzSettingsKeys(*extras.settings);
  if (extras.energy) out << fmt::format(" energy={}", *extras.energy * units::kHartreeInEv);
  out << " pbc=\"F F F\"\n";
  writeAtoms(out, cell, Eigen::Vector3d::Zero(), extras.forces);
}

void writeXyzFile(const std::string& path, const ObjectiveCell& cell, const XyzExtras& extras) {
  AtomicOutputFile file(path);
  writeXyz(file.stream(), cell, extras);
  file.commit();
}

long long unrolledAtomCount(const ObjectiveCell& cell, long zetaMin, long zetaMax) {
  if (cell.symmetry.isRing()) zetaMin = zetaMax = 0;
  const long double steps = static_cast<long double>(zetaMax) - zetaMin + 1;
  const long double atoms = steps * cell.symmetry.rotationOrder() * cell.atomCount();
  return atoms > 9e18L ? std::numeric_limits<long long>::max() : static_cast<long long>(atoms);
}

ObjectiveCell unroll(const ObjectiveCell& cell, long zetaMin, long zetaMax) {
  const Symmetry& s = cell.symmetry;
  if (s.isRing()) zetaMin = zetaMax = 0;
  if (zetaMax < zetaMin)
    throw InputError("<unroll>", "zeta range", fmt::format("{}..{}", zetaMin, zetaMax),
                     "zetaMin <= zetaMax");
  const long long atoms = unrolledAtomCount(cell, zetaMin, zetaMax);
  if (atoms > kMaxUnrolledAtoms)
    throw InputError("<unroll>", "zeta range", fmt::format("{}..{}: {} atoms (about {:.3g} GB)",
                                                         zetaMin, zetaMax, atoms, atoms * 60e-9),
                     fmt::format("at most {} unrolled atoms", kMaxUnrolledAtoms));
  ObjectiveCell out;
  out.speciesNames = cell.speciesNames;
  const long nz = zetaMax - zetaMin + 1;
  out.positions.resize(3, nz * s.rotationOrder() * cell.atomCount());
  int col = 0;
  for (long zeta = zetaMin; zeta <= zetaMax; ++zeta)
    for (int c = 0; c < s.rotationOrder(); ++c)
      for (int a = 0; a < cell.atomCount(); ++a) {
        out.species.push_back(cell.species[a]);
        out.positions.col(col++) = s.apply({zeta, c}, cell.positions.col(a));
      }
  if (!s.isRing() && s.twist() == 0.0)
    out.symmetry = Symmetry::screw(static_cast<double>(nz) * s.translation(), 0.0, 1);
  else
    out.symmetry = Symmetry::ring(1);
  return out;
}

void writeUnrolledXyzFile(const std::string& path, const ObjectiveCell& cell, long zetaMin,
                          long zetaMax) {
  const ObjectiveCell u = unroll(cell, zetaMin, zetaMax);
  AtomicOutputFile file(path);
  std::ofstream& out = file.stream();
  out << u.atomCount() << "\n";
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  if (u.symmetry.isRing()) {
    out << "Properties=species:S:1:pos:R:3 pbc=\"F F F\"\n";
  } else {
    double rmax = 0.0;
    for (int a = 0; a < u.atomCount(); ++a)
      rmax = std::max(rmax, std::hypot(u.positions(0, a), u.positions(1, a)));
    const double box = 2.0 * rmax * kBohrInAngstrom + 20.0;
    shift << box / 2, box / 2, 0.0;
    out << fmt::format(
        "Lattice=\"{0} 0 0 0 {0} 0 0 0 {1}\" Properties=species:S:1:pos:R:3 "
        "pbc=\"F F T\"\n",
        box, u.symmetry.translation() * kBohrInAngstrom);
  }
  writeAtoms(out, u, shift, nullptr);
  file.commit();
}

}  // namespace mesochain::objective
