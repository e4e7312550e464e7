#pragma once
// Runs a loaded scene with its outputs: the loop the `mesochain dem` command drives.
#include <functional>
#include <string>

#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {

struct RunSummary {
  long steps = 0;
  double time = 0.0;             // ns
  bool stoppedByCriterion = false;
  EnergyLedger finalEnergies;
  double timeStep = 0.0;
  double criticalTimeStep = 0.0;
  bool dissipatedTracked = false;  // the scene has contact dashpots
  bool tensile = false;            // [tensile]: strain and engineering stress (MPa)
  double initialStress = 0.0, finalStrain = 0.0, finalStress = 0.0, peakStress = 0.0;
};

// Progress callback receives the fraction of the maximum step count done.
RunSummary runScene(const Scene& scene, const std::string& outputDirectory,
                    const std::function<void(double)>& progress);

}  // namespace mesochain::mdem
