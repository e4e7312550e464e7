#pragma once
// PairIntegrals of an ordered species pair (A, B) from the tables A-B.skf and B-A.skf.
//
// Heteronuclear convention (the one of DFTB+, src/dftbp/dftbplus/parser.F90: readSKFiles and
// getFullTable, with the rotation of src/dftbp/dftb/sk.F90 and the call in
// src/dftbp/dftb/nonscc.F90, vect = x_2 - x_1):
//   An integral between shell l1 on A and shell l2 on B is taken from A-B.skf when l1 <= l2 and
//   from B-A.skf (with the shells swapped) when l1 > l2. So for the pair (A, B):
//     ss, pp_sigma, pp_pi:  from A-B.skf
//     <s_A | p_B>:          the sp column of A-B.skf  ("s on the first atom, p on the second")
//     <p_A | s_B>:          the sp column of B-A.skf, with the sign (-1)^(1+0) of the swap
//   i.e. the sp column of X-Y.skf is the sigma integral between s on X and p on Y, Y lying
//   along +z from X. Example (3ob-3-1): the sp column of C-H.skf is zero (H has no p shell) and
//   <p_C | s_H> comes from the sp column of H-C.skf.
// Orbital order s, p_x, p_y, p_z (DFTB+ orders p as p_y, p_z, p_x; the values are the same).
#include <string>

#include "dftb/parameters.hpp"
#include "dftb/sk_grid.hpp"
#include "dftb/skf_file.hpp"

namespace mesochain::dftb {

class SkPairIntegrals final : public PairIntegrals {
 public:
  // ab = A-B.skf, ba = B-A.skf (the same table for A = B); lA, lB: highest shell (0 or 1).
  // Throws InputError if the two tables have different grids.
  SkPairIntegrals(const SkfTable& ab, const SkfTable& ba, int lA, int lB);

  double cutoff() const override { return grid_.cutoff(); }
  void blocks(const Eigen::Vector3d& d, OrbitalBlock& h, OrbitalBlock& s) const override;
  void blocksWithDerivatives(const Eigen::Vector3d& d, OrbitalBlock& h, OrbitalBlock& s,
                             OrbitalBlock dh[3], OrbitalBlock ds[3]) const override;

  int orbitalsA() const { return nA_; }
  int orbitalsB() const { return nB_; }
  // Interpolated radial integrals (H first, then S): ss, sp, ps, pp_sigma, pp_pi.
  static constexpr int kColumns = 10;
  void radial(double r, double value[kColumns], double derivative[kColumns]) const {
    grid_.evaluate(r, value, derivative);
  }

 private:
  static SkGrid makeGrid(const SkfTable& ab, const SkfTable& ba);
  int nA_;
  int nB_;
  SkGrid grid_;
};

}  // namespace mesochain::dftb
