#pragma once
// Reader for DFTB+ Slater-Koster files (.skf), simple and extended ('@') format.
//
// Layout (as read by DFTB+, src/dftbp/type/oldskdata.F90):
//   [extended only] line starting with '@' (rest of the line ignored)
//   gridDist nGrid [anything]            -> nGrid - 1 table rows follow (DFTB+ reads nGrid - 1)
//   [homonuclear only] Ed Ep Es SPE Ud Up Us fd fp fs           (simple, 10 values)
//                      Ef Ed Ep Es SPE Uf Ud Up Us ff fd fp fs  (extended, 13 values)
//   mass c2..c9 rcut d1..d10             (20 values; heteronuclear: the mass is a placeholder)
//   nGrid - 1 rows of integrals: 10 H then 10 S values (simple) or 20 + 20 (extended). Row i
//   (1-based) belongs to r = i * gridDist.
//   [lines up to "Spline" are ignored, as DFTB+ does: some published tables hold more rows
//    than they declare]
//   Spline / nInt cutoff / a1 a2 a3 / nInt-1 lines "start end c0 c1 c2 c3" /
//   last line "start end c0 c1 c2 c3 c4 c5"; anything after it is ignored.
//
// Integral columns are stored in the extended (spdf) order of DFTB+, 20 per row:
//   0 ff0 1 ff1 2 ff2 3 ff3 4 df0 5 df1 6 df2 7 dd0 8 dd1 9 dd2
//   10 pf0 11 pf1 12 pd0 13 pd1 14 pp0 15 pp1 16 sf0 17 sd0 18 sp0 19 ss0
// The simple format holds the columns dd0 dd1 dd2 pd0 pd1 pp0 pp1 sd0 sp0 ss0 (7..9, 12..15,
// 17..19); the f columns stay zero. "xy m" is the integral between shell x of the first atom
// of the file name and shell y of the second, m = 0 sigma, 1 pi, ...
//
// Stricter than DFTB+ (which reads list-directed and would continue a short row on the next
// line): every row must hold exactly the expected count of numbers.
#include <array>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "dftb/repulsive.hpp"

namespace mesochain::dftb {

// Column indices in the extended order above.
enum SkfColumn : int {
  kSkfPpSigma = 14,
  kSkfPpPi = 15,
  kSkfSpSigma = 18,
  kSkfSsSigma = 19,
  kSkfColumnCount = 20,
};

struct SkfTable {
  std::string path;
  bool extended = false;     // first line started with '@'
  bool homonuclear = false;  // the atomic line was read
  double gridSpacing = 0.0;  // Bohr
  int declaredPoints = 0;    // nGrid as written on the grid line
  Eigen::MatrixXd ham;       // (declaredPoints - 1) x 20
  Eigen::MatrixXd over;      // (declaredPoints - 1) x 20

  // Homonuclear tables only; index 0 s, 1 p, 2 d, 3 f (Hartree, electrons).
  std::array<double, 4> onsite{};
  std::array<double, 4> hubbard{};
  std::array<double, 4> occupation{};
  double spinPolarisationError = 0.0;
  double mass = 0.0;  // atomic mass units, as written

  PolynomialRepulsiveData polynomial;
  std::optional<SplineRepulsiveData> spline;
  int splineLine = 0;  // line of the "Spline" keyword (0 if none)

  int rows() const { return static_cast<int>(ham.rows()); }
};

// Reads one file; homonuclear: the file is A-A (it has the atomic line). Throws InputError
// naming the file and line for every problem (missing file, garbled or non-finite number, too
// few or too many columns, fewer rows than declared, broken Spline block).
SkfTable readSkfFile(const std::string& path, bool homonuclear);

}  // namespace mesochain::dftb
