#pragma once
// AB-stacked graphene layers bent into concentric cylinders about z (a "ring sector" cell).
//
// Flat sheet: the lattice of nanotube_builder.hpp, a1 = a (sqrt3/2, 1/2), a2 = a (sqrt3/2,
// -1/2), a = sqrt3 * bond. The sheet direction along the arc is C = n a1 + m a2 for chiral
// indices 0 <= m <= n (not both 0), reduced by gcd(n, m) to the primitive vector; (1, 0) is
// zigzag, (1, 1) armchair. Along z runs the translational vector T = t1 a1 + t2 a2 of the
// (n, m) tube, t1 = (2m+n)/d_R, t2 = -(2n+m)/d_R, d_R = gcd(2n+m, 2m+n), which is
// perpendicular to C with |T| = sqrt3 |C| / d_R (White, Robertson & Mintmire, PRB 47, 5485
// (1993)). One sheet cell is the parallelogram C x T with 4 (n^2+nm+m^2)/d_R atoms (4 for
// zigzag and armchair, 28 for (2, 1)). A sheet point r has arc coordinate r.C/|C| and axial
// coordinate (C x r)/|C|, the handedness of the nanotube roll-up. Sheet atoms at 0 and
// 2 (a1 + a2)/3 (the nanotube builder's sheet moved by -(a1 + a2)/3), so that zigzag and
// armchair give the rectangle cell (0, 0), (a/2, b/2), (a/2, 3b/2), (0, 2b) (x zigzag, y
// armchair, b the bond) with its arc and axial coordinates unchanged.
// Bernal (AB) stacking shifts every second layer by one bond length along the armchair
// direction, the sheet vector (a1 + a2)/3 for every chiral direction (its atoms then sit over
// atoms and hexagon centres of the layer below), wrapped into the cell.
//
// Bending: one angular sector of 2 pi / N_a holds `cellsAlongArc` sheet cells of every layer.
// The middle layer (radius R_mid) is unstrained: N_a * cellsAlongArc * |C| = 2 pi R_mid.
// Layer k = 0..N-1 sits at R_k = R_mid + (k - (N-1)/2) * interlayer and has the same angular
// positions as the middle layer (phi = s / R_mid for arc coordinate s): inner layers are
// compressed along the arc by R_k / R_mid, outer ones stretched, and the AB registry is kept
// in angle. Atoms are ordered layer by layer (innermost first), cell by cell along the arc.
// A monolayer sector (n, m) with N_a sectors of c cells is the (c N_a n, c N_a m) nanotube.
// Symmetry: screw with gamma = 0 and T = |T| along z, rotation order N_a. Lengths in Bohr.
#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class Direction { Armchair, Zigzag };

// Chiral indices of the sheet direction along the arc.
struct ChiralIndices {
  int n = 1;
  int m = 0;
};

// (1, 1) for Armchair, (1, 0) for Zigzag.
ChiralIndices chiralIndices(Direction dir);

// The flat sheet cell of one direction: the primitive indices, the periods |C| (along the arc)
// and |T| (along z) in Bohr, and the atoms per layer and cell.
struct GrapheneSheetCell {
  ChiralIndices primitive;
  double arcPeriod = 0.0;
  double axialPeriod = 0.0;
  int atomsPerLayer = 0;
};
// Throws InputError (source "<builder>", key "chiral") unless 0 <= m <= n and n >= 1.
GrapheneSheetCell grapheneSheetCell(ChiralIndices dir, double bondLength);

ObjectiveCell buildGrapheneRingSector(int layers, ChiralIndices dir, int rotationOrder,
                                      int cellsAlongArc, double interlayer, double bondLength);
// Armchair and zigzag: the chiral builder with (1, 1) and (1, 0).
ObjectiveCell buildGrapheneRingSector(int layers, Direction dir, int rotationOrder,
                                      int cellsAlongArc, double interlayer, double bondLength);

}  // namespace mesochain::objective
