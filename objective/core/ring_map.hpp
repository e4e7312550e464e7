#pragma once
// Bending a straight objective cell into a closed ring (and back), the geometry of bend scans.
//
// Straight cell: axis z, translation T0, twist 0, rotation order 1 (a translational cell).
// Its cross-section is described in a right-handed frame (e_r, e_a, e_z) centred on the
// centroid c of the x-y positions: u_r = (p - c).e_r is the coordinate that will point along
// the ring radius, u_a = (p - c).e_a with e_a = e_z x e_r the one that will lie along the ring
// axis. The ring of N_a cells has the nominal (neutral-line) radius R = N_a T0 / (2 pi) and
// its own axis Z; the map
//   X = (R + u_r) cos(z / R),  Y = (R + u_r) sin(z / R),  Z = -u_a
// sends the screw translation z -> z + T0 to the rotation by 2 pi / N_a about Z (so the ring's
// symmetry is the cyclic group C_{N_a}, T = 0), keeps arc length along the centroid line
// (R dtheta = dz) and is proper (orientation preserving; the sign of Z makes it so: the local
// frame (e_r, e_a, e_z) goes to (X, -Z, Y)).
//
// Bending directions of a flattened cell (width along its long principal axis, thickness along
// the short one): "soft" bends about the long axis, so the thin direction runs along the ring
// radius (e_r = short axis): the flat faces become coaxial cylinders around the ring axis, like
// a belt. "hard" bends in the plane of the faces (e_r = long axis): the width runs along the
// radius and the faces become flat annuli perpendicular to the ring axis, like a washer.
// For a round tube both give the same ring.
#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class BendDirection { Soft, Hard };

// The cross-section frame of a straight cell: centroid and the radial unit vector e_r in the
// x-y plane (e_a = e_z x e_r).
struct BendFrame {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d radial = Eigen::Vector2d::UnitX();
};

// Principal axes of the x-y positions: soft -> the short axis is radial, hard -> the long axis.
BendFrame bendFrame(const ObjectiveCell& straight, BendDirection direction);

// The ring of `rotationOrder` copies of the straight cell (translation T0 > 0, twist 0,
// rotation order 1). Throws InputError (source "<bend>") for another symmetry, N_a < 2, or a
// radius at which an atom would reach the ring axis (R + u_r < 1 Bohr).
ObjectiveCell straightToRing(const ObjectiveCell& straight, const BendFrame& frame,
                             int rotationOrder);
// The inverse for a ring made by straightToRing (positions in the cell's straight frame with
// the centroid at the origin, e_r = x, e_a = y): translation T0 = 2 pi R / N_a where R is
// the nominal radius `radius`. Used to carry relaxed atoms from one ring to the next.
ObjectiveCell ringToStraight(const ObjectiveCell& ring, double radius);

// A sector cell (screw T along z with twist 0 and rotation order N_from, e.g. a bent graphene
// stack from buildGrapheneRingSector) rebent to `rotationOrderTo` sectors: each atom at
// (rho, theta, z) goes to (rho - radiusFrom + radiusTo, theta N_from / N_to, z), keeping arc
// lengths along the line of radius radiusFrom -> radiusTo (the nominal middle radii).
ObjectiveCell rebendSector(const ObjectiveCell& sector, double radiusFrom, double radiusTo,
                           int rotationOrderTo);

// Mean distance of the cell's atoms from the ring axis (Bohr): the measured radius of the
// centroid line (its inverse is the measured curvature).
double meanRingRadius(const ObjectiveCell& ring);

}  // namespace mesochain::objective
