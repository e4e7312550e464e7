#include "benchmarks/bench_network_mts.hpp"

#include <chrono>
#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <omp.h>

#include "common/errors.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::app {

std::pair<long, double> timedSteps(mdem::Simulation& sim, double seconds, long fixedSteps, int chunk) {
  long steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (fixedSteps > 0 ? steps < fixedSteps : elapsed < seconds) {
    sim.run(chunk);
    steps += chunk;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return {steps, elapsed};
}

double elementStepRate(mdem::Simulation& sim, double seconds) {
  sim.run(8);
  const auto [steps, elapsed] = timedSteps(sim, seconds, 0, 8);
  return static_cast<double>(steps) * sim.bodies().size() / elapsed;
}

Accuracy conservativeRun(mdem::Scene s, int ratio, double h, long steps) {
  std::vector<std::string> kept;
  for (const std::string& e : s.effects)
    if (e == "bonds" || e == "vdw_contact") kept.push_back(e);
  s.effects = kept;
  s.run.timeStep = h, s.run.timeStepFraction = 0.0, s.run.outerStepRatio = ratio;
  mdem::Simulation sim(s);
  Accuracy a;
  const double e0 = sim.energies().total();
  long samples = 0;
  for (long k = 0; k < steps; k += 8) {
    sim.run(8);
    const mdem::EnergyLedger e = sim.energies();
    a.energyError = std::max(a.energyError, std::abs(e.total() - e0));
    a.kinetic += sim.kineticEnergy(), ++samples;
  }
  a.kinetic /= std::max(1L, samples);
  a.positions = sim.bodies().position;
  return a;
}

int printOuterRatioCurve(const mdem::Scene& scene, const std::vector<int>& ratios, double seconds, int threads) {
  omp_set_num_threads(threads);
  const int n = scene.bodies.size();
  // The common inner step of the accuracy runs: the run fraction of the unsplit critical step.
  mdem::Scene unsplit = scene;
  unsplit.run.outerStepRatio = 1;
  const double hCommon = mdem::Simulation(unsplit).timeStep();
  const long accuracySteps = 4000;
  std::cout << fmt::format(
      "Multiple time stepping on {} elements ({} threads): vdw_contact every `ratio` steps, the other effects every "
      "step.\nThroughput at each ratio's own step (time_step_fraction {:.2g} of the inner critical step); accuracy "
      "without damping\n(bonds + vdw_contact) over {} steps of a common h = {:.4g} ns: largest |E(t) - E(0)| per "
      "element, over the mean kinetic energy, and the RMS\nposition difference from ratio 1 at the end.\n",
      n, threads, scene.run.timeStepFraction, accuracySteps, hCommon);
  std::cout << "ratio  h_ns        outer_ns    limit_ns    element-steps/s  ns/hour    |dE|/element_zJ  |dE|/<K>    "
               "rms_dx_nm\n";
  std::vector<mdem::Vec3> reference;
  for (int ratio : ratios) {
    mdem::Scene s = scene;
    s.run.outerStepRatio = ratio;
    try {
      mdem::Simulation sim(s);
      const double rate = elementStepRate(sim, seconds);
      const double nsPerHour = rate / n * sim.timeStep() * 3600.0;
      // The accuracy run at the common step (refused when the ratio does not fit the limit).
      std::string accuracy = "(outer step above the limit at the common h)";
      if (ratio * hCommon <= sim.outerStability().criticalTimeStep || ratio == 1) {
        const Accuracy a = conservativeRun(scene, ratio, hCommon, accuracySteps);
        if (ratio == 1) reference = a.positions;
        double dx2 = 0.0;
        if (!reference.empty())
          for (int i = 0; i < n; ++i) dx2 += (a.positions[i] - reference[i]).squaredNorm();
        accuracy = fmt::format("{:15.4g}  {:9.3g}  {:10.3g}", a.energyError / n, a.energyError / a.kinetic,
                               reference.empty() ? NAN : std::sqrt(dx2 / n));
      }
      std::cout << fmt::format("{:5d}  {:10.4g}  {:10.4g}  {:10.4g}  {:15.4g}  {:9.4g}  {}\n", sim.outerStepRatio(),
                               sim.timeStep(), sim.outerStepRatio() * sim.timeStep(),
                               sim.outerStability().criticalTimeStep, rate, nsPerHour, accuracy)
                << std::flush;
    } catch (const InputError& e) {
      std::cout << fmt::format("{:5d}  refused: {}\n", ratio, e.what()) << std::flush;
    }
  }
  return 0;
}

}  // namespace mesochain::app
