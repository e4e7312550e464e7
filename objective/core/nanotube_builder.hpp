#pragma once
// Ideal (n,m) carbon nanotubes rolled up from graphene, as objective cells.
//
// Roll-up (White, Robertson & Mintmire, Phys. Rev. B 47, 5485 (1993); Dumitrica & James,
// J. Mech. Phys. Solids 55, 2206 (2007)):
//   graphene lattice a1 = a (sqrt3/2, 1/2), a2 = a (sqrt3/2, -1/2), a = sqrt3 * bond length,
//   atoms at 0 and (a1 + a2)/3; chiral vector C_h = n a1 + m a2, radius R = |C_h| / (2 pi).
//   A sheet point r goes to (R cos phi, R sin phi, z) with
//     phi = 2 pi (r . C_h) / |C_h|^2,   z = (C_h x r) / |C_h|   (2D cross product),
//   so the sheet atom at the origin sits at (R, 0, 0) and the tube axis is z.
//
// Helical cell: N_a = gcd(n, m); the screw vector H = p a1 + q a2 solves m p - n q = N_a, so
// C_h/N_a and H span the graphene lattice and two atoms plus g(zeta, c) generate the tube.
// All solutions differ by multiples of C_h/N_a (a rotation by 2 pi/N_a, same translation), so
// the screw is unique once its angle is reduced into (-pi/N_a, pi/N_a]. With this sign choice
// T = (C_h x H)/|C_h| = N_a * A_cell / |C_h| > 0 (A_cell = sqrt3 a^2 / 2). Examples: (n,n) has
// T = a/2 and gamma = pi/n; (n,0) has T = sqrt3 a/2 and gamma = +pi/n (the boundary value).
// A tube with m > n is the mirror image of (m, n); it is built with the same formulas.
//
// Everything in Bohr and radians; bondLength in Bohr.
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

// The source the builders' input errors name (their arguments come from a builder table or the
// command line, not from one file).
inline constexpr const char* kBuilderSource = "<builder>";

// The roll-up of one (n, m) tube: lattice data and the sheet -> cylinder map.
class NanotubeRollUp {
 public:
  // Throws InputError (source "<builder>") unless n >= 1, m >= 0 and bondLength > 0 finite.
  NanotubeRollUp(int n, int m, double bondLength);

  int n() const { return n_; }
  int m() const { return m_; }
  double bondLength() const { return bond_; }
  Eigen::Vector2d a1() const { return a1_; }
  Eigen::Vector2d a2() const { return a2_; }
  Eigen::Vector2d chiral() const { return ch_; }
  double radius() const;
  int rotationOrder() const { return gcd_; }  // N_a = gcd(n, m)
  // Translational period |T_vec| and atoms per translational cell 4 (n^2+nm+m^2)/d_R.
  double translationalPeriod() const;
  long translationalAtomCount() const;
  // The integer coefficients (t1, t2) of T_vec = t1 a1 + t2 a2.
  std::pair<long, long> translationalVector() const;
  // Screw translation T > 0 and reduced screw angle gamma in (-pi/N_a, pi/N_a].
  double screwTranslation() const;
  double screwTwist() const;
  // The sheet point r (Bohr) on the cylinder.
  Eigen::Vector3d roll(const Eigen::Vector2d& r) const;
  // The inverse on the cylinder surface: (arc length R*phi, z) with phi in (-pi, pi].
  Eigen::Vector2d unrollToSheetFrame(const Eigen::Vector3d& x) const;

 private:
  int n_, m_, gcd_;
  double bond_;
  long lengthSquared_;  // L = n^2 + n m + m^2 (|C_h|^2 / a^2)
  long reducedTwistNumerator_;
  Eigen::Vector2d a1_, a2_, ch_;
};

// The most atoms a builder makes in one cell: far beyond what DFTB can diagonalise (4 orbitals
// per carbon: a 4e5 x 4e5 complex Hamiltonian, 2.6 TB), so larger requests are typing errors.
inline constexpr long kMaxBuiltAtoms = 100'000;

// The minimal objective cell: 2 atoms, screw (T, gamma), rotation order gcd(n, m).
ObjectiveCell buildNanotubeHelical(int n, int m, double bondLength);
// The translational unit cell (gamma = 0, N_a = 1) with 4 (n^2+nm+m^2)/d_R atoms; with
// useRotation, N_a = gcd(n, m) and only the atoms of the sector 0 <= phi < 2 pi/N_a.
ObjectiveCell buildNanotubeTranslational(int n, int m, double bondLength, bool useRotation = false);
// The sector 0 <= phi < 2 pi / order of the translational cell (gamma = 0, N_a = order): exact
// (the rotation by 2 pi / order maps the tube onto itself) when order divides gcd(n, m), an
// InputError otherwise; 4 (n^2+nm+m^2) / (d_R order) atoms.
ObjectiveCell buildNanotubeSector(int n, int m, double bondLength, int order);
// Concentric walls sharing one translational period (e.g. (5,5)@(10,10)); gamma = 0, N_a = 1.
// Incommensurate periods, duplicate walls or walls closer than 1 Å in radius: InputError.
ObjectiveCell buildMultiWallTranslational(const std::vector<std::pair<int, int>>& walls,
                                          double bondLength);
// The same walls as one angular sector of 2 pi / order (N_a = order), every wall's own exact
// sector (order must divide gcd(n, m) of every wall), so the walls carry different numbers of
// atoms: the C5 sector of (35,35)@(40,40) has 28 + 32 (objective/core/tube_sector_builder.hpp).
ObjectiveCell buildMultiWallSector(const std::vector<std::pair<int, int>>& walls, double bondLength,
                                   int order);

}  // namespace mesochain::objective
