#pragma once
// Geometry of laying a tube onto a film (mdem/contacts/deposition.hpp): how high an element must
// rest to clear what lies below it, and the draped height profile of a whole tube.
//
// Support height. A horizontal segment A = {p + s a : |s| <= h_a, z} (a horizontal unit vector)
// and a segment B = {c + t b : |t| <= h_b}. Because A is horizontal, the distance of a point
// B(t) from A(z) is sqrt(d_h(t)^2 + (B_z(t) - z)^2), with d_h the in-plane distance of B(t)'s
// footprint from A's footprint. A(z) keeps distance >= D from all of B exactly when
//   z >= z_hi = max_t [ B_z(t) + sqrt(D^2 - d_h(t)^2) ]   over the t with d_h(t) <= D.
// d_h^2 is a quadratic in t on each of three pieces (B(t)'s footprint projecting before, onto or
// after A's footprint), so on each piece the function is linear + sqrt(concave quadratic), a
// concave function whose maximum is an end of the piece or a root of a quadratic (the
// stationarity condition squared): z_hi is computed in closed form, not by a search.
//
// An element tilted out of the plane whose footprint lies within that of A and whose points are
// all at heights >= z_hi clears B as well (each of its points lies on a horizontal copy of A at a
// height >= z_hi), which is how deposition.cpp uses this for tilted elements.
//
// Draped profile. The heights zeta_e of the n+1 ends of an n-element tube follow
//   zeta_e = max_j ( required_j - f(|e - j|) ),
// the lowest profile above every required end height whose climb away from a crest is bounded:
// f(d) = sum_{i=1..d} L sin(min(alpha, (i - 1/2) beta)), i.e. the slope of consecutive elements
// changes by at most beta at a crest (a bend of beta per bond) and never exceeds alpha. Where two
// crests' flanks meet (a tube sagging between two supports) the profile has a kink of at most
// 2 alpha. Computed in O(n d0), d0 = alpha / beta: near crests directly, beyond them by a forward
// and a backward sweep of the linear tail.
#include <vector>

#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

// z_hi above (relative to A's height 0); `c` is B's centre relative to A's centre (minimum
// image applied by the caller), `a` a horizontal unit vector, `b` a unit vector. Returns
// -infinity when B's footprint stays farther than D from A's.
double supportHeight(const Vec3& a, double halfLengthA, const Vec3& c, const Vec3& b, double halfLengthB,
                     double clearance);

struct DrapeProfile {
  double elementLength = 0.0;  // L, nm
  double maxSlope = 0.0;       // alpha, rad (< pi/2)
  double bendPerElement = 0.0; // beta, rad (> 0)
};

// Heights of the ends (size n+1) from the required heights of the ends (size n+1).
std::vector<double> drapeEnvelope(const std::vector<double>& required, const DrapeProfile& p);

}  // namespace mesochain::mdem
