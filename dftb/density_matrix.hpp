#pragma once
// The density and energy-weighted density matrices of one k-point from its occupied
// eigenvectors, with BLAS-3 rank-m updates, and their folding onto the image pairs.
//
// With C the S-orthonormal eigenvectors, f the occupations (0..2) and e the levels (Hartree),
//   rho   = sum_n f_n c_n c_n^+            = X X^+,            X = C_m diag(sqrt f)
//   rho^E = sum_n f_n e_n c_n c_n^+        = X_+ X_+^+ - X_- X_-^+,
// where X_+- are the columns of X diag(sqrt|e|) with e >= 0 resp. e < 0 (the levels ascend, so
// the negative ones are the first columns): sqrt(f e) does not exist for e < 0, and splitting
// by sign keeps both products Hermitian rank-k updates (zherk / dsyrk: n^2 m / 2 multiply-adds
// each, half of a general product). Only the m columns of the states that carry charge enter
// (dftb/eigensolver.hpp: occupiedStateCount).
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "dftb/bloch.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/images.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::dftb {

template <class Scalar>
using MatrixMap = Eigen::Map<Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>>;

// c: n x (at least m) eigenvector columns, overwritten (scaled). rho, rhoE: n x n, their lower
// triangles (with the diagonal) receive the matrices; the strict upper triangles are not
// written. Scalar = double (a k-point with real phases) or std::complex<double>.
template <class Scalar>
void formDensityMatrices(MatrixMap<Scalar> c, int m, const Eigen::VectorXd& occupations,
                         const Eigen::VectorXd& levels, MatrixMap<Scalar> rho,
                         MatrixMap<Scalar> rhoE);

// The contribution of one k-point with filling weight `weight` to every image pair p = (i, j, g)
// (see bloch.hpp): p[p]_ab = weight * Re(exp(i theta_g) rho[(j,b),(i,a)]), w[p] likewise from
// rhoE; assigned, not added. rho, rhoE as left by formDensityMatrices (lower triangles; the upper
// elements are read as the conjugates of the lower ones).
template <class Scalar>
void foldDensityBlocks(const OrbitalLayout& layout, const objective::ImageList& images,
                       const objective::HelicalKGrid& grid, const objective::HelicalKPoint& k,
                       double weight, const MatrixMap<Scalar>& rho, const MatrixMap<Scalar>& rhoE,
                       std::vector<OrbitalBlock>& p, std::vector<OrbitalBlock>& w);

}  // namespace mesochain::dftb
