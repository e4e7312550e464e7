#pragma once
// Linear parallel bond between two rigid elements (Potyondy & Cundall, Int. J. Rock Mech. Min.
// Sci. 41, 1329 (2004), section 2.2), written in a total, energy-based form.
//
// P&C give the increments dF_n = -k_n A dU_n, dF_s = -k_s A dU_s, dM_t = -k_s J dtheta_t,
// dM_b = -k_n I dtheta_b. Summed over a path these are the derivatives of the energy
//   E = 1/2 k_n A d_z^2                 (stretching)
//     + 1/2 k_s A (d_x^2 + d_y^2)       (shearing)
//     + 1/2 k_s J theta_z^2             (twisting)
//     + 1/2 k_n (I_x theta_x^2 + I_y theta_y^2)   (bending, anisotropic: I_x != I_y kept)
// where, in the bond frame attached to element a (z = bond normal at creation),
//   d     = R_a'^T (p_b - p_a)                     relative displacement of the anchor points,
//   theta = log(R_a'^T R_b')                       relative rotation vector of the bond frames.
// Forces and torques are the exact derivatives of E (see parallel_bond.cpp), so the bond is
// exactly conservative and conserves linear and angular momentum. theta is followed on a
// tracked branch of the log (quaternion.hpp, trackedLog) so that a bond can twist through
// several turns without wrapping. The "stored shear force and bending moment carried along as
// the bond plane turns" of the incremental scheme are here implicit: they are functions of the
// current relative configuration expressed in the (rotating) bond frame.
//
// Units: k_n, k_s in MPa/nm (= pN/nm^3); A nm^2; I, J nm^4; forces pN; moments and energies zJ.
#include <array>

#include <Eigen/Dense>

#include "mdem/body.hpp"

namespace mesochain::mdem {

// Cross-section of a bond in its own frame (x, y in the bond plane, z along the normal).
struct BondSection {
  double area = 0.0;  // A
  double ix = 0.0;    // I_x = ∫ y^2 dA (bending about the bond x axis)
  double iy = 0.0;    // I_y = ∫ x^2 dA
  double j = 0.0;     // polar moment J = I_x + I_y (as in P&C's parallel bond)

  // Rectangle of extent `along x` by `along y`: A = a b, I_x = a b^3/12, I_y = b a^3/12.
  static BondSection rectangle(double alongX, double alongY);
  // Disc of radius r: A = pi r^2, I_x = I_y = pi r^4/4, J = pi r^4/2.
  static BondSection disc(double r);
};

struct BondStiffness {
  double kn = 0.0;  // normal stiffness per unit area, MPa/nm
  double ks = 0.0;  // shear stiffness per unit area, MPa/nm
};

struct Bond {
  int a = -1, b = -1;
  BondStiffness k;
  BondSection section;
  Vec3 anchorA = Vec3::Zero();  // anchor point in the body frame of a (nm)
  Vec3 anchorB = Vec3::Zero();  // anchor point in the body frame of b
  Quat frameA;                  // bond frame relative to body a
  Quat frameB;                  // bond frame relative to body b (coincides with a's at creation)
  Vec3 theta = Vec3::Zero();    // tracked relative rotation vector (branch memory)
  double restLength = 0.0;      // distance between the centres at creation (nm)
  // Derived by makeBond: a's anchor in the bond frame of a, R(frameA)^T anchorA (constant).
  Vec3 anchorAInBondFrame = Vec3::Zero();
};

// What a bond carries, for outputs (bond frame of a): normal force k_n A d_z (pN, tension > 0),
// shear force k_s A |d_xy| (pN), bending moment k_n |(I_x theta_x, I_y theta_y)| and twisting
// moment k_s J |theta_z| (pN nm).
struct BondLoad {
  double normalForce = 0.0, shearForce = 0.0, bendingMoment = 0.0, twistingMoment = 0.0;
};
BondLoad bondLoad(const Bond& bond, const Vec3& d, const Vec3& theta);

// Energies of one bond (zJ).
struct BondEnergy {
  double stretching = 0.0, shearing = 0.0, twisting = 0.0, bending = 0.0;
  double total() const { return stretching + shearing + twisting + bending; }
  BondEnergy& operator+=(const BondEnergy& o) {
    stretching += o.stretching, shearing += o.shearing, twisting += o.twisting,
        bending += o.bending;
    return *this;
  }
};

// Forces (pN) and torques (pN nm) on a and b, world frame, and the bond's relative coordinates.
struct BondResult {
  Vec3 forceA, torqueA, forceB, torqueB;
  Vec3 d;      // relative displacement in the bond frame
  Vec3 theta;  // relative rotation vector in the bond frame
  BondEnergy energy;
};

// Creates a bond between two elements in their current configuration (taken as the rest
// state): anchors at the midpoint of the centres, bond z along x_b - x_a, bond x along the
// projection of a's body x axis (thickness direction of a brick).
Bond makeBond(int a, int b, const Bodies& bodies, const BondStiffness& k, const BondSection& s);

// The kernel: forces, torques and energies of one bond. bond.theta selects the branch.
BondResult evaluateBond(const Bond& bond, const Vec3& xa, const Quat& qa, const Vec3& xb,
                        const Quat& qb);

// Forces (pN), torques (pN nm) and the relative rotation vector of one bond, without energies.
struct BondForces {
  Vec3 forceA, torqueA, forceB, torqueB;
  Vec3 theta;
};

// The time-stepping kernel: the same forces and torques as evaluateBond (the exact derivatives
// of its energy), computed with the bond frame of a as one matrix, no anchor rotation for a
// (d = R_a'^T (x_b + s_b - x_a) - R(frameA)^T anchorA), and one log whose small-angle branch
// has no transcendental call (quaternion.hpp, trackedLogWithJacobian).
BondForces bondForces(const Bond& bond, const Vec3& xa, const Quat& qa, const Vec3& xb,
                      const Quat& qb);

// Two bonds at once (their elements' positions and orientations from s): each result bit for bit
// that of bondForces, the two computed lane by lane so that their arithmetic shares two-wide
// vector operations.
void bondForcesPair(const Bond& b0, const Bond& b1, const Bodies& s, BondForces& r0, BondForces& r1);

// Stiffness matrix (12 x 12, world frame, DOF order u_a, phi_a, u_b, phi_b with phi small
// world-frame rotations) of the bond linearised about its rest state in the current
// orientation of a: K = B^T D B with d = (u_b + phi_b x s_b) - (u_a + phi_a x s_a),
// theta = phi_b - phi_a, both in the bond frame, D = diag(k_s A, k_s A, k_n A, k_n I_x,
// k_n I_y, k_s J). Independent of evaluateBond (used for time-step bounds and normal modes).
Eigen::Matrix<double, 12, 12> linearStiffness(const Bond& bond, const Bodies& bodies);

}  // namespace mesochain::mdem
