#include "benchmarks/bench_network_inertia.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include <fmt/format.h>
#include <omp.h>

#include "benchmarks/bench_network_mts.hpp"
#include "common/errors.hpp"
#include "mdem/bond_spectrum.hpp"
#include "mdem/run.hpp"
#include "mdem/simulation.hpp"
#include "mdem/stability.hpp"

namespace mesochain::app {

namespace {
mdem::Scene scaled(mdem::Scene s, double scale, bool bodyFrame, StepKnob knob = StepKnob::Rotational) {
  s.run.bodyFrameCriticalStep = bodyFrame;
  if (knob == StepKnob::Fraction) s.run.timeStepFraction = scale;
  else (knob == StepKnob::Mass ? s.run.massScale : s.run.rotationalInertiaScale) = scale;
  mdem::scaleInertia(s.bodies, s.elementTypes, s.run.massScale, s.run.rotationalInertiaScale);
  return s;
}

// Largest |E(t) - E(0)| per element and over the mean kinetic energy, without damping (bonds and
// vdw_contact), `steps` steps at the scene's own step and outer ratio, energy sampled every 8.
std::pair<double, double> energyDrift(mdem::Scene s, double h, int ratio, long steps) {
  if (ratio == 1) s.run.outerEffects.clear();
  const Accuracy a = conservativeRun(s, ratio, h, steps);
  return {a.energyError / s.bodies.size(), a.energyError / a.kinetic};
}

struct Curve {
  std::vector<double> binMean;  // stress (MPa) per strain bin
  double wallSeconds = 0.0, timeStep = 0.0;
  long steps = 0;
};

constexpr double kBin = 0.02;

// Relax (local damping) for protocol.relaxNs, then pull; the tensile CSV read back and binned.
Curve pullCurve(const mdem::Scene& base, const PullProtocol& p, const std::string& folder) {
  mdem::Scene s = base;
  std::vector<std::string> physical;
  for (const std::string& e : s.effects)
    if (e != "local_damping" && e != "viscous_damping") physical.push_back(e);
  s.effects = physical;
  const double h = mdem::Simulation(s).timeStep();
  mdem::StageSpec relax;
  relax.name = "relax", relax.steps = std::max(1L, std::lround(p.relaxNs / h)), relax.addEffects = {"local_damping"};
  relax.energiesCsv = "relax-energies.csv", relax.energiesEvery = 1000;
  mdem::StageSpec pull;
  pull.name = "pull", pull.tensileStage = true, pull.energiesCsv = "pull-energies.csv", pull.energiesEvery = 50;
  pull.steps = std::lround(2.0 * (p.finalStrain / p.strainRate + p.ramp) / h) + 10;
  pull.tensile.enabled = true, pull.tensile.gripWidth = p.gripWidth, pull.tensile.strainRate = p.strainRate;
  pull.tensile.ramp = p.ramp, pull.tensile.finalStrain = p.finalStrain, pull.tensile.csv = "pull-tensile.csv";
  s.stages = {pull};
  if (p.relaxNs > 0.0) s.stages.insert(s.stages.begin(), relax);
  s.output = mdem::OutputSpec{};
  s.output.checkpointMinutes = 0.0;
  s.output.energiesEvery = 100;
  mdem::RunOptions options;
  options.overwrite = true;
  std::filesystem::create_directories(folder);
  const auto t0 = std::chrono::steady_clock::now();
  const mdem::RunSummary summary = mdem::runScene(s, folder, [](double) {}, options);
  Curve c;
  c.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  c.timeStep = summary.timeStep, c.steps = summary.steps;
  const int bins = static_cast<int>(std::lround(p.finalStrain / kBin));
  std::vector<double> sum(bins, 0.0);
  std::vector<int> count(bins, 0);
  std::ifstream in(folder + "/pull-tensile.csv");
  if (!in) throw InputError(folder + "/pull-tensile.csv", "", "no tensile CSV", "the pull stage's CSV");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-')) continue;
    std::stringstream row(line);
    std::string field;
    double v[3];
    for (double& x : v) std::getline(row, field, ','), x = std::stod(field);
    const int b = static_cast<int>(std::floor(v[1] / kBin));
    if (b >= 0 && b < bins) sum[b] += v[2], ++count[b];
  }
  for (int b = 0; b < bins; ++b) c.binMean.push_back(count[b] ? sum[b] / count[b] : NAN);
  return c;
}

double rmsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    if (std::isfinite(a[k]) && std::isfinite(b[k])) s += (a[k] - b[k]) * (a[k] - b[k]), ++n;
  return n ? std::sqrt(s / n) : NAN;
}
}  // namespace

