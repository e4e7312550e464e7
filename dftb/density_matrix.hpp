#pragma once
// The density and energy-weighted density matrices of one k-point from its occupied
// eigenvectors, with BLAS-3 products restricted to the orbital blocks the image pairs read, and
// their folding onto the image pairs.
//
// With C the S-orthonormal eigenvectors, f the occupations (0..2) and e the levels (Hartree),
//   rho   = sum_n f_n c_n c_n^+      = X X^+,   X = C_m diag(sqrt f),
//   rho^E = sum_n f_n e_n c_n c_n^+  = Y X^+,   Y = X diag(e),
// over the m columns of the states that carry charge (dftb/eigensolver.hpp:
// occupiedStateCount). Only the elements rho[(j,b),(i,a)] of atom pairs (i, j) with an image
// within the cutoff are read (about 9 % of the matrix for the (30,30) cell), so the atoms are
// cut into groups of consecutive atoms and only the group blocks that hold such a pair are
// formed, each by one general product (zgemm / dgemm, k = m): X_R X_C^+ and Y_R X_C^+ for row
// group R >= column group C; the blocks above are their adjoints. (The full lower triangles by
// Hermitian rank-m updates, zherk with the levels split by sign, cost 3-6 times the flops here
// and were slower than the former per-atom-pair products: docs/benchmarks.md.)
#include <complex>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "dftb/bloch.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/images.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::dftb {

template <class Scalar>
using MatrixMap = Eigen::Map<Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>>;

// Orbitals per group (about): large enough for BLAS-3 speed, small enough that the blocks
// follow the neighbour structure of a cell whose atoms are ordered along the tube.
inline constexpr int kDensityGroupOrbitals = 32;

// The group blocks formed for one geometry (the same at every k-point).
struct DensityBlockPlan {
  DensityBlockPlan() = default;
  // Groups of consecutive atoms of at least `groupOrbitals` orbitals (the last may be smaller);
  // the blocks (R, C), R >= C, of every image pair and every diagonal block (the on-site
  // density).
  DensityBlockPlan(const OrbitalLayout& layout, const objective::ImageList& images,
                   int groupOrbitals = kDensityGroupOrbitals);
  std::vector<int> groupStart;     // first orbital of each group, then the orbital count
  std::vector<int> groupOfOrbital;
  std::vector<std::pair<int, int>> blocks;  // (row group, column group), row >= column
  double fraction = 0;  // of the n^2 elements formed (for the benchmark notes)
};

// c: n x (at least m) eigenvector columns, overwritten with X; y: n x (at least m), receives Y.
// rho, rhoE: n x n, receive the plan's blocks (other elements are not written).
// Scalar = double (a k-point with real phases) or std::complex<double>.
template <class Scalar>
void formDensityMatrices(const DensityBlockPlan& plan, MatrixMap<Scalar> c, MatrixMap<Scalar> y,
                         int m, const Eigen::VectorXd& occupations, const Eigen::VectorXd& levels,
                         MatrixMap<Scalar> rho, MatrixMap<Scalar> rhoE);

// The contribution of one k-point with filling weight `weight` to every image pair p = (i, j, g)
// (see bloch.hpp): p[p]_ab = weight * Re(exp(i theta_g) rho[(j,b),(i,a)]), w[p] likewise from
// rhoE; assigned, not added. rho, rhoE as left by formDensityMatrices with the same plan (an
// element above the formed blocks is read as the conjugate of its mirror).
template <class Scalar>
void foldDensityBlocks(const DensityBlockPlan& plan, const OrbitalLayout& layout,
                       const objective::ImageList& images, const objective::HelicalKGrid& grid,
                       const objective::HelicalKPoint& k, double weight,
                       const MatrixMap<Scalar>& rho, const MatrixMap<Scalar>& rhoE,
                       std::vector<OrbitalBlock>& p, std::vector<OrbitalBlock>& w);

}  // namespace mesochain::dftb
