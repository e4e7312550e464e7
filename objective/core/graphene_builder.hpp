#pragma once
// AB-stacked graphene layers bent into concentric cylinders about z (a "ring sector" cell).
//
// Flat sheet frame: the zigzag direction is x (period a = sqrt3 * bond), the armchair
// direction is y (period 3 * bond); the rectangular cell holds 4 atoms at
// (0, 0), (a/2, b/2), (a/2, 3b/2), (0, 2b) with b the bond length. Bernal (AB) stacking
// shifts every second layer by one bond length along y (its atoms then sit over atoms and
// hexagon centres of the layer below).
//
// Bending: `dir` names the sheet direction that runs along the arc (Zigzag: x along the arc,
// y along z; Armchair: y along the arc, x along z). One angular sector of 2 pi / N_a holds
// `cellsAlongArc` rectangular cells of every layer. The middle layer (radius R_mid) is
// unstrained: N_a * cellsAlongArc * (period along the arc) = 2 pi R_mid. Layer k = 0..N-1
// sits at R_k = R_mid + (k - (N-1)/2) * interlayer and has the same angular positions as the
// middle layer (phi = s / R_mid for arc coordinate s): inner layers are compressed along the
// arc by R_k / R_mid, outer ones stretched, and the AB registry is kept in angle.
// Symmetry: screw with gamma = 0 and T = the sheet period along z, rotation order N_a.
// Lengths in Bohr.
#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class Direction { Armchair, Zigzag };

ObjectiveCell buildGrapheneRingSector(int layers, Direction dir, int rotationOrder,
                                      int cellsAlongArc, double interlayer, double bondLength);

}  // namespace mesochain::objective
