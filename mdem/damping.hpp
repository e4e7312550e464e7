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
#include "mdem/effect.hpp"

namespace mesochain::mdem {

class LocalDamping : public Effect {
 public:
  explicit LocalDamping(double alpha) : alpha_(alpha) {}
  std::string name() const override { return "local_damping"; }
  EffectRole role() const override { return EffectRole::NumericalDamping; }
  void gather(const State& state, double, int lo, int hi, Vec3* force, Vec3* torque) const override {
    for (int i = lo; i < hi; ++i) dampElement(state.bodies, i, force[i], torque[i]);
  }
  // Damps the force / torque of element i (the sum of the other effects on it).
  void dampElement(const Bodies& s, int i, Vec3& force, Vec3& torque) const;
  void reportEnergy(const State&, EnergyLedger&) const override {}

 private:
  double alpha_;
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
