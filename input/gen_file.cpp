#include "input/gen_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/text_reader.hpp"

namespace mesochain::objective {

using detail::isElementName;
using detail::TextLine;
using detail::TextReader;
using units::kAngstromInBohr;
using units::kBohrInAngstrom;
using units::kDegree;

namespace {

Eigen::Vector3d readVector(const TextReader& r, const TextLine& line, const std::string& what) {
  r.requireFields(line, 3, what);
  return {r.real(line, 0, what), r.real(line, 1, what), r.real(line, 2, what)};
}

// Lattice vectors a, b must be perpendicular to z, c along z (1D periodicity along z).
double axialPeriod(const TextReader& r, const TextLine lines[3], const Eigen::Vector3d v[3]) {
  const double tol = 1e-6;  // Å
  for (int k = 0; k < 2; ++k)
    if (std::abs(v[k].z()) > tol)
      r.fail(lines[k],
             fmt::format("lattice vector {} = ({}, {}, {}) Å with a z component", k + 1, v[k].x(),
                         v[k].y(), v[k].z()),
             "the first two lattice vectors perpendicular to z: mesochain cells are periodic "
             "along z only, and a and b only set the vacuum");
  if (std::hypot(v[2].x(), v[2].y()) > tol || !(std::abs(v[2].z()) > tol))
    r.fail(lines[2], fmt::format("lattice vector 3 = ({}, {}, {}) Å", v[2].x(), v[2].y(), v[2].z()),
           "a third lattice vector along z (mesochain cells are periodic along z only)");
  return std::abs(v[2].z());
}

// a and b of an S/F file only set the vacuum: mesochain's cell is periodic along z alone. When
// the atoms' images along a, b, a+b or a-b would come closer than kMinimumVacuumGapAngstrom
// (about twice the range of the Slater-Koster tables, 5.5 Å for pbc-0-3), DFTB+ would compute
// a 2-D or 3-D crystal from the same file: refused rather than run silently as a 1-D chain.
// The gap along a lateral vector L is |L| minus the atoms' extent along L (a lower bound of
// the distance of an atom to the images of the others).
constexpr double kMinimumVacuumGapAngstrom = 10.0;

void requireVacuumLattice(const TextReader& r, const TextLine lines[3], const Eigen::Vector3d v[3],
                          const Eigen::Matrix3Xd& positionsAngstrom) {
  const Eigen::Vector3d lateral[4] = {v[0], v[1], v[0] + v[1], v[0] - v[1]};
  const char* names[4] = {"a (lattice vector 1)", "b (lattice vector 2)", "a + b", "a - b"};
  for (int k = 0; k < 4; ++k) {
    const double length = lateral[k].norm();
    if (!(length > 0)) continue;
    const Eigen::Vector3d u = lateral[k] / length;
    const Eigen::VectorXd along = u.transpose() * positionsAngstrom;
    const double extent = along.size() ? along.maxCoeff() - along.minCoeff() : 0.0;
    const double gap = length - extent;
    if (gap < kMinimumVacuumGapAngstrom)
      r.fail(lines[k < 2 ? k : 0],
             fmt::format("periodic images along {} only {:.3g} Å apart (|{}| = {:.4g} Å, the atoms span "
                         "{:.4g} Å along it): as DFTB+ reads this file it is a 2-D or 3-D periodic crystal",
                         names[k], gap, names[k], length, extent),
             fmt::format("lattice vectors a and b that leave at least {:.0f} Å of vacuum between the "
                         "images (mesochain's cell is periodic along z only; a crystal is not an "
                         "objective cell: use a cell file with its symmetry)",
                         kMinimumVacuumGapAngstrom));
  }
}

}  // namespace

GenGeometry readGen(std::istream& in, const std::string& source) {
  TextReader r(source, in);
  GenGeometry out;
  const TextLine head = r.expect("the number of atoms and the type (C, S, F or H)", true);
  r.requireFields(head, 2, "the number of atoms and the type (C, S, F or H)");
  const long natoms = r.atomCount(head, 0);
  const std::string t = head.tokens[1];
  const char type = t.size() == 1 ? static_cast<char>(std::toupper(t[0])) : '?';
  switch (type) {
    case 'C':
      out.type = GenType::Cluster;
      break;
    case 'S':
      out.type = GenType::Supercell;
      break;
    case 'F':
      out.type = GenType::Fractional;
      break;
    case 'H':
      out.type = GenType::Helical;
      break;
    default:
      r.fail(head, "type '" + t + "'", "C, S, F or H");
  }
  const TextLine names = r.expect("the element names", true);
  for (std::size_t k = 0; k < names.tokens.size(); ++k) {
    const std::string& name = names.tokens[k];
    if (!isElementName(name))
      r.fail(names, "element name '" + name + "'", "element symbols such as C or Si");
    for (std::size_t l = 0; l < k; ++l)
      if (names.tokens[l] == name) r.fail(names, "'" + name + "' twice", "unique element names");
  }
  ObjectiveCell& cell = out.cell;
  cell.speciesNames = names.tokens;
  const long nspecies = static_cast<long>(names.tokens.size());
  std::vector<bool> used(names.tokens.size(), false);
  // Each atom takes a line: a count beyond the lines left fails at the first missing line,
  // so never allocate more than the file can fill.
  const long capacity = std::min<long>(natoms, static_cast<long>(r.remaining()));
  cell.positions.resize(3, capacity);
  const std::string atomFields = "index, element index, x, y, z";
  for (long a = 0; a < natoms; ++a) {
    const TextLine line =
        r.expect(fmt::format("atom {} of {} ({})", a + 1, natoms, atomFields), true);
    r.requireFields(line, 5, atomFields);
    r.integer(line, 0, "an integer atom index");
    const long sp = r.integer(line, 1, "an element index");
    if (sp < 1 || sp > nspecies)
      r.fail(line, fmt::format("element index {}", sp),
             fmt::format("an element index between 1 and {}", nspecies));
    used[sp - 1] = true;
    cell.species.push_back(static_cast<int>(sp - 1));
    for (int k = 0; k < 3; ++k) cell.positions(k, a) = r.real(line, 2 + k, "a coordinate");
  }
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k])
      r.fail(names, "element '" + names.tokens[k] + "' that no atom uses",
             "only the elements of the atoms");

  if (out.type == GenType::Cluster) {
    cell.positions *= kAngstromInBohr;
    cell.symmetry = Symmetry::ring(1);
  } else if (out.type == GenType::Helical) {
    const TextLine oline = r.expect("the origin (3 numbers, Å)", true);
    const Eigen::Vector3d origin = readVector(r, oline, "the origin x, y, z (Å)");
    const std::string what = "T (Å), twist (degrees), rotation order";
    const TextLine hline = r.expect("the helical line: " + what, true);
    r.requireFields(hline, 3, what);
    const double tr = r.real(hline, 0, "a translation T >= 0 (Å)");
    const double twist = r.real(hline, 1, "a twist angle (degrees)");
    const double order = r.real(hline, 2, "an integer rotation order >= 1");
    if (tr < 0.0) r.fail(hline, fmt::format("T = {} Å", tr), "a translation T >= 0 (Å)");
    if (order < 1.0 || order != std::floor(order) || order > 1e9)
      r.fail(hline, fmt::format("rotation order {}", hline.tokens[2]),
             "an integer rotation order from 1 to 1000000000");
    const int na = static_cast<int>(order);
    if (tr == 0.0) {
      const double m = twist * na / 360.0;
      if (std::abs(m - std::round(m)) > 1e-9)
        r.fail(hline, fmt::format("T = 0 with a twist of {} degrees", twist),
               fmt::format("a twist that is a multiple of 360/{} degrees (a closed ring)", na));
    }
    cell.positions = (cell.positions.colwise() - origin) * kAngstromInBohr;
    cell.symmetry =
        Symmetry::fromParameters(tr * kAngstromInBohr, twist * kDegree, na, source.c_str());
  } else {
    const TextLine oline = r.expect("the origin (3 numbers)", true);
    Eigen::Vector3d origin = readVector(r, oline, "the origin x, y, z");
    TextLine lines[3];
    Eigen::Vector3d v[3];
    for (int k = 0; k < 3; ++k) {
      lines[k] = r.expect(fmt::format("lattice vector {} (3 numbers, Å)", k + 1), true);
      v[k] = readVector(r, lines[k], "a lattice vector x, y, z (Å)");
    }
    const double period = axialPeriod(r, lines, v);
    Eigen::Matrix3d lattice;
    lattice << v[0], v[1], v[2];
    if (out.type == GenType::Fractional) {
      cell.positions = lattice * cell.positions;
      origin = lattice * origin;
    }
    requireVacuumLattice(r, lines, v, cell.positions);
    cell.positions = (cell.positions.colwise() - origin) * kAngstromInBohr;
    cell.symmetry = Symmetry::screw(period * kAngstromInBohr, 0.0, 1);
  }
  r.expectEnd(fmt::format("the end of the file after {} atoms and the {} lines", natoms,
                          out.type == GenType::Cluster ? "atom" : "symmetry"),
              true);
  return out;
}

