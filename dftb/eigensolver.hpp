#pragma once
// Generalized eigenproblem H c = e S c through LAPACK's divide-and-conquer drivers
// (zhegvd for complex Hermitian, dsygvd for real symmetric). A workspace object holds every
// buffer, sized once, so that a k-point loop allocates nothing.
#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace mesochain::dftb {

using ComplexMatrix = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic>;

class GeneralizedEigensolver {
 public:
  explicit GeneralizedEigensolver(int n = 0) { resize(n); }
  void resize(int n);
  int size() const { return n_; }

  // Solves in place: e receives the ascending eigenvalues; with `vectors` h holds the
  // eigenvectors on return (columns, S-orthonormal), otherwise h is overwritten (LAPACK skips
  // the back-transformation). s is overwritten. Throws NumericalError naming `context` when S is
  // not positive definite (near-singular overlap) or LAPACK fails.
  void solveComplex(ComplexMatrix& h, ComplexMatrix& s, Eigen::VectorXd& e, bool vectors,
                    const char* context);
  void solveReal(Eigen::MatrixXd& h, Eigen::MatrixXd& s, Eigen::VectorXd& e, bool vectors,
                 const char* context);

 private:
  int n_ = 0;
  std::vector<std::complex<double>> zwork_;
  std::vector<double> rwork_;
  std::vector<double> dwork_;
  std::vector<int> iwork_;
};

}  // namespace mesochain::dftb
