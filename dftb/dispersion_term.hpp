#pragma once
// The dispersion term ("dispersion", registered in dispersion_term.cpp): the Lennard-Jones form
// of dftb/dispersion_lj.hpp between every pair of atoms, summed with a cutoff or, for the r^-6
// tail, by the helical Ewald sum (dftb/dispersion_ewald.hpp). Built when
// CalculatorSettings::dispersion.enabled. Ledger: "dispersion" (Energy) and, for the cutoff sum
// on a screw cell, "dispersion_tail_estimate" (Reported, see below).
#include <memory>
#include <string>

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
};

// InputError (source "the calculator settings", the key) for a value outside the ranges above.
void validate(const DispersionSettings& settings);

// The cutoff sum. Truncation estimate of the r^-6 tail beyond the cutoff for a line of atoms
// with density lambda = N_o N_a / T (screw cells only):
//   E_tail = -(2/5) N_o lambda eps r0^6 / r_c^5   per cell  (not part of the energy).
class CutoffDispersionTerm final : public EnergyTerm {
 public:
  explicit CutoffDispersionTerm(const UffLennardJones& lj);
  std::string name() const override { return "dispersion"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;

 private:
  PairTerm<SamePotentialEvaluator<UffLennardJones>> pairs_;
};

}  // namespace mesochain::dftb
