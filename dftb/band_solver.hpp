#pragma once
// One band-structure solve on an objective cell: Bloch assembly from real-space blocks, the
// generalized eigenproblem at every helical k-point (OpenMP over k), Fermi-Dirac filling with
// one Fermi level, and (on request) the density and energy-weighted density folded onto the
// image pairs plus the on-site diagonal of the density (for Mulliken populations).
// Shared by the non-SCC band term (one solve) and the SCC term (one solve per iteration, with
// the charge-dependent shift added to the blocks and the on-site energies).
//
// Over MPI ranks (parallel/communicator.hpp): every rank assembles and solves the k-points it
// owns (parallel/work_split.hpp, a complex-phase point costed as four real ones), the
// eigenvalues are gathered so that every rank fills the same levels with the same Fermi level,
// and the density blocks are summed exactly (parallel/exact_sum.hpp): the results are the same
// bits for any number of ranks and threads. A failure at a k-point on any rank is the same
// NumericalError on every rank.
#include <vector>

#include <Eigen/Dense>

#include "dftb/bloch.hpp"
#include "dftb/fermi.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/images.hpp"
#include "parallel/communicator.hpp"
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

// The Cholesky factors L(k) of S(k) = L L^H at every k-point of one geometry, filled by the first
// solveBands() that receives them and reused by every later one on the same geometry: S does
// not depend on the charges, so the SCC iterations skip potrf. Kept only when they fit in
// `byteBudget` (n^2 scalars per k-point; a large ring with thousands of angular points would
// not), otherwise `kept` is false and every solve factors S itself. Storage is allocated here,
// never in the k loop, and only for the k-points this rank of `comm` owns (the same split as
// solveBands with that communicator).
struct OverlapFactors {
  explicit OverlapFactors(const BandGeometry& geometry,
                          double byteBudget = 1024.0 * 1024.0 * 1024.0,
                          const parallel::Communicator& comm = parallel::Communicator::serial());
  bool kept = false;
  double bytes = 0;
  std::vector<ComplexMatrix> complex;  // per k-point with complex phases
  std::vector<Eigen::MatrixXd> real;   // per k-point with real phases
  std::vector<char> ready;             // per k-point: the factor holds L(k)
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
  // timeEigensolver: every LAPACK step (both passes of the OccupiedOnly path); timeDensity:
  // the density matrices and their blocks (dftb/density_matrix.hpp), of which
  // timeDensityProducts is the BLAS-3 products (zherk / dsyrk) alone.
  double timeAssembly = 0, timeEigensolver = 0, timeFilling = 0, timeDensity = 0;
  double timeDensityProducts = 0;
  EigenvectorPath path = EigenvectorPath::AllVectors;  // the one taken (density only)
  std::vector<int> statesUsed;  // per k-point: eigenvectors entering the density (density only)
};

// h: the real-space H blocks per image pair (H0, or H0 plus an SCC shift); onsiteShift: empty,
// or one energy per cell atom added to its on-site diagonal (Hartree). kT > 0 (Hartree).
// path: how the eigenvectors are computed (the results agree to rounding; see eigensolver.hpp);
// factors: Cholesky factors of S(k) kept across solves of this geometry (or none); comm: the
// ranks that share the k-points (collective over them; every rank gets the whole solution);
// occupationThreshold: the occupation above which a state's vector enters the density
// (occupiedStateCount in eigensolver.hpp; a parameter for the tests of the cut).
BandSolution solveBands(const objective::ObjectiveCell& cell, const ParameterSet& params,
                        const BandGeometry& geometry, const std::vector<OrbitalBlock>& h,
                        const Eigen::VectorXd& onsiteShift, double kT, bool density,
                        EigenvectorPath path = EigenvectorPath::Automatic,
                        OverlapFactors* factors = nullptr,
                        const parallel::Communicator& comm = parallel::Communicator::serial(),
                        double occupationThreshold = kOccupationThreshold);

// The rank of `comm` that solves each k-point of `grid` (the same on every rank).
std::vector<int> kpointOwners(const objective::HelicalKGrid& grid,
                              const parallel::Communicator& comm);

}  // namespace mesochain::dftb
