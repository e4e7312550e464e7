#pragma once
// Numerical damping effects (EffectRole::NumericalDamping). Both act on the force already
// accumulated by the conservative effects and loads, so they are registered last (order 500).
//
// "local_damping" (Cundall's local non-viscous damping, as in PFC; Potyondy & Cundall 2004,
// eq. 8): per degree of freedom F_i -= alpha |F_i| sign(v_i), M_i -= alpha |M_i| sign(omega_i).
// Translations use world components; rotations use the body (principal-axis) components, the
// natural DOFs of the rotation integrator. alpha in [0, 1), dimensionless.
//
// "viscous_damping": F -= gamma m v, M_body -= gamma I omega_body (gamma in 1/ns): a uniform
// mass-proportional drag.
//
// Either may charge its work into the energy ledger (`track_work`, TrackedDamping below).
#include <optional>
#include <vector>

#include "mdem/boundary.hpp"
#include "mdem/effect.hpp"
#include "mdem/kick_work.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

// The work a numerical damping takes, charged when asked (`track_work`), for both kinds below,
// as the dashpots charge theirs (kick_work.hpp): P = -(D.v + T.w) summed over the elements in
// order, D and T the damping's force and world torque as applied (the components the
// kinematics clear again, boundary.hpp, left out). Reported as the ledger entry NAME_dissipated
// (EnergyKind::Dissipated). Off by default: it needs a serial phase per step, which also takes
// a bonded-chain scene off the stepper's barrier-free filament partition.
// `Damping` provides name() and dampElement(bodies, i, force, torque).
template <class Damping>
class TrackedDamping : public Effect {
 public:
  TrackedDamping(bool trackWork, const Scene& scene);
  EffectRole role() const override { return EffectRole::NumericalDamping; }
  void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const override;
  bool hasFinish() const override { return track_; }
  void finish(const State& state, double time) override;
  bool wantsStepVelocities() const override { return track_; }
  void kickForcesReplaced(const State& state) override;
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  void saveState(BinaryWriter& out) const override;
  void loadState(BinaryReader& in) override;

 private:
  bool track_ = false;
  // Per element, from the last gather (written by the thread that owns the element's block):
  // the damping's force and world torque as applied and its power at the velocities it was
  // formed with.
  mutable std::vector<Vec3> dampForce_, dampTorque_;
  mutable std::vector<double> itemPower_;
  // The scene's fixed and prescribed components, which the stepper clears (with track_work).
  std::optional<KinematicMap> kinematics_;
  KickWork work_;
  double powerAtItemVelocities() const;
};

class LocalDamping : public TrackedDamping<LocalDamping> {
 public:
  LocalDamping(double alpha, bool trackWork, const Scene& scene) : TrackedDamping(trackWork, scene), alpha_(alpha) {}
  std::string name() const override { return "local_damping"; }
  // Damps the force / torque of element i (the sum of the other effects on it).
  void dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const;

 private:
  double alpha_;
};

class ViscousDamping : public TrackedDamping<ViscousDamping> {
 public:
  ViscousDamping(double rate, bool trackWork, const Scene& scene) : TrackedDamping(trackWork, scene), rate_(rate) {}
  std::string name() const override { return "viscous_damping"; }
  void dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const;

 private:
  double rate_;
};

extern template class TrackedDamping<LocalDamping>;
extern template class TrackedDamping<ViscousDamping>;

}  // namespace mesochain::mdem
