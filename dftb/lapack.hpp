#pragma once
// The LAPACK / BLAS routines of the eigensolver and the density matrices, declared once, and one overload set per scalar
// type (double: real symmetric, std::complex<double>: Hermitian) so that the solver is written
// once. Character arguments carry gfortran's hidden length arguments (trailing size_t).
// Routine documentation: LAPACK Users' Guide, 3rd ed. (Anderson et al., SIAM 1999) and the
// reference sources (netlib.org/lapack).
#include <complex>
#include <cstddef>

namespace mesochain::dftb::lapack {

using cd = std::complex<double>;
using flen = std::size_t;

extern "C" {
void zpotrf_(const char* uplo, const int* n, cd* a, const int* lda, int* info, flen);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info, flen);
void zhegst_(const int* itype, const char* uplo, const int* n, cd* a, const int* lda,
             const cd* b, const int* ldb, int* info, flen);
void dsygst_(const int* itype, const char* uplo, const int* n, double* a, const int* lda,
             const double* b, const int* ldb, int* info, flen);
void zheevd_(const char* jobz, const char* uplo, const int* n, cd* a, const int* lda, double* w,
             cd* work, const int* lwork, double* rwork, const int* lrwork, int* iwork,
             const int* liwork, int* info, flen, flen);
void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda,
             double* w, double* work, const int* lwork, int* iwork, const int* liwork, int* info,
             flen, flen);
void zhetrd_(const char* uplo, const int* n, cd* a, const int* lda, double* d, double* e, cd* tau,
             cd* work, const int* lwork, int* info, flen);
void dsytrd_(const char* uplo, const int* n, double* a, const int* lda, double* d, double* e,
             double* tau, double* work, const int* lwork, int* info, flen);
void dsterf_(const int* n, double* d, double* e, int* info);
void dstedc_(const char* compz, const int* n, double* d, double* e, double* z, const int* ldz,
             double* work, const int* lwork, int* iwork, const int* liwork, int* info, flen);
void zunmtr_(const char* side, const char* uplo, const char* trans, const int* m, const int* n,
             const cd* a, const int* lda, const cd* tau, cd* c, const int* ldc, cd* work,
             const int* lwork, int* info, flen, flen, flen);
void dormtr_(const char* side, const char* uplo, const char* trans, const int* m, const int* n,
             const double* a, const int* lda, const double* tau, double* c, const int* ldc,
             double* work, const int* lwork, int* info, flen, flen, flen);
void zunmqr_(const char* side, const char* trans, const int* m, const int* n, const int* k,
             const cd* a, const int* lda, const cd* tau, cd* c, const int* ldc, cd* work,
             const int* lwork, int* info, flen, flen);
void dormqr_(const char* side, const char* trans, const int* m, const int* n, const int* k,
             const double* a, const int* lda, const double* tau, double* c, const int* ldc,
             double* work, const int* lwork, int* info, flen, flen);
void ztrsm_(const char* side, const char* uplo, const char* transa, const char* diag,
            const int* m, const int* n, const cd* alpha, const cd* a, const int* lda, cd* b,
            const int* ldb, flen, flen, flen, flen);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag,
            const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            double* b, const int* ldb, flen, flen, flen, flen);
void zgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const cd* alpha, const cd* a, const int* lda, const cd* b, const int* ldb,
            const cd* beta, cd* c, const int* ldc, flen, flen);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b,
            const int* ldb, const double* beta, double* c, const int* ldc, flen, flen);
}

// ---- Overloads by scalar type ------------------------------------------------------------
// Lower triangle throughout ('L'): the Bloch assembly fills the lower triangle only.

