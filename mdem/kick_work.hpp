#pragma once
// The work a dissipative force takes in velocity Verlet, charged as the kicks apply it (the
// contact dashpots, contacts/contact_effects.hpp; numerical damping with track_work,
// damping.hpp). The forces F of the force evaluation at time t enter two half kicks,
// (h/2) F.(v(t - h/2) + v(t))/2 + (h/2) F.(v(t) + v(t + h/2))/2 = h P(v(t)), P(v) = -F.v, with
// v(t) the velocities between the stepper's fused half kicks (State::stepVelocity). The charge
// is booked whole at t; the part of its second half kick, which comes with the next step,
// (h/4)(3 P(v(t)) - P(v(t - h/2))), is held back from the reported work, so that grip work -
// dissipated = change of the energy holds at every output to the integrator's own O(h^2) (tests
// GripWorkMinusDissipated*). Forces evaluated anew outside a step (a new simulation, a stage
// boundary) replace the last step's: their held-back share leaves the work, and their own
// opening half kick is charged at the next step as (h/2) P at their velocities.
namespace mesochain::mdem {

struct KickWork {
  double dissipated = 0.0, lastTime = 0.0, pending = 0.0;
  double opening = 0.0;  // P of forces evaluated outside a step, at their velocities

  // The step since the last call (0 or less: no step, nothing to charge) ; records `time`.
  double stepTo(double time) {
    const double h = time - lastTime;
    lastTime = time;
    return h;
  }
  // One force evaluation's charge: `now` = P(v(t)), `atItems` = P at the velocities the forces
  // were formed with, v(t - h/2).
  void charge(double h, double now, double atItems) {
    dissipated += h * now + 0.5 * h * opening;
    opening = 0.0;
    pending = 0.25 * h * (3.0 * now - atItems);
  }
  // The forces were evaluated anew outside a step; `atItems` = their P at their velocities.
  void forcesReplaced(double atItems) {
    dissipated -= pending;
    pending = 0.0;
    opening = atItems;
  }
  // The work taken up to the kicks applied so far.
  double reported() const { return dissipated - pending; }
};

}  // namespace mesochain::mdem
