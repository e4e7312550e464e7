#pragma once
// Atomic parameters of a .skf table from the free (unconfined) atom: on-site energies (the
// Kohn-Sham eigenvalues of the valence shells), the Hubbard U (derivative of the highest
// occupied level with respect to its occupation, by central difference), occupations.
#include <array>

#include "skgen/atom.hpp"

namespace mesochain::skgen {

struct AtomicData {
  std::array<double, 4> onsite{};      // s, p, d, f (Hartree)
  std::array<double, 4> hubbard{};     // the same U for every shell, as published sets do
  std::array<double, 4> occupation{};  // valence electrons per shell
};

// U = dε_HOMO / dq_HOMO ≈ [ε(q + δ) − ε(q − δ)] / (2δ), the highest occupied shell charged and
// discharged by δ electrons (spread equally over the spins). Free atom: `free` has no
// confinement.
double hubbardU(const AtomSettings& free, int n, int l, double delta = 0.01);

}  // namespace mesochain::skgen
