#pragma once
// Generalized eigenproblem H c = e S c (complex Hermitian or real symmetric), split into the
// steps LAPACK's zhegvd performs so that each can be reused or skipped:
//   S = L L^H (potrf, or a factor kept from an earlier solve of the same geometry),
//   A = L^-1 H L^-H (hegst), then either
//   * all eigenpairs of A by divide and conquer (heevd) and C = L^-H Y  [AllVectors], or
//   * A = Q T Q^H (hetrd), the eigenvalues of T (dsterf) now, and later, once the Fermi level
//     fixes how many states carry charge (m), the eigenvectors Z of T by divide and conquer
//     (dstedc, O(n^2) with deflation) and the two O(n^2 m) back-transformations on those m
//     columns only: Y = Q Z_m (unmtr), C = L^-H Y (trsm) [OccupiedOnly]. MRRR for the index
//     range 1..m (stemr) was tried first: on a cell without its rotation every level with
//     mu != 0 is twofold degenerate, and its bisection spent more time refining those
//     clusters (dlaneg, 36 % of the 120-atom run) than the vectors it skipped.
// A workspace object holds every buffer, sized once with the optimal lengths LAPACK's own
// workspace queries report (so that unmtr/unmqr take their blocked BLAS-3 path), and the k-point
// loop allocates nothing.
#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace mesochain::dftb {

using ComplexMatrix = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic>;

enum class EigenvectorPath {
  Automatic,     // OccupiedOnly from kOccupiedOnlyMinimumOrder orbitals on, AllVectors below
  AllVectors,    // divide and conquer for all n eigenpairs
  OccupiedOnly,  // tridiagonal form kept; the m lowest eigenvectors only
};
// Measured on the project's machine (docs/benchmarks.md, `bench dftb`): below this order the
// extra LAPACK calls of the two-pass path cost more than the vectors it skips.
inline constexpr int kOccupiedOnlyMinimumOrder = 64;
EigenvectorPath resolveEigenvectorPath(EigenvectorPath requested, int n);

// What one k-point keeps between the two passes. `a` holds H(k) on entry to reduce(); on
// return: with AllVectors the S-orthonormal eigenvectors (columns); with OccupiedOnly the
// reflectors of Q below the subdiagonal and L^H in the upper triangle and on the diagonal
// (tau, diagonal, offDiagonal: the rest of Q and T). With values only, `a` is overwritten.
template <class Scalar>
struct ReducedProblem {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> a;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> tau;
  Eigen::VectorXd diagonal, offDiagonal;
  void resize(int n);
};

// The number of states whose vectors enter the density: every level with an occupation above
// `threshold` (levels ascending, occupations 0..2), extended over levels degenerate with the
// last one within `degeneracy` (Hartree) so that a cut never splits a degenerate multiplet.
inline constexpr double kOccupationThreshold = 1e-15;
inline constexpr double kDegeneracyTolerance = 1e-8;
int occupiedStateCount(const Eigen::VectorXd& levels, const Eigen::VectorXd& occupations,
                       double threshold = kOccupationThreshold,
                       double degeneracy = kDegeneracyTolerance);

class GeneralizedEigensolver {
 public:
  enum class Mode { ValuesOnly, AllVectors, OccupiedOnly };

  explicit GeneralizedEigensolver(int n = 0) { resize(n); }
  void resize(int n);
  int size() const { return n_; }

  // Pass 1. p.a holds H(k) (lower triangle), s holds S(k) (lower triangle). Without `factor`,
  // s receives the Cholesky factor L in its lower triangle; with `factor` (L of the same S(k)
  // from an earlier solve), s is not referenced. e receives the n ascending eigenvalues.
  // Throws NumericalError naming `context` when S is not positive definite or LAPACK fails.
  template <class Scalar>
  void reduce(ReducedProblem<Scalar>& p,
              Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& s,
              const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>* factor,
              Eigen::VectorXd& e, Mode mode, const char* context);

  // Pass 2 after reduce(.., OccupiedOnly): the m lowest S-orthonormal eigenvectors into the
  // first m columns of c (n rows; c is not resized).
  template <class Scalar>
  void lowestVectors(ReducedProblem<Scalar>& p, int m,
                     Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& c,
                     const char* context);

  // Workspace lengths given to LAPACK (complex, real, integer), for the workspace test.
  int complexWorkLength() const { return static_cast<int>(zwork_.size()); }
  int realWorkLength() const { return static_cast<int>(dwork_.size()); }
  int integerWorkLength() const { return static_cast<int>(iwork_.size()); }

 private:
  int n_ = 0;
  std::vector<std::complex<double>> zwork_;
  std::vector<double> dwork_;  // real work of the real routines and rwork of the complex ones
  std::vector<double> dcopy_;  // 2n: the tridiagonal for dsterf / stedc (overwritten)
  std::vector<double> z_;      // n^2: the eigenvectors of T
  std::vector<int> iwork_;
};

}  // namespace mesochain::dftb
