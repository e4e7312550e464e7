#pragma once
// Time integration of rigid elements (kernels on plain data).
//
// Translation: velocity Verlet (kick-drift-kick).
// Rotation: the symplectic splitting of Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107,
// 5840 (1997) ("DLM"), written on quaternions; it is the same scheme as NO_SQUISH of Miller et
// al., J. Chem. Phys. 116, 8649 (2002), in rotation-matrix rather than 4-momentum variables.
// The torque kicks the body-frame angular momentum pi; the free rotor
// H = sum_i pi_i^2 / (2 I_i) is split into three exactly solvable rotations about the principal
// axes, composed symmetrically  x(h/2) y(h/2) z(h) y(h/2) x(h/2).  Each sub-flow rotates pi by
// R_i(alpha)^T and the orientation by q <- q (x) exp(alpha e_i / 2), alpha = h pi_i / I_i.
// Why: it handles the full anisotropic inertia tensor (I_x != I_y != I_z for bricks), is
// symplectic and time reversible (bounded energy error over long runs, no drift), conserves
// the world angular momentum R pi exactly in the free flight, and keeps q a unit quaternion
// because it only multiplies unit quaternions (we still renormalise against round-off).
#include <vector>

#include "mdem/body.hpp"

namespace mesochain::mdem {

// v += h F / m, pi += h R^T tau for one element and for every element.
inline void kickElement(Bodies& s, int i, double h) {
  s.velocity[i] += (h / s.mass[i]) * s.force[i];
  s.angularMomentumBody[i] += h * rotateInverse(s.orientation[i], s.torque[i]);
}
void kick(Bodies& s, double h);

// Exact-splitting free-rotor step of one body over h.
void freeRotorStep(Quat& q, Vec3& pi, const Vec3& inertia, double h);

// x += h v; orientations by the free rotor, or, for elements whose rotation is kinematic
// (kinematicRotation[i] != 0), by q <- exp(h omega_world) q. Accumulates the rotation probe.
void driftElement(Bodies& s, int i, double h, bool kinematicRotation);
void drift(Bodies& s, double h, const std::vector<char>& kinematicRotation);

// Kinetic energies (zJ): translational 1/2 m v^2 and rotational 1/2 sum pi_i^2 / I_i.
double kineticTranslational(const Bodies& s);
double kineticRotational(const Bodies& s);

}  // namespace mesochain::mdem
