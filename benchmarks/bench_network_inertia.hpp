#pragma once
// `mesochain-bench network --bond-spectrum`, `--inertia-scales 1,4,16`, `--mass-scales 1,4,16` and
// `--step-fractions 0.3,0.5,0.7,0.9`: what sets the mDEM time step and what rotational inertia
// scaling, mass (density) scaling ([run] rotational_inertia_scale, mass_scale; mdem/body.hpp) or
// the step's fraction of the critical step ([run] time_step_fraction) buy and change
// (docs/benchmarks.md, "What sets the mDEM time step", "Mass scaling", "The time step fraction").
#include <vector>

#include "mdem/scene.hpp"

namespace mesochain::app {

// Per scale: the bonds' Gershgorin bound against the true largest eigenfrequency of the bonded
// system (mdem/bond_spectrum.hpp), the mode's kinetic-energy shares, and the scene's critical
// step with its contacts and what limits it. Returns 0.
int printBondSpectrum(const mdem::Scene& scene, const std::vector<double>& scales, bool bodyFrame);

// What a value of the table sets: the scale of the moments alone, or of mass and moments (on top
// of the scene's own rotational_inertia_scale), or the time step's fraction of the critical step.
enum class StepKnob { Rotational, Mass, Fraction };

struct PullProtocol {
  bool enabled = false;
  double relaxNs = 0.0;        // relaxation with local damping before each pull (simulated time; 0: none)
  double strainRate = 1.0;     // 1/ns
  double finalStrain = 0.3;
  double gripWidth = 15.0;     // nm
  double ramp = 0.02;          // ns
  double perturbation = 1e-6;  // nm: the repeat of scale 1 with every element moved by up to this per axis
  bool knobsOnly = false;      // only the scaled runs (reference and repeat in another process)
  bool repeatOnly = false;     // only the repeat
};

// Per value of the knob ("scale" below; with critical_step = "gershgorin_body" when bodyFrame), without `pull`: critical and used step, outer ratio, element-steps/s, simulated ns per hour, the
// energy error without damping at that scale's own step; with `pull` instead, the stress-strain curve of
// the relax-and-pull protocol per scale, its RMS difference from the scene as given (scale 1), and
// that of a repeat of it with a perturbed start (the run-to-run scatter). Returns 0.
int printInertiaScaleCurve(const mdem::Scene& scene, StepKnob knob, const std::vector<double>& scales, bool bodyFrame,
                           double seconds, int threads, const PullProtocol& pull);

}  // namespace mesochain::app
