#pragma once
// Mulliken populations of the cell atoms of an objective structure, summed over k-points and
// images (Mulliken, J. Chem. Phys. 23, 1833 (1955)):
//   q_i = sum_{mu in i} sum_nu sum_g Re[rho_{mu nu}(g) S_{nu mu}(g)]
//       = sum_{a in i} rho_{aa}(e) + sum_{p = (i, j, g)} sum_ab P^p_ab s^p_ab,
// with the on-site overlap the identity, P^p the density blocks folded onto the image pairs and
// s^p the overlap blocks (dftb/bloch.hpp). Both (i, j, g) and (j, i, g^-1) are in the pair
// list, so the overlap population of a bond is split equally between its atoms.
#include <vector>

#include <Eigen/Dense>

#include "dftb/bloch.hpp"
#include "objective/core/images.hpp"

namespace mesochain::dftb {

// Electrons per cell atom; onsiteDensity: rho_{aa}(e) per orbital.
Eigen::VectorXd mullikenPopulations(const OrbitalLayout& layout,
                                    const objective::ImageList& images,
                                    const Eigen::VectorXd& onsiteDensity,
                                    const std::vector<OrbitalBlock>& p,
                                    const std::vector<OrbitalBlock>& s);

}  // namespace mesochain::dftb
