#include "dftb/eigensolver.hpp"

#include <string>

#include "common/errors.hpp"

extern "C" {
void zhegvd_(const int* itype, const char* jobz, const char* uplo, const int* n,
             std::complex<double>* a, const int* lda, std::complex<double>* b, const int* ldb,
             double* w, std::complex<double>* work, const int* lwork, double* rwork,
             const int* lrwork, int* iwork, const int* liwork, int* info);
void dsygvd_(const int* itype, const char* jobz, const char* uplo, const int* n, double* a,
             const int* lda, double* b, const int* ldb, double* w, double* work,
             const int* lwork, int* iwork, const int* liwork, int* info);
}

namespace mesochain::dftb {

void GeneralizedEigensolver::resize(int n) {
  n_ = n;
  if (n <= 0) return;
  // Workspace sizes for JOBZ = 'V' as documented for zhegvd / dsygvd (enough for 'N' too).
  zwork_.resize(static_cast<size_t>(2 * n + n * n));
  rwork_.resize(static_cast<size_t>(1 + 5 * n + 2 * n * n));
  dwork_.resize(static_cast<size_t>(1 + 6 * n + 2 * n * n));
  iwork_.resize(static_cast<size_t>(3 + 5 * n));
}

namespace {
void check(int info, int n, const char* context) {
  if (info == 0) return;
  if (info > n)
    throw NumericalError(std::string(context) +
                         ": the overlap matrix is not positive definite (leading minor " +
                         std::to_string(info - n) +
                         "): atoms too close, or a near-singular (linearly dependent) basis");
  throw NumericalError(std::string(context) + ": LAPACK eigensolver failed (info " +
                       std::to_string(info) + ")");
}
}  // namespace

void GeneralizedEigensolver::solveComplex(ComplexMatrix& h, ComplexMatrix& s, Eigen::VectorXd& e,
                                          bool vectors, const char* context) {
  const int n = static_cast<int>(h.rows());
  if (n != n_) resize(n);
  e.resize(n);
  const int itype = 1, lwork = static_cast<int>(zwork_.size()),
            lrwork = static_cast<int>(rwork_.size()), liwork = static_cast<int>(iwork_.size());
  int info = 0;
  zhegvd_(&itype, vectors ? "V" : "N", "L", &n, h.data(), &n, s.data(), &n, e.data(), zwork_.data(), &lwork,
          rwork_.data(), &lrwork, iwork_.data(), &liwork, &info);
  check(info, n, context);
}

void GeneralizedEigensolver::solveReal(Eigen::MatrixXd& h, Eigen::MatrixXd& s, Eigen::VectorXd& e,
                                       bool vectors, const char* context) {
  const int n = static_cast<int>(h.rows());
  if (n != n_) resize(n);
  e.resize(n);
  const int itype = 1, lwork = static_cast<int>(dwork_.size()),
            liwork = static_cast<int>(iwork_.size());
  int info = 0;
  dsygvd_(&itype, vectors ? "V" : "N", "L", &n, h.data(), &n, s.data(), &n, e.data(), dwork_.data(), &lwork,
          iwork_.data(), &liwork, &info);
  check(info, n, context);
}

}  // namespace mesochain::dftb
