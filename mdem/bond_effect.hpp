#pragma once
// Effect "bonds": all parallel bonds of the scene. Bond kernels run in parallel over bonds into
// a per-bond buffer (computeBond), then each element gathers its bonds' contributions in a
// fixed order (gather), so results do not depend on the number of OpenMP threads. The two
// halves are public so that the fused time step (stepper.hpp) can run them inside its own
// parallel region.
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
  int size() const { return static_cast<int>(bonds_.size()); }
  // Evaluates bond k in the current state into the buffer and advances its tracked twist branch.
  void computeBond(const Bodies& s, int k) {
    Bond& b = bonds_[k];
    const BondForces r = bondForces(b, s.position[b.a], s.orientation[b.a], s.position[b.b],
                                    s.orientation[b.b]);
    b.theta = r.theta;  // follow the branch of the relative rotation
    results_[k] = {r.forceA, r.torqueA, r.forceB, r.torqueB};
  }
  // Adds the buffered forces and torques of element i's bonds (in a fixed order).
  void gather(int i, Vec3& force, Vec3& torque) const {
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

 private:
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