inline int potrf(int n, cd* a) {
  int info = 0;
  zpotrf_("L", &n, a, &n, &info, 1);
  return info;
}
inline int potrf(int n, double* a) {
  int info = 0;
  dpotrf_("L", &n, a, &n, &info, 1);
  return info;
}
// A <- L^-1 A L^-H (itype 1: H c = e S c).
inline int hegst(int n, cd* a, const cd* l) {
  int info = 0, itype = 1;
  zhegst_(&itype, "L", &n, a, &n, l, &n, &info, 1);
  return info;
}
inline int hegst(int n, double* a, const double* l) {
  int info = 0, itype = 1;
  dsygst_(&itype, "L", &n, a, &n, l, &n, &info, 1);
  return info;
}
// Divide and conquer; rwork is unused in the real case.
inline int heevd(bool vectors, int n, cd* a, double* w, cd* work, int lwork, double* rwork,
                 int lrwork, int* iwork, int liwork) {
  int info = 0;
  zheevd_(vectors ? "V" : "N", "L", &n, a, &n, w, work, &lwork, rwork, &lrwork, iwork, &liwork,
          &info, 1, 1);
  return info;
}
inline int heevd(bool vectors, int n, double* a, double* w, double* work, int lwork, double*,
                 int, int* iwork, int liwork) {
  int info = 0;
  dsyevd_(vectors ? "V" : "N", "L", &n, a, &n, w, work, &lwork, iwork, &liwork, &info, 1, 1);
  return info;
}
inline int hetrd(int n, cd* a, double* d, double* e, cd* tau, cd* work, int lwork) {
  int info = 0;
  zhetrd_("L", &n, a, &n, d, e, tau, work, &lwork, &info, 1);
  return info;
}
inline int hetrd(int n, double* a, double* d, double* e, double* tau, double* work, int lwork) {
  int info = 0;
  dsytrd_("L", &n, a, &n, d, e, tau, work, &lwork, &info, 1);
  return info;
}
inline int sterf(int n, double* d, double* e) {
  int info = 0;
  dsterf_(&n, d, e, &info);
  return info;
}
// All eigenpairs of the tridiagonal (d, e) by divide and conquer (Cuppen; Gu & Eisenstat,
// SIAM J. Matrix Anal. Appl. 16, 172 (1995)): d receives the eigenvalues, z (n x n) the vectors.
inline int stedc(int n, double* d, double* e, double* z, double* work, int lwork, int* iwork,
                 int liwork) {
  int info = 0;
  dstedc_("I", &n, d, e, z, &n, work, &lwork, iwork, &liwork, &info, 1);
  return info;
}
inline void queryStedc(int n, int& lwork, int& liwork) {
  double d = 0, e = 0, z = 0, work = 0;
  int iw = 0;
  stedc(n, &d, &e, &z, &work, -1, &iw, -1);
  lwork = static_cast<int>(work);
  liwork = iw;
}
// C (n x m) <- Q C, Q from the reflectors hetrd left below the subdiagonal of a.
inline int unmtr(int n, int m, const cd* a, const cd* tau, cd* c, cd* work, int lwork) {
  int info = 0;
  zunmtr_("L", "L", "N", &n, &m, a, &n, tau, c, &n, work, &lwork, &info, 1, 1, 1);
  return info;
}
inline int unmtr(int n, int m, const double* a, const double* tau, double* c, double* work,
                 int lwork) {
  int info = 0;
  dormtr_("L", "L", "N", &n, &m, a, &n, tau, c, &n, work, &lwork, &info, 1, 1, 1);
  return info;
}
// B (n x m) <- op(T)^-1 B for the triangle T of a: `lower` with op = ^H (L^H x = y, T = L in
// the lower triangle), or the upper triangle with op = identity (the same solve, L^H stored).
inline void trsm(bool lowerAdjoint, int n, int m, const cd* a, cd* b) {
  const cd one = 1.0;
  ztrsm_("L", lowerAdjoint ? "L" : "U", lowerAdjoint ? "C" : "N", "N", &n, &m, &one, a, &n, b,
         &n, 1, 1, 1, 1);
}
inline void trsm(bool lowerAdjoint, int n, int m, const double* a, double* b) {
  const double one = 1.0;
  dtrsm_("L", lowerAdjoint ? "L" : "U", lowerAdjoint ? "T" : "N", "N", &n, &m, &one, a, &n, b,
         &n, 1, 1, 1, 1);
}

// C (rows x cols) <- A B^H for A rows x k, B cols x k; all three with leading dimension ld.
inline void gemmAdjoint(int rows, int cols, int k, const cd* a, const cd* b, cd* c, int ld) {
  const cd one = 1.0, zero = 0.0;
  zgemm_("N", "C", &rows, &cols, &k, &one, a, &ld, b, &ld, &zero, c, &ld, 1, 1);
}
inline void gemmAdjoint(int rows, int cols, int k, const double* a, const double* b, double* c,
                        int ld) {
  const double one = 1.0, zero = 0.0;
  dgemm_("N", "T", &rows, &cols, &k, &one, a, &ld, b, &ld, &zero, c, &ld, 1, 1);
}

// ---- Workspace queries (LWORK = -1): the optimal length the implementation asks for -----
inline double real(double x) { return x; }
inline double real(cd x) { return x.real(); }

template <class T>
int queryHetrd(int n) {
  T a{}, tau{}, work{};
  double d = 0, e = 0;
  hetrd(n, &a, &d, &e, &tau, &work, -1);
  return static_cast<int>(real(work));
}
// Q C for C with `columns` columns (unmtr) and the unmqr it calls on the (n-1)-order reflectors.
template <class T>
int queryUnmtr(int n, int columns) {
  T a{}, tau{}, c{}, work{};
  unmtr(n, columns, &a, &tau, &c, &work, -1);
  return static_cast<int>(real(work));
}
inline int queryUnmqr(int n, int columns, cd) {
  cd a{}, tau{}, c{}, work{};
  int info = 0, mi = n - 1, k = n - 1, lwork = -1;
  zunmqr_("L", "N", &mi, &columns, &k, &a, &n, &tau, &c, &n, &work, &lwork, &info, 1, 1);
  return static_cast<int>(work.real());
}
inline int queryUnmqr(int n, int columns, double) {
  double a{}, tau{}, c{}, work{};
  int info = 0, mi = n - 1, k = n - 1, lwork = -1;
  dormqr_("L", "N", &mi, &columns, &k, &a, &n, &tau, &c, &n, &work, &lwork, &info, 1, 1);
  return static_cast<int>(work);
}
}  // namespace mesochain::dftb::lapack
