#pragma once
// Writer of Slater-Koster files in the simple (s, p, d) format that mesochain's reader
// (dftb/skf_file.hpp, which documents the layout) and DFTB+ read:
//   gridDist nGrid                         (nGrid − 1 rows follow, row i at r = i gridDist)
//   [homonuclear] Ed Ep Es SPE Ud Up Us fd fp fs
//   mass c2..c9 rcut d1..d10               (polynomial repulsive all zero: the spline is used)
//   rows: 10 H values then 10 S values (dd0 dd1 dd2 pd0 pd1 pp0 pp1 sd0 sp0 ss0)
//   Spline block (always present), then a free-text documentation block (ignored by readers).
// Numbers are written with 17 significant digits, so a table read back is bit-identical.
#include <string>

#include "dftb/skf_file.hpp"

namespace mesochain::skgen {

// The explicit zero repulsive: one interval [start, cutoff] with zero coefficients and the
// exponential head exp(−0·r + 0) − 1 ≡ 0. Readers evaluate E_rep = 0 at every distance; use it
// when no repulsive has been fitted (documented as such in the file's documentation block).
dftb::SplineRepulsiveData zeroRepulsive(double start, double cutoff);

// Writes `t` (ham/over: rows × 20 in the extended column order; only the simple-format columns
// are written, the f columns must be zero; t.spline required). Throws InputError naming `path`
// when it cannot be written and std::invalid_argument for an inconsistent table.
void writeSkfFile(const std::string& path, const dftb::SkfTable& t,
                  const std::string& documentation);

}  // namespace mesochain::skgen
