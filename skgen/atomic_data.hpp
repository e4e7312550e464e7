#pragma once
// Atomic parameters of a .skf table from the free (unconfined) atom: on-site energies (the
// Kohn-Sham eigenvalues of the valence shells), the Hubbard U (derivative of the highest
// occupied level with respect to its occupation, by central difference), the spin constants W
// of spin-polarised DFTB and the spin-polarisation energy, occupations.
#include <array>
#include <vector>

#include "skgen/atom.hpp"

namespace mesochain::skgen {

struct AtomicData {
  std::array<double, 4> onsite{};      // s, p, d, f (Hartree)
  std::array<double, 4> hubbard{};     // the same U for every shell, as published sets do
  std::array<double, 4> occupation{};  // valence electrons per shell
  // W_ll' of the valence shells (order of Element::valence), Hartree; spinFunctional names
  // the functional they were computed with.
  std::vector<std::vector<double>> spinConstants;
  // E(spin-polarised free atom, Hund's rule) − E(spin-unpolarised free atom), Hartree: the
  // "SPE" field of the .skf atomic line (slakoformat.pdf: "spin polarisation error for
  // calculating formation energies"; read but not used by DFTB+).
  double spinPolarisationEnergy = 0.0;
};

// U = dε_HOMO / dq_HOMO ≈ [ε(q + δ) − ε(q − δ)] / (2δ), the highest occupied shell charged and
// discharged by δ electrons (spread equally over the spins). Free atom: `free` has no
// confinement.
double hubbardU(const AtomSettings& free, int n, int l, double delta = 0.01);

// Occupation derivatives of the spin-polarised atom at the spin-unpolarised reference
// (n_l↑ = n_l↓ = occupation/2 for every shell of `free`), by central differences of step δ in
// one spin channel of one shell at a time:
//   W_kk' = ½ (∂ε_k↑/∂n_k'↑ − ∂ε_k↑/∂n_k'↓)   spin constants (Köhler, Frauenheim et al.,
//                                              J. Phys. Chem. A 111, 5622 (2007); the W of
//                                              the DFTB+ manual's SpinConstants)
//   U_kk' = ½ (∂ε_k↑/∂n_k'↑ + ∂ε_k↑/∂n_k'↓) = ∂ε_k/∂n_k'  (shell-resolved Hubbard matrix)
// for the shells `shells` (indices into free.shells). A shell with no electrons (above the
// HOMO) cannot be discharged; as in the published tables its row and column are those of the
// highest occupied shell among `shells`. The atom functional is free.xc, solved spin-polarised.
// Without exchange-correlation W = 0 exactly (the Hartree potential sees only n↑ + n↓).
struct OccupationDerivatives {
  std::vector<std::vector<double>> w, u;
};
OccupationDerivatives occupationDerivatives(const AtomSettings& free,
                                            const std::vector<int>& shells,
                                            double delta = 0.01);

// Hund's-rule occupations of a spherical atom: every shell fills the majority spin first
// (up = min(occupation, 2l+1), down = the rest).
AtomSettings hundPolarised(const AtomSettings& unpolarised);

// E(hundPolarised(free)) − E(free, spin-unpolarised), both solved with free.xc.
double spinPolarisationEnergy(const AtomSettings& free);

}  // namespace mesochain::skgen
