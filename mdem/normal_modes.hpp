#pragma once
// Small-vibration analysis of a bonded assembly about its current (rest) state: the global
// stiffness matrix from the bonds' linearised stiffness (parallel_bond.hpp) and the rigid-body
// mass matrix (m I for translations, R diag(I) R^T for rotations), both 6N x 6N, world frame,
// DOF order per element (u_x, u_y, u_z, phi_x, phi_y, phi_z). Dense: for checks and small
// chains (a few hundred elements).
#include <vector>

#include <Eigen/Dense>

#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

Eigen::MatrixXd assembleStiffness(const Bodies& bodies, const std::vector<Bond>& bonds);
Eigen::MatrixXd assembleMass(const Bodies& bodies);

// Angular eigenfrequencies omega (rad/ns, ascending) of K v = omega^2 M v restricted to the
// DOFs whose flag in `freeDofs` (size 6N) is true.
Eigen::VectorXd eigenfrequencies(const Bodies& bodies, const std::vector<Bond>& bonds,
                                 const std::vector<bool>& freeDofs);

}  // namespace mesochain::mdem
