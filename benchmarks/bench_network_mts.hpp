#pragma once
// `mesochain-bench network --outer-ratios 1,2,4,8`: what multiple time stepping (the ratio of
// the contacts' outer step to the bonds' inner step, mdem/stepper.hpp) costs and changes on a
// network: throughput at each ratio's own time step, and, at one common inner step, the energy
// error without damping and the trajectory's deviation from the unsplit run
// (docs/benchmarks.md, "multiple time stepping").
#include <utility>
#include <vector>

#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::app {

// Runs `sim` `chunk` steps at a time until `fixedSteps` steps are done (> 0) or `seconds` of wall
// time have passed; returns the steps and the wall time (the benches' one timing loop).
std::pair<long, double> timedSteps(mdem::Simulation& sim, double seconds, long fixedSteps, int chunk);

// Element-steps per second of wall time of `sim` over `seconds`, after a warm-up of 8 steps.
double elementStepRate(mdem::Simulation& sim, double seconds);

struct Accuracy {
  double energyError = 0.0;  // largest |E(t) - E(0)|, zJ
  double kinetic = 0.0;      // mean kinetic energy over the samples, zJ
  std::vector<mdem::Vec3> positions;
};

// Without damping (the conservative effects only: bonds and vdw_contact), `steps` steps of h at
// outer ratio `ratio`, energy sampled every 8.
Accuracy conservativeRun(mdem::Scene s, int ratio, double h, long steps);

// `scene` names its effects and time_step_fraction; ratios that exceed the contacts' own
// critical step are reported as refused. Returns 0.
int printOuterRatioCurve(const mdem::Scene& scene, const std::vector<int>& ratios, double seconds, int threads);

}  // namespace mesochain::app
