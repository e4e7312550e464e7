#pragma once
// Extended XYZ files (the extxyz convention of ASE, OVITO and libAtoms: a count line, a comment
// line of key=value pairs, one line per atom). Positions in Å; `energy` in eV and `forces` in
// eV/Å, as ASE expects.
//
// mesochain writes and reads its symmetry on the comment line with three keys, all required
// when any is present:
//   mesochain:translation=T (Å, 0 = closed ring)  mesochain:twist=gamma (degrees)
//   mesochain:rotation_order=N_a
// Without them, a `Lattice` whose first two vectors are perpendicular to z and whose third is
// along z is read as a screw with T = |c|, gamma = 0, N_a = 1 (as for .gen type S); any other
// Lattice is an error; no Lattice at all is a cluster. The settings keys
// mesochain:<section>.<key> of input/xyz_settings.hpp are accepted and not used here. `Properties` (if given) must contain
// species:S:1 and pos:R:3; forces:R:3 is read when present; other columns are skipped.
#include <iosfwd>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

struct CellInput;

struct XyzFrame {
  ObjectiveCell cell;            // Bohr, radians
  bool hasSymmetry = false;      // true when mesochain: keys or a Lattice were read
  std::optional<double> energy;  // Hartree
  Eigen::Matrix3Xd forces;       // Hartree/Bohr; empty when the file has none
};

// Errors are InputError naming `source` and the line.
XyzFrame readXyz(std::istream& in, const std::string& source);
XyzFrame readXyzFile(const std::string& path);

struct XyzExtras {
  std::optional<double> energy;              // Hartree (written as energy=... in eV)
  const Eigen::Matrix3Xd* forces = nullptr;  // Hartree/Bohr, 3 x N_o (written in eV/Å)
  // The settings that produced the energy (k-points, temperature, parameters, dispersion, SCC),
  // written as mesochain:<section>.<key> (input/xyz_settings.hpp).
  const CellInput* settings = nullptr;
};

// The objective cell with its symmetry on the comment line.
void writeXyz(std::ostream& out, const ObjectiveCell& cell, const XyzExtras& extras = {});
void writeXyzFile(const std::string& path, const ObjectiveCell& cell, const XyzExtras& extras = {});

// At most this many atoms in an unrolled structure (about 60 bytes each in memory and 60 in
// the .xyz text: 0.6 GB each); unrolledAtomCount is the count a range gives, checked before
// anything is allocated.
inline constexpr long long kMaxUnrolledAtoms = 10'000'000;
long long unrolledAtomCount(const ObjectiveCell& cell, long zetaMin, long zetaMax);
// The images g(zeta, c) of the cell atoms for zeta = zetaMin..zetaMax and every c, as plain
// atoms (ordered by zeta, then c, then cell atom). The result is periodic along z with
// period (zetaMax - zetaMin + 1) T when gamma = 0 (symmetry: screw with gamma = 0, N_a = 1),
// and a cluster otherwise. For a ring, only zeta = 0 exists and the range is ignored.
ObjectiveCell unroll(const ObjectiveCell& cell, long zetaMin, long zetaMax);
// Writes unroll(...) for viewing (OVITO, ASE). When it is periodic along z, the file carries
// Lattice="L 0 0 0 L 0 0 0 nT" with pbc="F F T", L = 2 * (largest radius) + 20 Å, and the
// atoms are shifted by (L/2, L/2, 0) so the axis runs through the centre of the box.
void writeUnrolledXyzFile(const std::string& path, const ObjectiveCell& cell, long zetaMin,
                          long zetaMax);

}  // namespace mesochain::objective
