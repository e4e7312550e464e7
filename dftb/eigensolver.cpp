#include "dftb/eigensolver.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "dftb/lapack.hpp"

namespace mesochain::dftb {

using cd = std::complex<double>;
template <class T>
using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

EigenvectorPath resolveEigenvectorPath(EigenvectorPath requested, int n) {
  if (requested != EigenvectorPath::Automatic) return requested;
  return n >= kOccupiedOnlyMinimumOrder ? EigenvectorPath::OccupiedOnly
                                        : EigenvectorPath::AllVectors;
}

template <class Scalar>
void ReducedProblem<Scalar>::resize(int n) {
  a.resize(n, n);
  tau.resize(std::max(1, n));
  diagonal.resize(n);
  offDiagonal.resize(std::max(1, n));
}
template struct ReducedProblem<double>;
template struct ReducedProblem<cd>;

int occupiedStateCount(const Eigen::VectorXd& levels, const Eigen::VectorXd& occupations,
                       double threshold, double degeneracy) {
  const int n = static_cast<int>(levels.size());
  int m = 0;
  while (m < n && occupations[m] > threshold) ++m;  // ascending levels: occupations decrease
  while (m > 0 && m < n && levels[m] - levels[m - 1] <= degeneracy) ++m;
  return m;
}

void GeneralizedEigensolver::resize(int n) {
  n_ = n;
  if (n <= 0) return;
  // Lengths from the implementation's own workspace queries. zheevd (JOBZ = 'V') partitions its
  // WORK as [tau: n | eigenvectors of T: n^2 | the rest for zunmtr] and gives zhetrd all but
  // the first n (reference zheevd.f: INDWRK = N+1, INDWK2 = INDWRK + N*N). Its documented
  // minimum 2n + n^2 (and its own query, which returns that minimum) leaves zunmtr only n
  // elements: zunmqr then drops to the unblocked Householder updates (BLAS-2). Here the rest is
  // what zunmtr and the zunmqr it calls ask for (n * block size, plus the block reflector T).
  // dsyevd likewise: [e: n | tau: n | Z: n^2 | dormtr] (INDWK2 = 2N + N*N + 1).
  const int big = n >= 2 ? 1 : 0;  // the queries need n >= 2 (n - 1 reflectors)
  const int zHetrd = big ? lapack::queryHetrd<cd>(n) : 1;
  const int zUnm = big ? std::max(lapack::queryUnmtr<cd>(n, n), lapack::queryUnmqr(n, n, cd{})) : 1;
  const int dHetrd = big ? lapack::queryHetrd<double>(n) : 1;
  const int dUnm =
      big ? std::max(lapack::queryUnmtr<double>(n, n), lapack::queryUnmqr(n, n, double{})) : 1;
  int stedcWork = 1 + 4 * n + 2 * n * n, stedcIwork = 3 + 5 * n;
  if (big) lapack::queryStedc(n, stedcWork, stedcIwork);
  const long n2 = static_cast<long>(n) * n;
  const long zheevd = std::max({2 * n + n2, n + n2 + std::max<long>(n, zUnm), n + long(zHetrd)});
  const long zlen = std::max({zheevd, long(zHetrd), long(zUnm)});
  const long zheevdRwork = 1 + 5 * n + 2 * n2;
  const long dsyevd =
      std::max({1 + 6 * n + 2 * n2, 2 * n + n2 + std::max<long>(n, dUnm), 2 * n + long(dHetrd)});
  const long dlen = std::max({zheevdRwork, dsyevd, long(dHetrd), long(dUnm), long(stedcWork)});
  const long ilen = std::max<long>(3 + 5 * n, stedcIwork);
  zwork_.resize(static_cast<size_t>(zlen));
  dwork_.resize(static_cast<size_t>(dlen));
  iwork_.resize(static_cast<size_t>(ilen));
  dcopy_.resize(static_cast<size_t>(2 * n));
  z_.resize(static_cast<size_t>(n2));
}

namespace {
void check(int info, const char* routine, const char* context) {
  if (info == 0) return;
  throw NumericalError(std::string(context) + ": LAPACK " + routine + " failed (info " +
                       std::to_string(info) + ")");
}
}  // namespace

template <class Scalar>
void GeneralizedEigensolver::reduce(ReducedProblem<Scalar>& p, Matrix<Scalar>& s,
                                    const Matrix<Scalar>* factor, Eigen::VectorXd& e, Mode mode,
                                    const char* context) {
  const int n = static_cast<int>(p.a.rows());
  if (n != n_) resize(n);
  e.resize(n);
  Scalar* work;
  if constexpr (std::is_same_v<Scalar, cd>) work = zwork_.data();
  else work = dwork_.data();
  const int lwork = std::is_same_v<Scalar, cd> ? complexWorkLength() : realWorkLength();
  const Scalar* l = factor ? factor->data() : s.data();
  if (!factor) {
    const int info = lapack::potrf(n, s.data());
    if (info > 0)
      throw NumericalError(std::string(context) +
                           ": the overlap matrix is not positive definite (leading minor " +
                           std::to_string(info) +
                           "): atoms too close, or a near-singular (linearly dependent) basis");
    check(info, "potrf", context);
  }
  check(lapack::hegst(n, p.a.data(), l), "hegst", context);
  if (mode != Mode::OccupiedOnly) {
    check(lapack::heevd(mode == Mode::AllVectors, n, p.a.data(), e.data(), work, lwork,
                        dwork_.data(), realWorkLength(), iwork_.data(), integerWorkLength()),
          "heevd", context);
    if (mode == Mode::AllVectors) lapack::trsm(true, n, n, l, p.a.data());  // C = L^-H Y
    return;
  }
  if (p.diagonal.size() != n) p.resize(n);
  check(lapack::hetrd(n, p.a.data(), p.diagonal.data(), p.offDiagonal.data(), p.tau.data(), work,
                      lwork),
        "hetrd", context);
  e = p.diagonal;
  std::copy(p.offDiagonal.data(), p.offDiagonal.data() + std::max(0, n - 1), dcopy_.begin());
  check(lapack::sterf(n, e.data(), dcopy_.data()), "sterf", context);
  // L^H into the upper triangle: hetrd and unmtr reference only the lower triangle below the
  // diagonal, trsm(upper) only the upper triangle with the diagonal.
  const Eigen::Map<const Matrix<Scalar>> lower(l, n, n);
  p.a.template triangularView<Eigen::Upper>() = lower.adjoint();
}

template <class Scalar>
void GeneralizedEigensolver::lowestVectors(ReducedProblem<Scalar>& p, int m, Matrix<Scalar>& c,
                                           const char* context) {
  const int n = static_cast<int>(p.a.rows());
  if (m <= 0) return;
  if (n != n_) resize(n);
  if (c.rows() != n || c.cols() < m)
    throw NumericalError(std::string(context) + ": eigenvector buffer too small");
  Scalar* work;
  if constexpr (std::is_same_v<Scalar, cd>) work = zwork_.data();
  else work = dwork_.data();
  const int lwork = std::is_same_v<Scalar, cd> ? complexWorkLength() : realWorkLength();
  std::copy(p.diagonal.data(), p.diagonal.data() + n, dcopy_.begin());
  std::copy(p.offDiagonal.data(), p.offDiagonal.data() + std::max(0, n - 1), dcopy_.begin() + n);
  check(lapack::stedc(n, dcopy_.data(), dcopy_.data() + n, z_.data(), dwork_.data(),
                      realWorkLength(), iwork_.data(), integerWorkLength()),
        "stedc", context);
  const Eigen::Map<const Eigen::MatrixXd> z(z_.data(), n, n);
  if constexpr (std::is_same_v<Scalar, cd>) c.leftCols(m) = z.leftCols(m).cast<cd>();
  else c.leftCols(m) = z.leftCols(m);
  check(lapack::unmtr(n, m, p.a.data(), p.tau.data(), c.data(), work, lwork), "unmtr", context);
  lapack::trsm(false, n, m, p.a.data(), c.data());  // C = L^-H Y with L^H in the upper triangle
}

template void GeneralizedEigensolver::reduce<double>(ReducedProblem<double>&, Matrix<double>&,
                                                     const Matrix<double>*, Eigen::VectorXd&,
                                                     Mode, const char*);
template void GeneralizedEigensolver::reduce<cd>(ReducedProblem<cd>&, Matrix<cd>&,
                                                 const Matrix<cd>*, Eigen::VectorXd&, Mode,
                                                 const char*);
template void GeneralizedEigensolver::lowestVectors<double>(ReducedProblem<double>&, int,
                                                            Matrix<double>&, const char*);
template void GeneralizedEigensolver::lowestVectors<cd>(ReducedProblem<cd>&, int, Matrix<cd>&,
                                                        const char*);

}  // namespace mesochain::dftb
