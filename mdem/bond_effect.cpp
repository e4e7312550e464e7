#include "mdem/bond_effect.hpp"

#include "mdem/binary_io.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "bonds", 100, "parallel bonds between elements (parallel_bond.hpp)", true, nullptr,
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<BondEffect>(b.scene.bonds, b.scene.bodies.size()); },
    EffectTable{}, false})

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

std::vector<BondLoad> BondEffect::bondLoads(const State& state) const {
  const Bodies& s = state.bodies;
  std::vector<BondLoad> out(bonds_.size());
  for (std::size_t k = 0; k < bonds_.size(); ++k) {
    const Bond& b = bonds_[k];
    const BondResult r = evaluateBond(b, s.position[b.a], s.orientation[b.a], s.position[b.b], s.orientation[b.b]);
    out[k] = bondLoad(b, r.d, r.theta);
  }
  return out;
}

void BondEffect::addElementEnergies(const State& state, std::vector<double>& perElement) const {
  const std::vector<BondEnergy> e = bondEnergies(state);
  for (std::size_t k = 0; k < bonds_.size(); ++k) {
    perElement[bonds_[k].a] += 0.5 * e[k].total();
    perElement[bonds_[k].b] += 0.5 * e[k].total();
  }
}

void BondEffect::reportEnergy(const State& state, EnergyLedger& ledger) const {
  BondEnergy e;
  for (const BondEnergy& b : bondEnergies(state)) e += b;
  ledger.add("stretching", EnergyKind::Potential, e.stretching);
  ledger.add("shearing", EnergyKind::Potential, e.shearing);
  ledger.add("twisting", EnergyKind::Potential, e.twisting);
  ledger.add("bending", EnergyKind::Potential, e.bending);
}

void BondEffect::saveState(BinaryWriter& out) const {
  out.write<std::uint64_t>(bonds_.size());
  for (const Bond& b : bonds_) out.write(b.theta);
}

void BondEffect::loadState(BinaryReader& in) {
  in.expectCount("bonds", bonds_.size());
  for (Bond& b : bonds_) b.theta = in.read<Vec3>();
}

}  // namespace mesochain::mdem
