#pragma once
// DFTB+ .gen geometry files (format: DFTB+ manual, "Gen format"; helical type as in the
// DFTB+ helical tests). Coordinates and lengths in the file are in Å, angles in degrees.
//
//   line 1: number of atoms and type: C (cluster), S (periodic, Cartesian),
//           F (periodic, fractional) or H (helical); case-insensitive
//   line 2: the element names, indexed from 1
//   then one line per atom: index (an integer, ignored), element index, x, y, z
//   S/F:    origin line, then the three lattice vectors, one per line (Å)
//   H:      origin line (Å), then "T(Å) twist(degrees) rotation_order"
// Lines whose first field starts with '#' and blank lines are skipped. The origin is
// subtracted from the coordinates (for H the helical axis then passes through x = y = 0).
//
// mesochain cells are periodic along z only: S and F are accepted when the first two lattice
// vectors are perpendicular to z (they only set the vacuum and are ignored) and the third is
// along z; this maps to a screw with T = |c|, gamma = 0, N_a = 1. H with T = 0 is a closed
// ring (the twist must then be a multiple of 360/N_a); DFTB+ itself needs T > 0.
#include <iosfwd>
#include <string>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class GenType { Cluster, Supercell, Fractional, Helical };

struct GenGeometry {
  ObjectiveCell cell;  // Bohr, radians
  GenType type = GenType::Cluster;
};

// Errors are InputError naming `source` (the file) and the line.
GenGeometry readGen(std::istream& in, const std::string& source);
GenGeometry readGenFile(const std::string& path);

// Writes C for a cluster (ring of order 1), S for a plain translation (gamma = 0, N_a = 1;
// lattice: a square vacuum box of 2 * (largest radius) + 20 Å in x and y, c = (0, 0, T)),
// and H otherwise. Full double precision.
void writeGen(std::ostream& out, const ObjectiveCell& cell);
void writeGenFile(const std::string& path, const ObjectiveCell& cell);

}  // namespace mesochain::objective
