#pragma once
// The dispersion term ("dispersion", registered in dispersion_term.cpp): the Lennard-Jones form
// of dftb/dispersion_lj.hpp between every pair of atoms, summed with a cutoff or, for the r^-6
// tail, by the helical Ewald sum (dftb/dispersion_ewald.hpp). Built when
// CalculatorSettings::dispersion.enabled. Ledger: "dispersion" (Energy) and, for the cutoff sum
// on a screw cell, "dispersion_tail_estimate" (Reported, see below).
#include <memory>
#include <string>
#include <vector>

#include "dftb/dispersion_lj.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/pair_potential_term.hpp"

namespace mesochain::dftb {

struct DispersionSettings {
  bool enabled = false;
  double epsilon = 0.0;  // Hartree, well depth (>= 0)
  double r0 = 0.0;       // Bohr, position of the pair minimum (> 0)
  double cutoff = 0.0;   // Bohr (> 0)
  // r^-6 tail: false = cut off at `cutoff`; true = helical Ewald sum to `ewaldTolerance`
  // (dftb/dispersion_ewald.hpp).
  bool ewald = false;
  double ewaldTolerance = 1e-8;  // relative, in [1e-13, 1e-2]
  // Per-element parameters (DFTB+'s LennardJones Parameters, UFF or explicit), when non-empty:
  // element k has well depth elementEpsilon[k] (Hartree) and minimum elementR0[k] (Bohr), and a
  // pair of elements A, B uses DFTB+'s combination rule (src/dftbp/dftb/dispuff.F90), the
  // geometric means  eps_AB = sqrt(eps_A eps_B),  r0_AB = sqrt(r0_A r0_B).  Every species of the
  // parameter set needs an entry. Empty: epsilon and r0 above serve every pair.
  std::vector<std::string> elements;
  std::vector<double> elementEpsilon;
  std::vector<double> elementR0;

  bool operator==(const DispersionSettings&) const = default;
};

// InputError (source "the calculator settings", the key) for a value outside the ranges above.
void validate(const DispersionSettings& settings);

// The Lennard-Jones potential of every ordered species pair of `species` (the parameter set's
// names, in its order): one potential when settings.elements is empty, else the combined pair
// parameters. InputError naming the species that has no entry.
SpeciesPairTable<UffLennardJones> lennardJonesPairs(const DispersionSettings& settings,
                                                    const std::vector<std::string>& species);

// The cutoff sum. Truncation estimate of the r^-6 tail beyond the cutoff for a line of atoms
// (screw cells only), each cell atom j standing for a line density N_a / T:
//   E_tail = -(1/5) (N_a / T) sum_{i, j in the cell} C6_ij / r_c^5   per cell, C6 = 2 eps r0^6
// (= -(2/5) N_o lambda eps r0^6 / r_c^5 with one parameter set, lambda = N_o N_a / T; not part
// of the energy).
class CutoffDispersionTerm final : public EnergyTerm {
 public:
  explicit CutoffDispersionTerm(const UffLennardJones& lj);
  explicit CutoffDispersionTerm(SpeciesPairTable<UffLennardJones> pairs);
  std::string name() const override { return "dispersion"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;

 private:
  PairTerm<SpeciesPairTable<UffLennardJones>> pairs_;
};

}  // namespace mesochain::dftb
