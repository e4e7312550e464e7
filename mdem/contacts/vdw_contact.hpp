#pragma once
// Pair kernels of the van der Waals contact between two tube elements (cylinders), built on the
// coarse-grained tube potential (tube_potential.hpp, docs/mdem-contacts.md).
//
// Anisotropic form: each element is its axis segment; the energy is
//   E = \int_{-la}^{la} ds [H(h(s), a(s)) - H(h(s), b(s))]
// where, for the point p(s) = x_a + s t_a, h is its distance from the axis line of b and
// [a, b] = [-lb - u0, lb - u0] the extent of segment b relative to the foot point (u0 the axial
// coordinate of p along b). The integral along b is exact (table H); along a it is a
// Gauss-Legendre rule. Crossed segments feel an aligning moment (the energy is lowest when
// aligned); a segment sliding along a straight chain of segments sees no corrugation, because the
// inner integrals of consecutive segments add up to the integral along the whole chain.
//
// Isotropic form: a central pair potential U(r) of the centre distance r, U(r) = the anisotropic
// energy of the two segments parallel and side by side at axis distance r (tabulated). No moment.
//
// Forces and torques are the exact negative gradients of these energies (world frame; a torque
// is -dE/dphi for a rotation q -> exp(phi) q of the element).
#include <vector>

#include "mdem/contacts/quadrature.hpp"
#include "mdem/contacts/tube_potential.hpp"
#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

struct Segment {
  Vec3 centre;
  Vec3 axis;  // unit
  double halfLength = 0.0;
};

struct ContactPairResult {
  double energy = 0.0;
  Vec3 forceA = Vec3::Zero(), torqueA = Vec3::Zero();
  Vec3 forceB = Vec3::Zero(), torqueB = Vec3::Zero();
};

// Anisotropic kernel; the quadrature runs along a (`rule` on [-1, 1]).
ContactPairResult anisotropicVdw(const TubePairPotential& potential, const QuadratureRule& rule,
                                 const Segment& a, const Segment& b);

// Isotropic kernel U(r), tabulated for one pair of element lengths.
class IsotropicVdw {
 public:
  IsotropicVdw(const TubePairPotential& potential, double halfLengthA, double halfLengthB);
  double energy(double r, double* derivative) const;
  ContactPairResult evaluate(const Vec3& centreA, const Vec3& centreB) const;
  double cutoff() const { return rMax_; }

 private:
  double step_ = 0.0, rMax_ = 0.0;
  std::vector<double> u_, du_;
};

}  // namespace mesochain::mdem
