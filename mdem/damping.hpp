#pragma once
// Numerical damping effects (EffectRole::NumericalDamping). Both act on the force already
// accumulated by the conservative effects and loads, so they are registered last (order 500).
//
// "local_damping" (Cundall's local non-viscous damping, as in PFC; Potyondy & Cundall 2004,
// eq. 8): per degree of freedom F_i -= alpha |F_i| sign(v_i), M_i -= alpha |M_i| sign(omega_i).
// Translations use world components; rotations use the body (principal-axis) components, the
// natural DOFs of the rotation integrator. alpha in [0, 1), dimensionless. With track_work its
// work enters the energy ledger (below); the viscous damping's does not (yet).
//
// "viscous_damping": F -= gamma m v, M_body -= gamma I omega_body (gamma in 1/ns): a uniform
// mass-proportional drag.
#include <array>
#include <vector>

#include "mdem/effect.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

class LocalDamping : public Effect {
 public:
  // trackWork: charge the work the damping takes ([local_damping] track_work; off by default,
  // since it needs a serial phase per step, which also takes a bonded-chain scene off the
  // barrier-free filament partition). `scene` gives the element count and the constrained
  // components, whose damping the kinematics clear again (boundary.hpp).
  LocalDamping(double alpha, bool trackWork, const Scene& scene);
  std::string name() const override { return "local_damping"; }
  EffectRole role() const override { return EffectRole::NumericalDamping; }
  void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const override;
  // Damps the force / torque of element i (the sum of the other effects on it).
  void dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const;
  bool hasFinish() const override { return track_; }
  void finish(const State& state, double time) override;
  bool wantsStepVelocities() const override { return track_; }
  void kickForcesReplaced(const State& state) override;
  // With track_work: "local_damping_dissipated" (EnergyKind::Dissipated); else nothing.
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  void saveState(BinaryWriter& out) const override;
  void loadState(BinaryReader& in) override;

 private:
  double alpha_;
  bool track_ = false;
  // Per element, from the last gather (written by the thread that owns the element's block):
  // the damping's force and world torque as applied (constrained components cleared) and its
  // power at the velocities it was formed with.
  mutable std::vector<Vec3> dampForce_, dampTorque_;
  mutable std::vector<double> itemPower_;
  std::vector<std::array<bool, 6>> cleared_;  // components the kinematics clear, per element
  // The work as the dashpots charge theirs (contact_effects.hpp): h P(v(t)) per force
  // evaluation, P = -(D.v + T.w) over the elements in order, the second half kick's share held
  // back (pending_) until it is taken, the opening half kick of forces evaluated outside a step
  // charged at the next finish (opening_).
  double dissipated_ = 0.0, lastTime_ = 0.0, pending_ = 0.0, opening_ = 0.0;
  double powerAtItemVelocities() const;
};

class ViscousDamping : public Effect {
 public:
  explicit ViscousDamping(double rate) : rate_(rate) {}
  std::string name() const override { return "viscous_damping"; }
  EffectRole role() const override { return EffectRole::NumericalDamping; }
  void gather(const State& state, double, int lo, int hi, Vec3* force, Vec3* torque) const override {
    for (int i = lo; i < hi; ++i) dampElement(state.bodies, i, force[i], torque[i]);
  }
  void dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const;
  void reportEnergy(const State&, EnergyLedger&) const override {}

 private:
  double rate_;
};

}  // namespace mesochain::mdem
