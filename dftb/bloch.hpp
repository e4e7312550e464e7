#pragma once
// Kernels of the band-structure term on an objective cell, free functions on plain arrays.
//
// Real-space blocks: for image pair p = (i, j, g) with d = g(x_j) - x_i the block of cell atom
// i with the image g of cell atom j is  h^p = B_ij(d) D(g),  where B is the Slater-Koster
// two-centre block in the global frame and D(g) = diag(1, R(g)) rotates the p orbitals of the
// image (an image orbital is the cell orbital carried by g; its rotation comes from the group
// element, never from positions). Bloch sums (helical Bloch theorem, e.g. White, Robertson &
// Mintmire, Phys. Rev. B 47, 5485 (1993); Dumitrica & James (2007)):
//   H_{i a, j b}(k) = sum_{p = (i,j,g)} exp(i theta_g(k)) h^p_{ab}  (+ on-site energies),
// and likewise S. With rho_k = sum_n f_n c_n c_n^+ the band energy per cell is
//   E = sum_p sum_ab h^p_ab P^p_ab,  P^p_ab = Re sum_k w_k exp(i theta_g) rho_k[(j,b),(i,a)],
// and the gradient of the Mermin free energy follows from dh^p, ds^p contracted with P and
// the energy-weighted W (Hellmann-Feynman with Pulay term; fixed Fermi-Dirac occupations).
#include <vector>

#include <Eigen/Dense>

#include "dftb/eigensolver.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/images.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::dftb {

// Orbital offsets of the cell atoms in the Bloch matrices.
struct OrbitalLayout {
  std::vector<int> offset;  // per atom
  std::vector<int> count;   // per atom, 1 or 4
  int total = 0;
  OrbitalLayout(const objective::ObjectiveCell& cell, const ParameterSet& params);
};

// D(g) = diag(1, R) for an orbital block (s, p_x, p_y, p_z).
OrbitalBlock orbitalRotation(const Eigen::Matrix3d& r);

// The real-space blocks h^p, s^p for every pair of `images`.
void computeRealSpaceBlocks(const objective::ObjectiveCell& cell, const ParameterSet& params,
                            const objective::ImageList& images, std::vector<OrbitalBlock>& h,
                            std::vector<OrbitalBlock>& s);

// Assembles the lower triangle (and diagonal blocks in full) of H(k), S(k). Pairs that fall in
// the strict upper triangle are skipped: LAPACK reads the lower triangle only. onsiteShift:
// empty, or one energy per cell atom added to the diagonal of its orbitals (SCC shift V_i).
void assembleBloch(const objective::ObjectiveCell& cell, const ParameterSet& params,
                   const OrbitalLayout& layout, const objective::ImageList& images,
                   const std::vector<OrbitalBlock>& h, const std::vector<OrbitalBlock>& s,
                   const objective::HelicalKGrid& grid, const objective::HelicalKPoint& k,
                   ComplexMatrix& hk, ComplexMatrix& sk,
                   const Eigen::VectorXd& onsiteShift = Eigen::VectorXd());
// The same for a k-point whose phases are all real (+-1).
void assembleBlochReal(const objective::ObjectiveCell& cell, const ParameterSet& params,
                       const OrbitalLayout& layout, const objective::ImageList& images,
                       const std::vector<OrbitalBlock>& h, const std::vector<OrbitalBlock>& s,
                       const objective::HelicalKGrid& grid, const objective::HelicalKPoint& k,
                       Eigen::MatrixXd& hk, Eigen::MatrixXd& sk,
                       const Eigen::VectorXd& onsiteShift = Eigen::VectorXd());

// The density and energy-weighted density P^p, W^p of one k-point are formed and folded onto
// the image pairs in dftb/density_matrix.hpp.

// Contracts derivative blocks with P and W: gradient (3 x N_o), dE/dT, dE/dgamma.
struct BandDerivatives {
  Eigen::Matrix3Xd gradient;
  double dEdTranslation = 0.0;
  double dEdTwist = 0.0;
};
BandDerivatives contractDerivatives(const objective::ObjectiveCell& cell,
                                    const ParameterSet& params, const objective::ImageList& images,
                                    const std::vector<OrbitalBlock>& p,
                                    const std::vector<OrbitalBlock>& w, bool strain);

}  // namespace mesochain::dftb
