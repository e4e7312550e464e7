#pragma once
// Slater-Koster two-centre rotation for s and p orbitals (J. C. Slater and G. F. Koster,
// Phys. Rev. 94, 1498 (1954), Table I), with analytic derivatives.
//
// For d = x_B - x_A, r = |d|, e = d / r = (l, m, n), orbitals ordered s, p_x, p_y, p_z:
//   <s_A | s_B>     = V_ss
//   <s_A | p_B,a>   =  e_a V_sp            (V_sp: s on A, p on B)
//   <p_A,a | s_B>   = -e_a V_ps            (V_ps: s on B, p on A, i.e. p_A lies along -e seen
//                                           from B; the sign is the parity (-1)^(l_A + l_B))
//   <p_A,a | p_B,b> = e_a e_b (V_pps - V_ppp) + delta_ab V_ppp
// Derivatives with respect to d_c, from dr/dd_c = e_c and de_a/dd_c = (delta_ac - e_a e_c)/r:
//   d(e_a V)/dd_c     = (delta_ac - e_a e_c) V / r + e_a e_c V'
//   d(e_a e_b W)/dd_c = [(delta_ac - e_a e_c) e_b + e_a (delta_bc - e_b e_c)] W / r
//                       + e_a e_b e_c W'
// These are regular for every direction (no polar angles are used), r > 0.
#include <Eigen/Dense>

#include "dftb/parameters.hpp"

namespace mesochain::dftb {

// Radial Slater-Koster integrals at one distance.
struct SkRadial {
  double ss = 0.0, sp = 0.0, ps = 0.0, ppSigma = 0.0, ppPi = 0.0;
};

// Block (top-left nA x nB; the rest zero). nA, nB are 1 (s) or 4 (s, p).
void skBlock(const Eigen::Vector3d& d, const SkRadial& v, int nA, int nB, OrbitalBlock& block);

// Block and its derivatives with respect to d_x, d_y, d_z; dv holds dV/dr of each integral.
void skBlockWithDerivatives(const Eigen::Vector3d& d, const SkRadial& v, const SkRadial& dv,
                            int nA, int nB, OrbitalBlock& block, OrbitalBlock dblock[3]);

}  // namespace mesochain::dftb
