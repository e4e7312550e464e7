#pragma once
// Lennard-Jones dispersion with its r^-6 tail summed by the helical Ewald sum (docs/ewald.md):
//   V_LJ(r) = [V_LJ(r) + C6 / r^6] - C6 / r^6,   C6 = 2 eps r0^6,
// the bracket (r^-12 beyond the switch radius, the switched polynomial plus C6/r^6 inside) by
// the cutoff pair sum, the full -C6 sum_g 1/r^6 over every image by ewald::HelicalLatticeSum to
// a requested tolerance. The plain cutoff sum drops the r^-6 tail beyond the cutoff instead.
#include <memory>

#include "dftb/dispersion_lj.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/pair_potential_term.hpp"
#include "ewald/helical_lattice_sum.hpp"

namespace mesochain::dftb {

// V_LJ(r) + C6 / r^6 (decays as r^-12), zero beyond the cutoff.
class LjShortRange final : public RadialPotential {
 public:
  explicit LjShortRange(const UffLennardJones& lj);
  double cutoff() const override { return lj_.cutoff(); }
  void evaluate(double r, double& value, double& derivative) const override;
  double c6() const { return c6_; }

 private:
  UffLennardJones lj_;
  double c6_;
};

class EwaldDispersionTerm final : public EnergyTerm {
 public:
  // tolerance: relative accuracy of the Ewald sum (ewald::LatticeSumSettings).
  EwaldDispersionTerm(const UffLennardJones& lj, double tolerance);
  // A potential per species pair (C6_ij = 2 eps_ij r0_ij^6 weights the 1/r^6 sum of pair i, j).
  EwaldDispersionTerm(const SpeciesPairTable<UffLennardJones>& lj, double tolerance);
  std::string name() const override { return "dispersion"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;

 private:
  PairTerm<SpeciesPairTable<LjShortRange>> shortTerm_;
  ewald::HelicalLatticeSum sum_;
};

}  // namespace mesochain::dftb