int printBondSpectrum(const mdem::Scene& scene, const std::vector<double>& scales, bool bodyFrame) {
  std::cout << fmt::format(
      "What sets the time step of {} ({} elements, {} bonds): per rotational inertia scale, the bonds' Gershgorin "
      "bound omega_G\n(stability.hpp, without contacts; translations in world axes, and in body axes: omega_Gb), the largest eigenfrequency of the linearised bonded system "
      "omega_true (dense, per filament),\nthe kinetic-energy shares of its mode (axial / transverse translation, "
      "torsion / bending rotation), and the scene's critical step\nwith its contacts (what limits it; the "
      "Gershgorin row that gives it).\n",
      scene.source, scene.bodies.size(), scene.bonds.size());
  std::cout << "scale  omega_G      omega_Gb     omega_true   G/true  Gb/true  G_row  2/omega_true_ns  shares ax/tr/tor/bend   critical_ns  "
               "h_ns        M  limited by\n";
  for (double scale : scales) {
    const mdem::Scene s = scaled(scene, scale, bodyFrame);
    const mdem::KinematicMap kin(s.boundary, s.bodies.size());
    const mdem::StabilityLimit g = mdem::criticalTimeStep(s.bodies, s.bonds, kin);
    const mdem::StabilityLimit gb = mdem::criticalTimeStep(s.bodies, s.bonds, kin, {}, mdem::GershgorinFrame::Body);
    const mdem::BondSpectrum b = mdem::bondSpectrum(s.bodies, s.bonds, kin);
    std::string sim;
    try {
      const mdem::Simulation run(s);
      const mdem::StabilityLimit& l = run.stability();
      sim = fmt::format("{:11.4g}  {:10.4g}  {:1d}  {} ({} of element {}, omega {:.4g}, beta {:.4g})", l.criticalTimeStep,
                        run.timeStep(), run.outerStepRatio(), l.limitedBy, l.rotational ? "rotation" : "translation",
                        l.element, l.omega, l.dampingRate);
    } catch (const InputError& e) {
      sim = std::string("refused: ") + e.what();
    }
    std::cout << fmt::format("{:5.3g}  {:11.5g}  {:11.5g}  {:11.5g}  {:6.3f}  {:7.3f}  {:5s}  {:15.4g}  {:.2f}/{:.2f}/{:.2f}/{:.2f}    {}\n",
                             scale, g.omegaMax, gb.omegaMax, b.omegaMax, g.omegaMax / b.omegaMax, gb.omegaMax / b.omegaMax,
                             g.rotational ? "rot" : "trans",
                             2.0 / b.omegaMax, b.mode.axial, b.mode.transverse, b.mode.torsion, b.mode.bendingRotation,
                             sim)
              << std::flush;
  }
  return 0;
}

