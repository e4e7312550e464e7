#pragma once
// Critical time step of the explicit integrator, from the bond stiffness against the mass and
// the principal moments of inertia.
//
// Velocity Verlet is stable for a linear system when h < 2 / omega_max, omega_max^2 the largest
// eigenvalue of M^{-1} K. We bound omega_max^2 from above, rigorously, by Gershgorin's theorem
// applied to M^{-1/2} K M^{-1/2}, with K the bonds' linearised stiffness (parallel_bond.hpp,
// linearStiffness) written in each element's principal frame so that M is diagonal
// (m, m, m, I_1, I_2, I_3): omega_max^2 <= max_i sum_j |K_ij| / sqrt(M_ii M_jj).
// DOFs of elements that are completely constrained (all six fixed, or prescribed) are left
// out. The returned step is therefore never above the true stability limit; for a uniform
// chain it is within a factor of about 2 of it.
#include <vector>

#include "mdem/boundary.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

struct StabilityLimit {
  double criticalTimeStep = 0.0;  // ns, 2 / omega_max (infinite without bonds)
  double omegaMax = 0.0;          // rad/ns, the Gershgorin bound
  int element = -1;               // element whose row gives the bound
  bool rotational = false;        // whether that row is a rotational DOF
};

StabilityLimit criticalTimeStep(const Bodies& bodies, const std::vector<Bond>& bonds,
                                const KinematicMap& kinematics);

}  // namespace mesochain::mdem
