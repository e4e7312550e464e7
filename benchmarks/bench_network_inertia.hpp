#pragma once
// `mesochain-bench network --bond-spectrum`, `--inertia-scales 1,4,16` and `--mass-scales 1,4,16`:
// what sets the mDEM time step and what rotational inertia scaling or mass (density) scaling
// ([run] rotational_inertia_scale, mass_scale; mdem/body.hpp) buys and changes
// (docs/benchmarks.md, "What sets the mDEM time step" and "Mass scaling").
#include <vector>

#include "mdem/scene.hpp"

namespace mesochain::app {

// Per scale: the bonds' Gershgorin bound against the true largest eigenfrequency of the bonded
// system (mdem/bond_spectrum.hpp), the mode's kinetic-energy shares, and the scene's critical
// step with its contacts and what limits it. Returns 0.
int printBondSpectrum(const mdem::Scene& scene, const std::vector<double>& scales, bool bodyFrame);

// Which inertia a scale multiplies: the moments alone, or mass and moments (on top of the
// scene's own rotational_inertia_scale).
enum class InertiaKnob { Rotational, Mass };

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

// Per scale (with critical_step = "gershgorin_body" when bodyFrame), without `pull`: critical and used step, outer ratio, element-steps/s, simulated ns per hour, the
// energy error without damping at that scale's own step; with `pull` instead, the stress-strain curve of
// the relax-and-pull protocol per scale, its RMS difference from the scene as given (scale 1), and
// that of a repeat of it with a perturbed start (the run-to-run scatter). Returns 0.
int printInertiaScaleCurve(const mdem::Scene& scene, InertiaKnob knob, const std::vector<double>& scales, bool bodyFrame,
                           double seconds, int threads, const PullProtocol& pull);

}  // namespace mesochain::app
