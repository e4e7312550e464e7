#pragma once
// Effect "bonds": all parallel bonds of the scene. Bond kernels run in parallel over bonds into
// a per-bond buffer, then each element gathers its bonds' contributions in a fixed order, so
// results do not depend on the number of OpenMP threads.
#include <vector>

#include "mdem/effect.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

class BondEffect : public Effect {
 public:
  BondEffect(std::vector<Bond> bonds, int elementCount);
  std::string name() const override { return "bonds"; }
  void addForces(State& state) override;
  Energies energy(const State& state) const override;

  const std::vector<Bond>& bonds() const { return bonds_; }
  // Energy of each bond in the current state.
  std::vector<BondEnergy> bondEnergies(const State& state) const;

 private:
  std::vector<Bond> bonds_;
  std::vector<BondResult> results_;
  // CSR adjacency: for element i, entries [start_[i], start_[i+1]) of incident_, each
  // 2 * bond + (0 if the element is a, 1 if b).
  std::vector<int> start_;
  std::vector<int> incident_;
};

}  // namespace mesochain::mdem
