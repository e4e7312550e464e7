#pragma once
// Face-to-face van der Waals contact between two bricks (collapsed tubes), docs/mdem-contacts.md.
//
// Model. A brick (body x = thickness, y = width w, z = length L) is a collapsed tube: two
// graphene layers of areal density n, parallel to its mid-plane at x = +-t/2 (t = the layer
// spacing), each a w x L rectangle. Two layer sheets at separation z interact, per unit area of
// overlap, by the Lennard-Jones potential integrated over an infinite sheet (the 10-4 wall):
//   e(z) = 2 pi eps n^2 sigma^2 [ (2/5) (sigma/z)^10 - (sigma/z)^4 ]            (E1)
// (an atom at height z over a sheet: \int 2 pi rho 4 eps [sigma^12/r^12 - sigma^6/r^6] drho with
// r^2 = z^2 + rho^2). Two bricks whose mid-planes are a distance D apart then have, per unit
// overlap area, f(D) = e(D - t) + 2 e(D) + e(D + t)  (near-near, two near-far, far-far)  (E2)
// which is even in D (a flipped brick is the same brick; no face has to be chosen).
// e is switched to zero (C2 quintic) between the gaps switch_gap and cutoff_gap and, below
// 0.7 sigma, continued linearly (a finite wall, as for tubes).
//
// Energy of a pair: an integral over the mid-plane rectangle of brick a,
//   E = \int_{A_a} dA(p) S_b(p) f(g(p)),                                          (E3)
// g(p) = n_b . (p - x_b) the signed distance of p from the mid-plane of b, and S_b(p) a smooth
// indicator of the projection of p falling inside the rectangle of b: S_b = s(u; w_b/2) s(v; L_b/2)
// with u, v the in-plane coordinates of p - x_b along b's width and length and s(x; a) a C2
// quintic ramp from 1 at |x| = a - delta to 0 at |x| = a + delta (symmetric about the edge, so
// \int s dx = 2a: the area of a fully covered overlap is exact; delta = `edge_width_nm`, of the
// order of the range over which the field of a finite sheet falls off beyond its edge). The
// integral over a is a Gauss-Legendre product rule (`face_points` per direction on each of
// `face_panels` panels). E is thus the projected overlap area times the energy per area for
// parallel bricks; tilting varies g across the face (aligning moment about in-plane axes), and
// twisting about the normal changes the overlap (aligning moment for unequal w and L).
// Forces and torques are the exact gradients of the quadrature (E3) (world frame; torque =
// -dE/dphi for q -> exp(phi) q).
#include "mdem/contacts/quadrature.hpp"
#include "mdem/contacts/tube_potential.hpp"
#include "mdem/contacts/vdw_contact.hpp"
#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

struct FaceContactSpec {
  LennardJones lj;
  double layerSpacing = 0.34;  // t, nm
  double edgeWidth = 0.6;      // delta, nm (docs/mdem-contacts.md: fitted to the layer quadrature)
  double switchGap = 0.8;      // nm (gap between two layers)
  double cutoffGap = 1.2;      // nm
  int points = 4;              // Gauss points per panel per direction
  int panels = 4;              // panels per direction over a brick face
};

// A brick's mid-plane rectangle: centre, unit normal (body x), width and length axes (body y, z).
struct BrickFace {
  Vec3 centre, normal, widthAxis, lengthAxis;
  double halfWidth = 0.0, halfLength = 0.0;
};
BrickFace brickFace(const Vec3& centre, const Quat& orientation, double width, double length);

class FaceContactModel {
 public:
  explicit FaceContactModel(const FaceContactSpec& spec);
  const FaceContactSpec& spec() const { return spec_; }
  // (E1) with the switch and the wall continuation, zJ/nm^2, and its derivative.
  double layerPairEnergy(double z, double* derivative) const;
  // (E2), even in D.
  double bilayerEnergy(double d, double* derivative) const;
  // Largest |D| with f(D) != 0.
  double cutoffDistance() const { return spec_.layerSpacing + spec_.cutoffGap; }
  // Largest centre distance at which two faces interact.
  double interactionRange(const BrickFace& a, const BrickFace& b) const;
  // Energy, forces and torques of the pair (E3); the quadrature runs over a.
  ContactPairResult evaluate(const BrickFace& a, const BrickFace& b) const;

 private:
  FaceContactSpec spec_;
  QuadratureRule rule_;  // composite rule on [-1, 1]
  double zWall_ = 0.0, eWall_ = 0.0, dWall_ = 0.0;
};

}  // namespace mesochain::mdem
