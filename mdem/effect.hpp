#pragma once
// The seam of the engine: an effect (bonds, contacts, loads, damping, ...) is a small unit that
// declares its name, registers itself (effect_registry.hpp), computes its forces in phases the
// stepper drives inside its one parallel region, and reports its energies into the ledger. The
// engine knows no effect by name: it builds whatever the scene names, in registration order,
// and an effect that is not named has no object and costs no loop.
//
// One force evaluation at time t (positions and velocities of time t) runs, for the effects in
// their order:
//   prepare(t)                  serial, once (effects with hasPrepare()), on the state the
//                               items then see: e.g. refresh a neighbour list, or form once per
//                               element what every item of the element reads (a contact's axes);
//   computeItems(t, lo, hi)     per item (bond, contact pair) into the effect's own buffer,
//                               items split between threads; an item writes only its own slot;
//   gather(t, lo, hi, F, M)     per element: adds the element's share of every item to the
//                               accumulated force F[i] / torque M[i] of elements [lo, hi), in a
//                               fixed order. Effects gather in their order, so a damping effect
//                               sees (and acts on) the sum of those before it;
//   finish(t)                   serial, once (effects with hasFinish()): e.g. charge the work
//                               dissipated since the last evaluation.
// Sums are formed per element in a fixed order, so results do not depend on the number of
// threads. Units: mdem/units.hpp.
#include <memory>
#include <string>
#include <vector>

#include "mdem/body.hpp"
#include "mdem/energy_ledger.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

class BinaryWriter;
class BinaryReader;
struct ContactStabilityTerms;
class ContactNeighbourhood;

// What the integrator advances and effects act on.
struct State {
  Bodies bodies;
  double time = 0.0;  // ns
  // Multiple time stepping (stepper.hpp): the outer group's force and torque at the last
  // boundary state, per element (empty without the splitting).
  std::vector<Vec3> heldForce, heldTorque;
  // The velocities and world angular velocities of the time of the last step (between the half
  // kick that ends it and the one that opens the next, which the stepper fuses), per element;
  // recorded only when an effect asks (Effect::wantsStepVelocities), for its finish.
  std::vector<Vec3> stepVelocity, stepAngularVelocity;
};

// Physical effects model the material; numerical damping (local / viscous) only drives a
// relaxation: it is left out of residuals and of grip reactions, and of the energy balance unless
// it charges its work (local damping with track_work, damping.hpp).
enum class EffectRole { Physical, NumericalDamping };

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;
  virtual EffectRole role() const { return EffectRole::Physical; }

  virtual bool hasPrepare() const { return false; }
  virtual void prepare(const State& /*state*/, double /*time*/) {}

  virtual int itemCount() const { return 0; }
  virtual void computeItems(const State& /*state*/, double /*time*/, int /*lo*/, int /*hi*/) {}
  // Items join elements of different filaments (contacts). When no effect does, and each item
  // belongs to one element (itemElement), the stepper may advance separate filaments on
  // separate threads with no barrier (stepper.hpp, ThreadPartition).
  virtual bool couplesFilaments() const { return false; }
  // Dissipative physical forces (dashpots): their damping rate limits the step as tightly as
  // the bonds do, so multiple time stepping leaves them on the inner step unless named.
  virtual bool dissipates() const { return false; }
  // The lowest-numbered element item k touches (-1: none); with couplesFilaments() false, the
  // elements it touches are bonded to it (ThreadPartition computes items by this element).
  virtual int itemElement(int /*k*/) const { return -1; }
  virtual void computeItemList(const State& state, double time, const int* items, int count) {
    for (int e = 0; e < count; ++e) computeItems(state, time, items[e], items[e] + 1);
  }

  virtual void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const = 0;

  virtual bool hasFinish() const { return false; }
  virtual void finish(const State& /*state*/, double /*time*/) {}
  // Whether finish reads State::stepVelocity and stepAngularVelocity (the stepper then records them).
  virtual bool wantsStepVelocities() const { return false; }
  // The forces the next step opens with were evaluated anew outside a step (a new simulation, a
  // stage boundary: Simulation::refreshForces), replacing those of the last step.
  virtual void kickForcesReplaced(const State& /*state*/) {}

  // The energies of the current state (stored, or dissipated so far) into the ledger. Called at
  // outputs, not per step.
  virtual void reportEnergy(const State& state, EnergyLedger& ledger) const = 0;

  // Adds each element's share of the energy this effect stores (zJ; a bond's or a pair's energy
  // split evenly between its two elements), for per-element outputs (VTK frames).
  virtual void addElementEnergies(const State& /*state*/, std::vector<double>& /*perElement*/) const {}

  // Contributions to the critical time step beyond the bonds' (stability.hpp): per element type.
  virtual void addStabilityTerms(std::vector<ContactStabilityTerms>& /*perType*/) const {}
  // Capabilities other parts of the engine may use (null when the effect has none).
  virtual const std::vector<Bond>* bondList() const { return nullptr; }
  // What each bond of bondList() carries in `state` (outputs), or nothing.
  virtual std::vector<BondLoad> bondLoads(const State& /*state*/) const { return {}; }
  virtual const ContactNeighbourhood* contactNeighbourhood() const { return nullptr; }

  // Evolving state that determines the future (tracked twist branches, dissipated work,
  // neighbour list), for checkpoints: what saveState writes, loadState reads back bit for bit.
  virtual void saveState(BinaryWriter& /*out*/) const {}
  virtual void loadState(BinaryReader& /*in*/) {}

  // All phases of this effect alone, serially, adding to state.bodies.force / torque at
  // state.time (tests and benchmarks that look at one effect).
  void addForces(State& state);
};

using EffectPtr = std::unique_ptr<Effect>;

}  // namespace mesochain::mdem