int printInertiaScaleCurve(const mdem::Scene& scene, StepKnob knob, const std::vector<double>& scales, bool bodyFrame,
                           double seconds, int threads, const PullProtocol& pull) {
  omp_set_num_threads(threads);
  const int n = scene.bodies.size();
  const long driftSteps = 4000;
  std::cout << fmt::format(
      "{} on {} elements ({} threads; critical_step {}): per scale the scene's critical and used step "
      "(time_step_fraction {:.2g}), outer ratio M,\nthroughput, simulated ns per hour, and the energy error without "
      "damping (bonds + vdw_contact) over {} steps at that step: largest |E(t) - E(0)|\nper element and over the mean "
      "kinetic energy.\n",
      knob == StepKnob::Mass       ? fmt::format("Mass scaling (rotational_inertia_scale {:g} kept)", scene.run.rotationalInertiaScale)
      : knob == StepKnob::Fraction ? std::string("The time step's fraction of the critical step (scale: time_step_fraction)")
                                   : std::string("Rotational inertia scaling"),
      n, threads, bodyFrame ? "gershgorin_body" : "gershgorin", scene.run.timeStepFraction, driftSteps);
  std::cout << "scale  critical_ns  h_ns        M  element-steps/s  ns/hour   |dE|/element_zJ  |dE|/<K>\n";
  for (double scale : pull.enabled ? std::vector<double>{} : scales) {
    const mdem::Scene s = scaled(scene, scale, bodyFrame, knob);
    try {
      mdem::Simulation sim(s);
      const double rate = elementStepRate(sim, seconds);
      const auto [perElement, relative] = energyDrift(s, sim.timeStep(), sim.outerStepRatio(), driftSteps);
      std::cout << fmt::format("{:5.3g}  {:11.4g}  {:10.4g}  {:1d}  {:15.4g}  {:8.4g}  {:15.4g}  {:8.3g}\n", scale,
                               sim.stability().criticalTimeStep, sim.timeStep(), sim.outerStepRatio(), rate,
                               rate / n * sim.timeStep() * 3600.0, perElement, relative)
                << std::flush;
    } catch (const InputError& e) {
      std::cout << fmt::format("{:5.3g}  refused: {}\n", scale, e.what()) << std::flush;
    }
  }
  if (!pull.enabled) return 0;
  std::cout << fmt::format(
      "\nStress-strain: relax {:.4g} ns (local damping; 0: the scene as given, e.g. relaxed by --relax-ns), then pull at {:.3g}/ns to {:.3g} (grips {:.3g} nm, ramp {:.3g} "
      "ns);\nmean stress (MPa) per strain bin of {:.2g}; RMS difference from the first run; 'repeat' is the scene as given with "
      "every element moved by up to {:.3g} nm per axis.\n",
      pull.relaxNs, pull.strainRate, pull.finalStrain, pull.gripWidth, pull.ramp, kBin, pull.perturbation);
  const std::string root = (std::filesystem::temp_directory_path() / fmt::format("mesochain-inertia-{}", ::getpid())).string();
  // The reference: the scene as given (scale 1, its own critical_step); then its repeat, then the knobs.
  std::vector<std::pair<std::string, mdem::Scene>> runs;
  if (!pull.knobsOnly) {
    if (!pull.repeatOnly) runs.emplace_back("reference", scene);
    // Every element moved by a uniform random vector of up to `perturbation` per axis (fixed seed).
    mdem::Scene repeat = scene;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-pull.perturbation, pull.perturbation);
    for (mdem::Vec3& x : repeat.bodies.position) x += mdem::Vec3(u(gen), u(gen), u(gen));
    runs.emplace_back("repeat", repeat);
  }
  if (!pull.repeatOnly)
    for (double scale : scales)
      if (scale != (knob == StepKnob::Fraction ? scene.run.timeStepFraction : 1.0) || bodyFrame)
        runs.emplace_back(fmt::format("{}{:g}{}", knob == StepKnob::Mass ? "m" : knob == StepKnob::Fraction ? "f" : "", scale,
                                      bodyFrame ? "b" : ""),
                         scaled(scene, scale, bodyFrame, knob));
  std::vector<double> reference;
  for (const auto& [name, s] : runs) {
    const Curve c = pullCurve(s, pull, root + "/" + name);
    if (reference.empty()) reference = c.binMean;
    std::string bins;
    for (double v : c.binMean) bins += fmt::format(" {:6.2f}", v);
    std::cout << fmt::format("{:>9s}  h {:.4g} ns, {} steps, {:.0f} s:{}  rms {:.3g}\n", name, c.timeStep, c.steps,
                             c.wallSeconds, bins, rmsDifference(c.binMean, reference))
              << std::flush;
  }
  std::filesystem::remove_all(root);
  return 0;
}

}  // namespace mesochain::app