GenGeometry readGenFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "the geometry file cannot be opened (does it exist?)");
  return readGen(in, path);
}

void writeGen(std::ostream& out, const ObjectiveCell& cell) {
  const Symmetry& s = cell.symmetry;
  const bool cluster = s.isRing() && s.rotationOrder() == 1;
  const bool supercell = !s.isRing() && s.twist() == 0.0 && s.rotationOrder() == 1;
  out << fmt::format("{} {}\n", cell.atomCount(), cluster ? 'C' : (supercell ? 'S' : 'H'));
  for (std::size_t k = 0; k < cell.speciesNames.size(); ++k)
    out << (k ? " " : "") << cell.speciesNames[k];
  out << "\n";
  double rmax = 0.0;
  for (int a = 0; a < cell.atomCount(); ++a) {
    const Eigen::Vector3d x = cell.positions.col(a) * kBohrInAngstrom;
    rmax = std::max(rmax, std::hypot(x.x(), x.y()));
    out << fmt::format("{:6d} {:3d} {:>24} {:>24} {:>24}\n", a + 1, cell.species[a] + 1, x.x(),
                       x.y(), x.z());
  }
  if (cluster) return;
  out << "0.0 0.0 0.0\n";
  const double t = s.translation() * kBohrInAngstrom;
  if (supercell) {
    const double box = 2.0 * rmax + 20.0;
    out << fmt::format("{} 0.0 0.0\n0.0 {} 0.0\n0.0 0.0 {}\n", box, box, t);
  } else {
    const double twist = s.isRing() ? 360.0 / s.rotationOrder() : s.twist() / kDegree;
    out << fmt::format("{} {} {}\n", t, twist, s.rotationOrder());
  }
}

void writeGenFile(const std::string& path, const ObjectiveCell& cell) {
  AtomicOutputFile file(path);
  writeGen(file.stream(), cell);
  file.commit();
}

}  // namespace mesochain::objective
