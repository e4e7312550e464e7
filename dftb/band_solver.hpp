#pragma once
// One band-structure solve on an objective cell: Bloch assembly from real-space blocks, the
// generalized eigenproblem at every helical k-point (OpenMP over k), Fermi-Dirac filling with
// one Fermi level, and (on request) the density and energy-weighted density folded onto the
// image pairs plus the on-site diagonal of the density (for Mulliken populations).
// Shared by the non-SCC band term (one solve) and the SCC term (one solve per iteration, with
// the charge-dependent shift added to the blocks and the on-site energies).
#include <vector>

#include <Eigen/Dense>

#include "dftb/bloch.hpp"
#include "dftb/fermi.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/images.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::dftb {

// Everything that depends on the geometry only: orbitals, image pairs within the integral
// cutoff, k-points, the real-space blocks h^p (H0) and s^p, and the valence electron count.
struct BandGeometry {
  BandGeometry(const objective::ObjectiveCell& cell, const ParameterSet& params, int nKappa,
               objective::AngularSampling angular);
  OrbitalLayout layout;
  objective::ImageList images;
  objective::HelicalKGrid grid;
  std::vector<OrbitalBlock> h0, s;
  double electrons = 0.0;  // sum of the neutral atoms' valence occupations
};

struct BandSolution {
  std::vector<Eigen::VectorXd> levels;  // per k-point, ascending
  std::vector<double> weights;          // per k-point
  Filling filling;
  // With density only: P^p and W^p per image pair (see bloch.hpp) and the on-site diagonal
  // rho_{mu mu} = sum_k w_k sum_n f_nk |c_{mu n}(k)|^2 per orbital.
  std::vector<OrbitalBlock> p, w;
  Eigen::VectorXd onsiteDensity;
  // Wall-clock seconds.
  double timeAssembly = 0, timeEigensolver = 0, timeFilling = 0, timeDensity = 0;
};

// h: the real-space H blocks per image pair (H0, or H0 plus an SCC shift); onsiteShift: empty,
// or one energy per cell atom added to its on-site diagonal (Hartree). kT > 0 (Hartree).
BandSolution solveBands(const objective::ObjectiveCell& cell, const ParameterSet& params,
                        const BandGeometry& geometry, const std::vector<OrbitalBlock>& h,
                        const Eigen::VectorXd& onsiteShift, double kT, bool density);

}  // namespace mesochain::dftb
