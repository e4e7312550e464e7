#pragma once
// Boundary conditions: fixed degrees of freedom, applied loads and prescribed motions.
// Fixed DOFs and prescribed motions are kinematic: the integrator overwrites the velocities
// after each half kick (KinematicMap::apply). Loads are an effect (LoadEffect, registered as "loads"),
// built whenever the scene has loads.
#include <array>
#include <vector>

#include "mdem/effect.hpp"

namespace mesochain::mdem {

// DOF order: x, y, z (translation), rx, ry, rz (rotation about the world axes).
// Fixed translations may move at a prescribed velocity (the grips of a tensile test):
// v_d(t) = velocity_d * min(1, (t - start) / ramp) on each fixed translation d (0 by default:
// held; start is the time the stage that set the grips began).
struct FixedDofs {
  int element = -1;
  std::array<bool, 6> fixed{};
  Vec3 velocity = Vec3::Zero();  // nm/ns
  double ramp = 0.0;             // ns
  double start = 0.0;            // ns: the ramp starts here (the grips of a later stage)
  bool allRotationsFixed() const { return fixed[3] && fixed[4] && fixed[5]; }
};

struct Load {
  int element = -1;
  Vec3 force = Vec3::Zero();   // pN
  Vec3 moment = Vec3::Zero();  // pN nm
  // false: fixed world direction; true: follows the element (given in the world frame at t = 0,
  // then carried with the element's orientation).
  bool following = false;
  double ramp = 0.0;  // ns; the load grows linearly from 0 over this time
};

// A prescribed motion takes all 6 DOFs of the element.
//  * velocity mode: v(t) = velocity * r(t), omega(t) = angularVelocity * r(t), with
//    r(t) = min(1, t / ramp) (r = 1 if ramp = 0);
//  * displacement mode (duration > 0): moves by `translateBy` and turns by `rotateBy`
//    (rotation vector, world frame, any angle) over `duration` with the smooth profile
//    v(t) = translateBy / T (1 - cos(2 pi t / T)), zero velocity and acceleration at both
//    ends; afterwards the element is held.
struct Prescribed {
  int element = -1;
  Vec3 velocity = Vec3::Zero();         // nm/ns
  Vec3 angularVelocity = Vec3::Zero();  // rad/ns
  double ramp = 0.0;                    // ns
  Vec3 translateBy = Vec3::Zero();      // nm
  Vec3 rotateBy = Vec3::Zero();         // rad
  double duration = 0.0;                // ns (> 0 selects the displacement mode)

  Vec3 velocityAt(double t) const;
  Vec3 angularVelocityAt(double t) const;
};

struct Boundary {
  std::vector<FixedDofs> fixed;
  std::vector<Load> loads;
  std::vector<Prescribed> prescribed;
};

// Fixed rotational DOFs are velocity constraints on the world angular velocity: omega_d = 0 for
// every fixed axis d, at all times (so the rotation probe integral of omega_d dt stays 0). The
// constraint acts by impulses along the fixed world axes only: after each kick the free world
// components of the angular momentum L = I_w omega (I_w = R diag(I) R^T) are kept and the fixed
// components of omega are zeroed, omega = P (P^T I_w P)^{-1} P^T L with P the free axes
// (constrainedAngularVelocity). The orientation then advances kinematically,
// q <- exp(h omega) q. With one free axis e this is the exact hinge: the body turns about e only,
// q(t) = exp(phi e) q(0), with the constant moment of inertia e^T I_w e, whether or not e is a
// principal axis. With two free axes the constraint is non-holonomic (finite rotations about
// x and y compose to some rotation about z; only the angular velocity about z is zero).
//
// Per element of the map: kinematicRotation = 1 when some rotation is fixed or prescribed (the
// orientation is then advanced by exp(h omega_world) instead of the free rotor).
struct KinematicMap {
  std::vector<const FixedDofs*> fixed;         // per element or nullptr
  std::vector<const Prescribed*> prescribed;   // per element or nullptr
  std::vector<char> kinematicRotation;         // per element

  KinematicMap(const Boundary& b, int elementCount);
  bool constrained(int i) const { return fixed[i] || prescribed[i]; }
  // Overwrites constrained velocities for time t (after a half kick), of one element or all.
  // Inline test first: the stepper calls it twice per element-step, and most elements are free.
  void applyElement(Bodies& s, int i, double t) const {
    if (constrained(i)) applyConstrained(s, i, t);
  }
  void apply(Bodies& s, double t) const;
  // Zeroes force / torque components on fixed and prescribed DOFs (for reporting and for the
  // damping, which must see the unbalanced force only), of one element or all.
  void clearElement(int i, Vec3& force, Vec3& torque) const {
    if (constrained(i)) clearConstrained(i, force, torque);
  }
  void clearConstrainedForces(Bodies& s) const;

 private:
  void applyConstrained(Bodies& s, int i, double t) const;
  void clearConstrained(int i, Vec3& force, Vec3& torque) const;
};

// World angular velocity of element i with the rotational DOFs `fixed[3..5]` locked, from its
// current angular momentum (see above).
Vec3 constrainedAngularVelocity(const Bodies& s, int i, const std::array<bool, 6>& fixed);

class LoadEffect : public Effect {
 public:
  LoadEffect(std::vector<Load> loads, const Bodies& initial);
  std::string name() const override { return "loads"; }
  void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const override {
    for (int i = lo; i < hi; ++i)
      if (start_[i] < start_[i + 1]) addToElement(state.bodies, i, time, force[i], torque[i]);
  }
  // Entry "load_potential".
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  // Adds the loads on element i at `time` to force / torque (in load order).
  void addToElement(const Bodies& s, int i, double time, Vec3& force, Vec3& torque) const;

 private:
  std::vector<Load> loads_;
  std::vector<Vec3> forceBody_, momentBody_;  // following loads in the body frame
  // Loads by element: order_[start_[i] .. start_[i+1]) index loads_; elements with loads.
  std::vector<int> start_, order_, loadedElements_;
};

}  // namespace mesochain::mdem
