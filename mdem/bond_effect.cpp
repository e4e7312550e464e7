#include "mdem/bond_effect.hpp"

namespace mesochain::mdem {

BondEffect::BondEffect(std::vector<Bond> bonds, int elementCount)
    : bonds_(std::move(bonds)), results_(bonds_.size()), start_(elementCount + 1, 0) {
  for (const Bond& b : bonds_) ++start_[b.a + 1], ++start_[b.b + 1];
  for (int i = 0; i < elementCount; ++i) start_[i + 1] += start_[i];
  incident_.resize(start_.back());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int k = 0; k < static_cast<int>(bonds_.size()); ++k) {
    incident_[fill[bonds_[k].a]++] = 2 * k;
    incident_[fill[bonds_[k].b]++] = 2 * k + 1;
  }
}

void BondEffect::addForces(State& state) {
  Bodies& s = state.bodies;
  const int nb = size();
#pragma omp parallel if (nb > 512)
  {
#pragma omp for schedule(static)
    for (int k = 0; k < nb; ++k) computeBond(s, k);
#pragma omp for schedule(static)
    for (int i = 0; i < s.size(); ++i) gather(i, s.force[i], s.torque[i]);
  }
}

std::vector<BondEnergy> BondEffect::bondEnergies(const State& state) const {
  const Bodies& s = state.bodies;
  std::vector<BondEnergy> out(bonds_.size());
  for (std::size_t k = 0; k < bonds_.size(); ++k) {
    const Bond& b = bonds_[k];
    out[k] = evaluateBond(b, s.position[b.a], s.orientation[b.a], s.position[b.b],
                          s.orientation[b.b])
                 .energy;
  }
  return out;
}

Energies BondEffect::energy(const State& state) const {
  Energies e;
  for (const BondEnergy& b : bondEnergies(state)) e.bonds += b;
  return e;
}

}  // namespace mesochain::mdem
