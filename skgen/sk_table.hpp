#pragma once
// A Slater-Koster table for one ordered pair of elements A-B: the two-centre integrals of the
// basis functions of A (first atom) and B (second atom) on a uniform distance grid, in the
// column layout of dftb/skf_file.hpp ("xy m": shell x of A, shell y of B, x <= y; the integrals
// with x > y belong to the B-A table), plus the atomic line for A-A.
#include <functional>

#include "dftb/skf_file.hpp"
#include "skgen/element_basis.hpp"
#include "skgen/two_centre.hpp"

namespace mesochain::skgen {

struct TableGrid {
  double spacing = 0.02;  // Bohr; row i (0-based) at r = (i + 1) spacing
  double cutoff = 10.4;   // Bohr; last row at the largest multiple of spacing <= cutoff
  TwoCentreQuadrature quadrature;
};

// Column of the extended .skf order for ⟨l_a| |l_b⟩ with |m|; −1 when l_a > l_b.
int skfColumn(int la, int lb, int m);

// Integrals with the density-superposition potential and functional `xc` (spin-unpolarised).
// `homonuclear`: also fill the atomic line (on-site energies, U, occupations, mass of A).
// `progress(done, total)` after every row. No repulsive is set (t.spline empty).
// Throws std::invalid_argument for a grid with no row (cutoff < spacing).
dftb::SkfTable buildSkTable(const ElementBasis& a, const ElementBasis& b, XcKind xc,
                            const TableGrid& grid, bool homonuclear,
                            const std::function<void(int, int)>& progress = {});

}  // namespace mesochain::skgen
