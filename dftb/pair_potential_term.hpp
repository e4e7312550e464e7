#pragma once
// A pair potential summed over the objective images of the cell atoms:
//   E = 1/2 sum_{(i, j, g), |d| < r_c} V_{s_i s_j}(|g(x_j) - x_i|)   (per cell),
// used for the repulsive energy of the tables, Lennard-Jones dispersion and its short-range
// Ewald part. A term is a small evaluator of one pair (HOOMD-style); the loop, the chain rule
// for x, T and gamma and the threads are the one kernel of dftb/image_pair_sum.hpp.
//
// Evaluator: a copyable object with
//   double cutoff() const;                                         // Bohr, largest over pairs
//   void operator()(int si, int sj, double r, double& v, double& dv) const;  // V, dV/dr
// for the species indices si, sj of the two atoms (cell.species). The term reports one ledger
// entry, Energy, under its name.
#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dftb/energy_term.hpp"
#include "dftb/image_pair_sum.hpp"
#include "dftb/parameters.hpp"

namespace mesochain::dftb {

template <class Evaluator>
class PairTerm final : public EnergyTerm {
 public:
  PairTerm(std::string name, Evaluator evaluator)
      : name_(std::move(name)), evaluator_(std::move(evaluator)) {}

  std::string name() const override { return name_; }
  const Evaluator& evaluator() const { return evaluator_; }

  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override {
    const objective::ImageList images(cell, evaluator_.cutoff());
    const auto& species = cell.species;
    ImagePairSum s = imagePairSum(cell, images, request.gradient, request.strain,
                                  [&](int i, int j, double r, double& v, double& dv) {
                                    evaluator_(species[i], species[j], r, v, dv);
                                  });
    out.energies.add(name_, EnergyKind::Energy, s.energy);
    if (request.gradient) out.gradient = std::move(s.gradient);
    out.dEdTranslation = s.dTranslation;
    out.dEdTwist = s.dTwist;
  }

 private:
  std::string name_;
  Evaluator evaluator_;
};

// One potential for every species pair (a `final` RadialPotential: the call is direct).
template <class Potential>
struct SamePotentialEvaluator {
  Potential potential;
  double cutoff() const { return potential.cutoff(); }
  void operator()(int, int, double r, double& v, double& dv) const { potential.evaluate(r, v, dv); }
};

// A potential per ordered species pair in a table (species indices of cell.speciesNames, which
// the calculator keeps in the parameter set's order), or one potential for every pair
// (speciesCount = 0, `pairs` of size 1). Potential: a `final` RadialPotential (direct calls).
template <class Potential>
struct SpeciesPairTable {
  std::vector<Potential> pairs;  // speciesCount^2 entries, [si * speciesCount + sj]; or 1
  int speciesCount = 0;
  const Potential& pair(int si, int sj) const {
    return speciesCount ? pairs[static_cast<std::size_t>(si) * speciesCount + sj] : pairs.front();
  }
  double cutoff() const {
    double c = 0.0;
    for (const Potential& p : pairs) c = std::max(c, p.cutoff());
    return c;
  }
  void operator()(int si, int sj, double r, double& v, double& dv) const { pair(si, sj).evaluate(r, v, dv); }
};

// A potential per species pair looked up through a function (the tables' repulsive splines,
// tests and benchmarks).
struct LookupEvaluator {
  using Lookup = std::function<const RadialPotential&(int, int)>;
  Lookup potential;
  double cut = 0.0;
  double cutoff() const { return cut; }
  void operator()(int si, int sj, double r, double& v, double& dv) const {
    potential(si, sj).evaluate(r, v, dv);
  }
};

// The pair term over a lookup: potential(si, sj) returns the pair potential of two species
// (indices of cell.speciesNames); cutoff is the largest cutoff over the pairs.
class PairPotentialTerm final : public EnergyTerm {
 public:
  using PotentialLookup = LookupEvaluator::Lookup;
  PairPotentialTerm(std::string name, PotentialLookup potential, double cutoff)
      : term_(std::move(name), LookupEvaluator{std::move(potential), cutoff}) {}
  std::string name() const override { return term_.name(); }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override {
    term_.evaluate(cell, request, out);
  }

 private:
  PairTerm<LookupEvaluator> term_;
};

}  // namespace mesochain::dftb
