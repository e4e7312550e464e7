#pragma once
// Effect "bonds": all parallel bonds of the scene (parallel_bond.hpp). Items are the bonds: each
// bond kernel writes its forces and torques into a per-bond buffer (computeBond), then each
// element gathers its bonds' contributions in a fixed order (gatherElement), so results do not
// depend on the number of OpenMP threads. Bonds join elements of one filament only, so a scene
// of separate filaments may run barrier-free (stepper.hpp).
#include <algorithm>
#include <vector>

#include "mdem/effect.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

class BondEffect : public Effect {
 public:
  BondEffect(std::vector<Bond> bonds, int elementCount);
  std::string name() const override { return "bonds"; }

  int itemCount() const override { return size(); }
  void computeItems(const State& state, double, int lo, int hi) override {
    int k = lo;
    for (; k + 1 < hi; k += 2) computeBondPair(state.bodies, k, k + 1);
    if (k < hi) computeBond(state.bodies, k);
  }
  void computeItemList(const State& state, double, const int* items, int count) override {
    int e = 0;
    for (; e + 1 < count; e += 2) computeBondPair(state.bodies, items[e], items[e + 1]);
    if (e < count) computeBond(state.bodies, items[e]);
  }
  int itemElement(int k) const override { return std::min(bonds_[k].a, bonds_[k].b); }
  void gather(const State&, double, int lo, int hi, Vec3* force, Vec3* torque) const override {
    for (int i = lo; i < hi; ++i) gatherElement(i, force[i], torque[i]);
  }
  // Entries "stretching", "shearing", "twisting", "bending".
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  const std::vector<Bond>* bondList() const override { return &bonds_; }
  // The tracked twist branch of every bond.
  void saveState(BinaryWriter& out) const override;
  void loadState(BinaryReader& in) override;

  const std::vector<Bond>& bonds() const { return bonds_; }
  int size() const { return static_cast<int>(bonds_.size()); }
  // Evaluates bond k in the current state into the buffer and advances its tracked twist branch.
  void computeBond(const Bodies& s, int k) {
    Bond& b = bonds_[k];
    const BondForces r = bondForces(b, s.position[b.a], s.orientation[b.a], s.position[b.b],
                                    s.orientation[b.b]);
    store(k, r);
  }
  // Bonds k and l (k != l) together: the same results as computeBond of each (bondForcesPair).
  void computeBondPair(const Bodies& s, int k, int l) {
    BondForces r, q;
    bondForcesPair(bonds_[k], bonds_[l], s, r, q);
    store(k, r), store(l, q);
  }
  // Adds the buffered forces and torques of element i's bonds (in a fixed order).
  void gatherElement(int i, Vec3& force, Vec3& torque) const {
    for (int e = start_[i]; e < start_[i + 1]; ++e) {
      const Wrench& r = results_[incident_[e] >> 1];
      if (incident_[e] & 1) {
        force += r.forceB, torque += r.torqueB;
      } else {
        force += r.forceA, torque += r.torqueA;
      }
    }
  }
  // Energy of each bond in the current state.
  std::vector<BondEnergy> bondEnergies(const State& state) const;
  // What each bond carries in the current state (outputs).
  std::vector<BondLoad> bondLoads(const State& state) const override;
  void addElementEnergies(const State& state, std::vector<double>& perElement) const override;

 private:
  // Bond k's result into the buffer; its tracked twist branch follows the relative rotation.
  void store(int k, const BondForces& r) {
    bonds_[k].theta = r.theta;
    results_[k] = {r.forceA, r.torqueA, r.forceB, r.torqueB};
  }
  struct Wrench {
    Vec3 forceA, torqueA, forceB, torqueB;
  };
  std::vector<Bond> bonds_;
  std::vector<Wrench> results_;
  // CSR adjacency: for element i, entries [start_[i], start_[i+1]) of incident_, each
  // 2 * bond + (0 if the element is a, 1 if b).
  std::vector<int> start_;
  std::vector<int> incident_;
};

}  // namespace mesochain::mdem
