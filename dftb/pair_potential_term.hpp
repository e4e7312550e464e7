#pragma once
// A radial pair potential summed over the objective images of the cell atoms:
//   E = 1/2 sum_{(i, j, g), |d| < r_c} V_{s_i s_j}(|g(x_j) - x_i|)   (per cell),
// used for the repulsive energy of the tables and for Lennard-Jones dispersion.
// One template loop (kernel apart from orchestration): the potential per species pair is a
// RadialPotential; gradient and strain derivatives follow from d = g(x_j) - x_i.
#include <functional>
#include <memory>
#include <string>

#include "dftb/energy_term.hpp"
#include "dftb/parameters.hpp"

namespace mesochain::dftb {

class PairPotentialTerm : public EnergyTerm {
 public:
  // potential(si, sj) returns the pair potential of two species (indices of cell.speciesNames
  // as mapped by the caller); cutoff is the largest cutoff over the pairs.
  using PotentialLookup = std::function<const RadialPotential&(int, int)>;
  PairPotentialTerm(std::string name, PotentialLookup potential, double cutoff);

  std::string name() const override { return name_; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;

 private:
  std::string name_;
  PotentialLookup potential_;
  double cutoff_;
};

}  // namespace mesochain::dftb
