#pragma once
// Viscous dashpot in parallel with a contact between two tube elements ("contact_damping").
//
// The dashpot acts at the contact point c (midpoint of the closest points of the two axis
// segments) on the relative velocity of the two elements there,
//   v_rel = (v_b + w_b x (c - x_b)) - (v_a + w_a x (c - x_a)),
//   F_a = gamma lambda s v_rel,  F_b = -F_a,
//   M_a = (c - x_a) x F_a + gamma_r lambda s (w_b - w_a),  M_b = (c - x_b) x F_b - gamma_r lambda s (w_b - w_a),
// with lambda the contact length (overlap of the two segments projected on each other's axis,
// averaged, plus (R_a + R_b)|sin(angle)| for a crossing) and s a smooth weight of the wall gap
// (1 below fullGap, 0 beyond cutoffGap). Forces are equal and opposite and act at one point, so
// linear and angular momentum are conserved; the power is -gamma lambda s |v_rel|^2 - ... <= 0.
// For aligned tubes in contact the friction force per unit length is exactly gamma v.
#include "mdem/contacts/contact_spec.hpp"
#include "mdem/contacts/vdw_contact.hpp"

namespace mesochain::mdem {

// Closest points of two segments: parameters sa in [-la, la], sb in [-lb, lb].
void closestPoints(const Segment& a, const Segment& b, double* sa, double* sb);
// Wall-to-wall gap of two tubes of radii ra, rb along the segments: the distance of the closest
// points of the axes minus both radii (negative: the walls interpenetrate).
double wallGap(const Segment& a, const Segment& b, double ra, double rb);

// Contact length lambda and weight s (see above).
double contactLength(const Segment& a, const Segment& b, double radiusA, double radiusB);

// Where and how strongly the dashpot acts: the contact point c and lambda s (zero beyond the
// cut-off gap: then the pair has no dashpot and its velocities need not be formed).
struct DashpotContact {
  Vec3 point = Vec3::Zero();
  double weightedLength = 0.0;  // lambda s, nm
};
DashpotContact dashpotContact(const ContactDampingSpec& spec, const Segment& a, const Segment& b, double radiusA,
                              double radiusB);
// The forces and torques of a contact with weightedLength > 0.
ContactPairResult dashpotForces(const ContactDampingSpec& spec, const DashpotContact& contact, const Segment& a,
                                const Segment& b, const Vec3& va, const Vec3& wa, const Vec3& vb, const Vec3& wb);

// Both in one call.
ContactPairResult contactDashpot(const ContactDampingSpec& spec, const Segment& a, const Segment& b,
                                 double radiusA, double radiusB, const Vec3& va, const Vec3& wa,
                                 const Vec3& vb, const Vec3& wb);

}  // namespace mesochain::mdem
