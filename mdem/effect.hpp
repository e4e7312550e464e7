#pragma once
// The engine is a list of effect objects built from the scene's `effects` list (plus the loads
// when the scene has any). Each effect adds its forces and torques to the state and reports its
// energy; an effect that is not named has no object and costs no loop. Contacts will plug in
// the same way.
#include <memory>
#include <string>

#include "mdem/body.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

// What the integrator advances and effects act on.
struct State {
  Bodies bodies;
  double time = 0.0;  // ns
};

// Energies (zJ) by kind. Kinetic terms are filled by the simulation, the rest by effects.
struct Energies {
  double kineticTranslational = 0.0;
  double kineticRotational = 0.0;
  BondEnergy bonds;
  double loadPotential = 0.0;  // -F.u - M.theta of fixed-direction loads (0 for others)
  double vdw = 0.0;            // van der Waals contacts between elements (mdem/contacts)
  // Work dissipated so far by the contact dashpots (zJ, >= 0): not stored energy, so not part of
  // total(); total() + contactDissipated is conserved without other damping.
  double contactDissipated = 0.0;

  double potential() const { return bonds.total() + loadPotential + vdw; }
  double total() const { return kineticTranslational + kineticRotational + potential(); }
  Energies& operator+=(const Energies& o) {
    kineticTranslational += o.kineticTranslational;
    kineticRotational += o.kineticRotational;
    bonds += o.bonds;
    loadPotential += o.loadPotential;
    vdw += o.vdw;
    contactDissipated += o.contactDissipated;
    return *this;
  }
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;
  // Adds forces and torques (world frame) to state.bodies.force / torque.
  virtual void addForces(State& state) = 0;
  // Energy stored by this effect in the current state (zero for dissipative effects).
  virtual Energies energy(const State& state) const = 0;
};

using EffectPtr = std::unique_ptr<Effect>;

}  // namespace mesochain::mdem
