#pragma once
// Time integration of rigid elements (kernels on plain data).
//
// Translation: velocity Verlet (kick-drift-kick).
// Rotation: the symplectic splitting of Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107,
// 5840 (1997) ("DLM"), written on quaternions; it is the same scheme as NO_SQUISH of Miller et
// al., J. Chem. Phys. 116, 8649 (2002), in rotation-matrix rather than 4-momentum variables.
// The torque kicks the body-frame angular momentum pi; the free rotor
// H = sum_i pi_i^2 / (2 I_i) is split into three rotations about the principal axes, composed
// symmetrically  x(h/2) y(h/2) z(h) y(h/2) x(h/2).  The exact sub-flow of H_i over a time tau
// rotates pi by R_i(alpha)^T and the orientation by q <- q (x) exp(alpha e_i / 2), with
// alpha = tau pi_i / I_i (freeRotorStepExact: one sincos per sub-rotation).
//
// Rational (Cayley) sub-rotations (freeRotorStep, the default): each sub-rotation turns by
// phi = f(alpha) = 2 atan(alpha / 2) instead of alpha, so that with a = alpha / 2
//   cos phi = (1 - a^2) / (1 + a^2),  sin phi = 2 a / (1 + a^2),
//   q <- q (x) (1, a e_i)   (an unnormalised quaternion of the same rotation: tan(phi/2) = a),
// one division per sub-rotation and one normalisation of q per step, no transcendental call.
// Why this keeps every property of the exact splitting:
//  * A sub-step leaves pi_i unchanged and rotates about e_i by an angle that depends on pi_i
//    only. The flow of any Hamiltonian K(pi_i) is exactly such a rotation, at the constant
//    rate K'(pi_i) (pi_i Poisson-commutes with K). Rotating by f(tau pi_i / I_i) over tau is
//    therefore the exact tau-flow of K_tau(pi_i) = (I_i / tau^2) F(tau pi_i / I_i) with
//    F' = f, F(0) = 0; here F(x) = 2 x atan(x/2) - 2 ln(1 + x^2/4), so
//    K_tau = pi_i^2 / (2 I_i) - tau^2 pi_i^4 / (48 I_i^3) + O(tau^4): a modified Hamiltonian
//    that differs from H_i at O(tau^2). Each sub-step is an exact Hamiltonian flow, hence
//    symplectic (Lie-Poisson on the rigid body), and the composition is symplectic.
//  * f is odd, so the sub-step over -tau is the inverse of the one over tau (pi_i, and so the
//    angle, is the same before and after); the composition is symmetric, hence time
//    reversible and of even order. f(x) = x - x^3/12 + O(x^5): consistent, so second order,
//    like the exact splitting (the extra local error is O(h^3), the splitting's own order).
//  * Each sub-step rotates q by R_i(phi) and pi by R_i(phi)^T, so the world angular momentum
//    R(q) pi is unchanged in free flight for any phi: conserved exactly (up to round-off).
//  * Backward error analysis then bounds the energy error at O(h^2) over exponentially long
//    times, with no drift, as for the exact splitting (tests/mdem/test_rotor_integrator.cpp
//    compares both: convergence order, energy error over a long free-rotor run, momentum).
// Why DLM at all: it handles the full anisotropic inertia tensor (I_x != I_y != I_z for
// bricks), and keeps q a unit quaternion (we renormalise once per step).
#include <vector>

#include "mdem/body.hpp"

namespace mesochain::mdem {

// The kick's increments of element i over h: dv = (h / m) F, dL = h R(q)^T tau.
struct KickIncrement {
  Vec3 velocity, angularMomentumBody;
};
inline KickIncrement kickIncrement(const Bodies& s, int i, double h) {
  return {(h / s.mass[i]) * s.force[i], h * rotateInverse(s.orientation[i], s.torque[i])};
}
// v += h F / m, pi += h R^T tau for one element (and, kick below, for every element).
inline void kickElement(Bodies& s, int i, double h) {
  const KickIncrement d = kickIncrement(s, i, h);
  s.velocity[i] += d.velocity;
  s.angularMomentumBody[i] += d.angularMomentumBody;
}
// kickElement(s, i, h) twice with the increments formed once: v + dv + dv, L + dL + dL (the same
// rounding as two calls, since force, torque and orientation do not change between them);
// `between()` sees the element after the first (e.g. to record the velocities of that time).
template <class Between>
inline void kickElementTwice(Bodies& s, int i, double h, Between&& between) {
  const KickIncrement d = kickIncrement(s, i, h);
  s.velocity[i] += d.velocity;
  s.angularMomentumBody[i] += d.angularMomentumBody;
  between();
  s.velocity[i] += d.velocity;
  s.angularMomentumBody[i] += d.angularMomentumBody;
}
inline void kickElementTwice(Bodies& s, int i, double h) {
  kickElementTwice(s, i, h, [] {});
}
void kick(Bodies& s, double h);

// Free-rotor step of one body over h, DLM splitting with rational (Cayley) sub-rotations.
void freeRotorStep(Quat& q, Vec3& pi, const Vec3& inertia, double h);
// The same with the exact sub-rotations (one sincos each): the reference for tests.
void freeRotorStepExact(Quat& q, Vec3& pi, const Vec3& inertia, double h);

// x += h v; orientations by the free rotor, or, for elements whose rotation is kinematic
// (kinematicRotation[i] != 0), by q <- exp(h omega_world) q. Accumulates the rotation probe.
void driftElement(Bodies& s, int i, double h, bool kinematicRotation);
void drift(Bodies& s, double h, const std::vector<char>& kinematicRotation);
// driftElement(s, i, h, false) and driftElement(s, i + 1, h, false), bit for bit, with the two
// free-rotor chains interleaved (and packed into vector operations) so that their divisions overlap.
void driftFreePair(Bodies& s, int i, double h);

// Kinetic energies (zJ): translational 1/2 m v^2 and rotational 1/2 sum pi_i^2 / I_i.
double kineticTranslational(const Bodies& s);
double kineticRotational(const Bodies& s);

}  // namespace mesochain::mdem
