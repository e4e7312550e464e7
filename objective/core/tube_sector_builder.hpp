#pragma once
// Angular sectors of multi-walled tubes whose walls carry different numbers of atoms (issue 15,
// few-layer graphene with free interlayer sliding).
//
// A wall (n, m) is mapped onto itself by the rotation 2 pi / d exactly when d divides
// gcd(n, m) (C_h / d is then a lattice vector; nanotube_builder.hpp). So the sector of
// 2 pi / d of walls that share one translational period is an exact objective cell (screw
// T, gamma = 0, rotation order d) when d divides every wall's gcd: every wall is its own ideal
// roll-up, unstrained at its own radius, and holds 4 (n² + nm + m²) / (d_R d) atoms, a number
// that differs from wall to wall (the C5 sector of (35,35)@(40,40): 28 + 32 atoms). Unlike a
// graphene ring (graphene_builder.hpp: the same atoms in every layer, so the outer layers are
// stretched and the inner compressed: the bonded plate) the walls of such a sector have the
// lengths of layers that have slid freely past each other.
//
// Families: armchair walls (n, n) with T = a and zigzag walls (n, 0) with T = sqrt3 a share their
// period within the family. The walls of a family step their index by s: radius step
// s a sqrt3 / 2 pi (armchair; s = 5: 3.39 Å at 1.42 Å bonds) or s a / 2 pi (zigzag; s = 9:
// 3.52 Å, s = 8: 3.13 Å). The largest exact sector (the fewest atoms) has d = gcd of all wall
// indices; any divisor of it gives a wider sector.
#include <string>
#include <utility>
#include <vector>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class TubeFamily { Armchair, Zigzag };

// "armchair" / "zigzag"; InputError(source, key) otherwise.
TubeFamily tubeFamily(const std::string& name, const std::string& source, const std::string& key);

// Walls (inner first): index n_k = inner + k step, k = 0..walls-1; (n_k, n_k) or (n_k, 0).
// InputError unless inner >= 1, 1 <= walls <= 100, step >= 1.
std::vector<std::pair<int, int>> familyWalls(TubeFamily family, int inner, int walls, int step);

// The index step whose radius step is nearest `spacing` (Bohr) for the bond length (Bohr).
int nearestIndexStep(TubeFamily family, double spacing, double bondLength);

// gcd of n and m over all walls: the largest rotation order of an exact sector.
int largestSectorOrder(const std::vector<std::pair<int, int>>& walls);

}  // namespace mesochain::objective
