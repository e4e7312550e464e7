// `mesochain-bench network`: element-steps per second of random tube networks with van der
// Waals contacts and dashpots (10^4 and 10^5 elements), on 1 thread and on OpenMP threads, with
// the shares of time in the neighbour search and in the contact kernels; with --kernel-curve, the
// accuracy-against-cost curve of the anisotropic contact kernel over the pairs of the network
// (docs/benchmarks.md, "mDEM networks").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include "benchmarks/bench_network_coarsen.hpp"
#include "benchmarks/bench_network_inertia.hpp"
#include "benchmarks/bench_network_kernel.hpp"
#include "benchmarks/bench_network_mts.hpp"
#include "benchmarks/bench_network_skin.hpp"
#include "app/cli/command.hpp"
#include "common/errors.hpp"
#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/contacts/network_generator.hpp"
#include "mdem/contacts/network_structure.hpp"
#include "mdem/contacts/vdw_contact.hpp"
#include "mdem/contacts/vdw_kernel_isa.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/lammps_export.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/simulation.hpp"
#include "mdem/units.hpp"

namespace mesochain::app {

namespace {
struct NetworkBenchOptions {
  std::vector<int> totals{10000, 100000};
  int tubeLength = 25;
  int threads = 2;
  double seconds = 3.0;
  long steps = 0;       // > 0: fixed step count instead of --seconds (callgrind)
  bool isotropic = false;
  bool effectsCost = false;  // also: the same network with fewer named effects (1 thread)
  std::string lammps;   // prefix of the LAMMPS export (then nothing is timed)
  bool kernelCurve = false;  // the accuracy-against-cost curve of the anisotropic kernel
  int kernelPoints = 0;      // > 0: only this rule, --kernel-repeat times (callgrind)
  int kernelRepeat = 20;
  std::string kernelPath = "table";  // "table" (one lookup of D per point) or "line" (three of H)
  std::string kernelIsa = "cpu";     // "cpu" (the version the CPU supports) or "baseline" (SSE2 copy)
  std::vector<int> outerRatios;      // non-empty: the multiple-time-stepping curve and exit
  std::string scene;                 // a scene file instead of the generated networks
  double relaxNs = 0.0;              // > 0: relax (local damping) this long first, then measure
  std::string relaxedState;          // with relaxNs: the relaxed state's checkpoint, read if present
  std::string stateFromRun;          // a `mesochain dem` checkpoint of the --scene file's run: its elements' state
  std::string coarsenTo;             // with --scene: a scene whose element type is twice as long (bench_network_coarsen.hpp)
  bool coarsenRelaxed = false;       // coarsen after --relax-ns (the relaxed film), not before
  std::vector<double> skins;         // --skins: the Verlet skin's cost (bench_network_skin.hpp)
  long skinCheckSteps = 400;
  double alignedWindow = -1.0;       // >= 0: [vdw_contact] aligned_window_deg for the measurement
  int quadraturePoints = 0;          // > 0: [vdw_contact] quadrature_points after the relaxation (--relax-ns)
  int crossingPoints = 0;            // > 0: [vdw_contact] crossing_quadrature_points (as --quadrature-points; and --kernel-points)
  bool bondSpectrum = false;         // what sets the time step (bench_network_inertia.hpp) and exit
  std::vector<double> inertiaScales; // non-empty: the rotational-inertia-scaling table and exit
  std::vector<double> massScales;    // non-empty: the same for mass (density) scaling
  std::vector<double> stepFractions; // non-empty: the same for time_step_fraction
  PullProtocol pull;                 // with inertiaScales: the stress-strain comparison
  std::string criticalStep;  // [run] critical_step of the scaled runs ("": the scene's own)
};

mdem::Scene networkScene(int total, int perTube, bool isotropic) {
  mdem::Scene s;
  mdem::ElementType t;
  t.name = "cnt1010", t.shape = mdem::Shape::Cylinder, t.radius = 0.678, t.length = 2.0, t.mass = 325 * 1.9945e-5;
  s.elementTypes.push_back(t);
  mdem::BondType b;
  b.name = "cnt", b.fromModuli = true, b.youngModulus = 1e6, b.shearModulus = 0.4e6;
  s.bondTypes.push_back(b);
  mdem::NetworkSpec n;
  n.tubes = total / perTube, n.elementsPerTube = perTube;
  // A film of 3 layers at ~6 % footprint coverage per layer (random sequential placement).
  const double area = n.tubes * perTube * 2.0 * (2 * 0.678 + 0.3) / (3 * 0.06);
  n.size = mdem::Vec3(std::sqrt(area), std::sqrt(area), 2 * (2 * 0.678 + 0.3));
  n.waviness = 0.1, n.seed = 7;
  mdem::generateNetwork(s, n);
  s.contacts.vdw.lj = {2.84e-3 * mdem::units::kElectronvolt, 0.34, 38.2};
  s.contacts.vdw.anisotropic = !isotropic;
  s.contacts.damping.translational = 1.0;
  s.effects = {"bonds", "vdw_contact", "contact_damping", "local_damping"};
  s.run.timeStepFraction = 0.3;
  return s;
}

struct Measurement {
  double rate = 0.0;
  // Shares of the profiled pass's wall time (NaN under --steps, which runs no profiled pass).
  double neighbourShare = std::nan(""), contactShare = std::nan("");
  long pairs = 0;
};

// The rate comes from an unprofiled pass: with the stepper's phase timing on, one thread runs the
// phase-by-phase scheme instead of the block sweep (mdem/stepper.cpp), not the production path. The
// shares come from a second, profiled pass of the same length (not run under --steps, so that a
// callgrind count holds only the production path).
Measurement measure(const mdem::Scene& scene, double seconds, long fixedSteps) {
  mdem::Simulation sim(scene);
  sim.run(5);  // warm-up
  Measurement m;
  const auto [steps, elapsed] = timedSteps(sim, seconds, fixedSteps, 5);  // 5: --steps is a multiple of 5
  m.rate = static_cast<double>(steps) * scene.bodies.size() / elapsed;
  if (fixedSteps <= 0) {
    mdem::PhaseTimes phases;  // the stepper's own phase timing (dem --profile)
    sim.setProfile(&phases);
    const double profiled = timedSteps(sim, seconds, 0, 5).second;
    sim.setProfile(nullptr);
    m.contactShare = (phases["items vdw_contact"] + phases["gather vdw_contact"]) / profiled;
    m.neighbourShare = (phases["prepare vdw_contact"] + phases["prepare contact_damping"]) / profiled;
  }
  m.pairs = sim.contactNeighbourhood() ? static_cast<long>(sim.contactNeighbourhood()->list().pairs().size()) : 0;
  return m;
}
// Contacts (wall gap < 0.5 nm) and aligned contacts (< 10 degrees) per element, listed pairs per
// element and the largest bundle of the current state of `sim`.
std::string contactSummary(const mdem::Simulation& sim) {
  const mdem::ContactNeighbourhood* nb = sim.contactNeighbourhood();
  if (!nb) return "no contacts named";
  const mdem::Bodies& b = sim.state().bodies;
  const mdem::NetworkStructure n = mdem::networkStructure(*nb, b, 0.5, 10.0 * mdem::units::kPi / 180.0, 0);
  const double e = b.size();
  return fmt::format("{:.3f} contacts, {:.3f} aligned, {:.3f} listed pairs per element; largest bundle {} elements",
                     n.contacts / e, n.aligned / e, nb->list().pairs().size() / e, n.largestBundle);
}

// The bundled case: the scene relaxed for `ns` with local damping (alpha of the scene, added when
// not named), its final positions, orientations and velocities taken as the new start.
// With `statePath`, a checkpoint of that relaxed state is read when the file exists (the same scene
// and time: callgrind need not relax) and written otherwise.
mdem::Scene relaxedScene(mdem::Scene s, double ns, const std::string& statePath) {
  if (std::find(s.effects.begin(), s.effects.end(), "local_damping") == s.effects.end())
    s.effects.push_back("local_damping");
  mdem::Simulation sim(s);
  if (!statePath.empty() && std::filesystem::exists(statePath)) {
    mdem::CheckpointFile(statePath, s).restore(sim);
    std::cout << fmt::format("relaxed state read from {} (t = {:.4g} ns): {}\n", statePath, sim.time(), contactSummary(sim));
    s.bodies = sim.state().bodies;
    return s;
  }
  const long steps = std::max(1L, std::lround(ns / sim.timeStep()));
  std::cout << fmt::format("relaxing {} elements for {:.4g} ns ({} steps of {:.4g} ns, local damping {:.3g})\n  before: {}\n",
                           s.bodies.size(), ns, steps, sim.timeStep(), s.localDampingAlpha, contactSummary(sim))
            << std::flush;
  const auto t0 = std::chrono::steady_clock::now();
  for (long done = 0; done < steps;) {
    const long chunk = std::min(steps - done, (steps + 9) / 10);
    sim.run(chunk);
    done += chunk;
    std::cout << fmt::format("  {:3.0f} %  t = {:.4g} ns  {:.0f} s\n", 100.0 * done / steps, sim.time(),
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count())
              << std::flush;
  }
  std::cout << "  after:  " << contactSummary(sim) << "\n";
  if (!statePath.empty()) mdem::writeCheckpoint(statePath, s, sim, [](mdem::BinaryWriter&) {}, [](mdem::BinaryWriter&) {});
  s.bodies = sim.state().bodies;
  return s;
}

// The promise "an effect not named costs nothing" measured: the same network (same bodies and
// bonds) with the contact effects named or not. A scene that does not name them builds no
// neighbour list and no contact loop, so it runs at the bonded-chain rate of `bench dem`.
void printEffectsCost(const NetworkBenchOptions& o) {
  omp_set_num_threads(1);
  mdem::Scene s = networkScene(o.totals.front(), o.tubeLength, o.isotropic);
  const std::vector<std::vector<std::string>> lists{{"bonds", "local_damping"},
                                                    {"bonds", "vdw_contact", "local_damping"},
                                                    {"bonds", "vdw_contact", "contact_damping", "local_damping"}};
  std::cout << fmt::format("\nthe same {} elements with fewer named effects, 1 thread:\n", s.bodies.size());
  double base = 0.0;
  for (const auto& list : lists) {
    s.effects = list;
    mdem::Simulation sim(s);
    const double rate = elementStepRate(sim, o.seconds);
    if (base == 0.0) base = rate;
    std::string names;
    for (const auto& e : list) names += (names.empty() ? "" : " + ") + e;
    std::cout << fmt::format("  {:<52s} {:10.4g} element-steps/s  ({:.2f} of the first)\n", names, rate,
                             rate / base)
              << std::flush;
  }
}

// --scene, coarsened to --coarsen-to's elements when given.
// With --state-from-run, the elements start where that run's checkpoint has them.
mdem::Scene sceneFile(const NetworkBenchOptions& o) {
  mdem::Scene s = mdem::loadScene(o.scene);
  if (!o.stateFromRun.empty()) {
    const mdem::CheckpointState st = mdem::readCheckpointState(s, o.stateFromRun);
    s.bodies = st.bodies;
    const mdem::Simulation sim(s);
    std::cout << fmt::format("state of the run's checkpoint {} (stage {}, step {}, t = {:.4g} ns): {}\n", o.stateFromRun,
                             st.stage, st.step, st.time, contactSummary(sim));
  }
  return o.coarsenTo.empty() || o.coarsenRelaxed ? s : coarsenedFilm(s, o.coarsenTo);
}

// The scene of the kernel curve: the generated network, or --scene (relaxed with --relax-ns).
mdem::Scene curveScene(const NetworkBenchOptions& o) {
  if (o.scene.empty()) return networkScene(o.totals.front(), o.tubeLength, false);
  mdem::Scene s = sceneFile(o);
  return o.relaxNs > 0.0 ? relaxedScene(std::move(s), o.relaxNs, o.relaxedState) : s;
}

}  // namespace

Command makeBenchNetworkCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<NetworkBenchOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& bench) {
    *sub = bench.add_subcommand("network", "mDEM element-steps per second for tube networks with contacts");
    (*sub)->add_option("--totals", opt->totals, "total element counts");
    (*sub)->add_option("--tube-length", opt->tubeLength, "elements per tube");
    (*sub)->add_option("--threads", opt->threads, "OpenMP threads of the parallel run");
    (*sub)->add_option("--seconds", opt->seconds, "time per measurement");
    (*sub)->add_option("--skins", opt->skins,
                       "[contacts] skin_nm values: listed pairs, list builds, rate and neighbour-search share per skin, "
                       "and whether each skin's trajectory is the first one's bit for bit, and exit")
        ->delimiter(',')
        ->check(CLI::Range(1e-3, 10.0));
    (*sub)->add_option("--skin-check-steps", opt->skinCheckSteps, "with --skins: steps of the trajectory comparison")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--steps", opt->steps, "fixed number of steps per measurement (multiple of 5; for callgrind)");
    (*sub)->add_flag("--isotropic", opt->isotropic, "isotropic (central) contact form instead of the anisotropic one");
    (*sub)->add_flag("--effects-cost", opt->effectsCost,
                     "also time the same network without the contact effects named (1 thread)");
    (*sub)->add_option("--lammps", opt->lammps,
                       "write PREFIX-<elements>.data/.table/.settings for bench/lammps/in.network and exit");
    (*sub)->add_flag("--kernel-curve", opt->kernelCurve,
                     "accuracy against cost of the anisotropic kernel (Gauss points, quadrature tolerance) and exit");
    (*sub)->add_option("--kernel-points", opt->kernelPoints,
                       "with --kernel-curve: only this many Gauss points, --kernel-repeat times (for callgrind)");
    (*sub)->add_option("--kernel-repeat", opt->kernelRepeat, "with --kernel-points: evaluations of every pair");
    (*sub)->add_option("--crossing-quadrature-points", opt->crossingPoints,
                       "[vdw_contact] crossing_quadrature_points: with --kernel-points, and for the runs of "
                       "--inertia-scales, --mass-scales or --step-fractions as --quadrature-points")
        ->check(CLI::Range(2, 64));
    (*sub)->add_option("--outer-ratios", opt->outerRatios,
                       "multiple time stepping: throughput and accuracy at these outer/inner step ratios, and exit")
        ->delimiter(',')
        ->check(CLI::Range(1, 64));
    (*sub)->add_flag("--bond-spectrum", opt->bondSpectrum,
                     "the bonds' Gershgorin bound against the true largest eigenfrequency and its mode, per "
                     "--inertia-scales (default 1), and exit");
    (*sub)->add_option("--inertia-scales", opt->inertiaScales,
                       "rotational inertia scaling: step, throughput, ns/hour and energy error per scale, and exit")
        ->delimiter(',')
        ->check(CLI::Range(1.0, 1e4));
    (*sub)->add_option("--mass-scales", opt->massScales,
                       "mass (density) scaling on top of the scene's rotational_inertia_scale: the same table (or "
                       "--pull curves) per scale, and exit")
        ->delimiter(',')
        ->check(CLI::Range(1.0, 1e4))
        ->excludes("--inertia-scales")
        ->excludes("--bond-spectrum");
    (*sub)->add_option("--step-fractions", opt->stepFractions,
                       "[run] time_step_fraction: the same table (or --pull curves) per fraction of the critical step, "
                       "and exit")
        ->delimiter(',')
        ->check(CLI::Range(0.01, 1.0))
        ->excludes("--inertia-scales")
        ->excludes("--mass-scales")
        ->excludes("--bond-spectrum");
    (*sub)->add_option("--critical-step", opt->criticalStep,
                       "with --inertia-scales / --mass-scales / --step-fractions / --bond-spectrum: [run] critical_step of the runs "
                       "(default: the scene's own)")
        ->check(CLI::IsMember({"gershgorin", "gershgorin_body"}));
    (*sub)->add_flag("--pull", opt->pull.enabled,
                     "with --inertia-scales, --mass-scales or --step-fractions: the stress-strain curves instead of the table (pull at 1/ns to 30 % from "
                     "the scene, after --relax-ns if given; a repeat of the scene as given with a perturbed start)");
    (*sub)->add_option("--pull-rate-per-ns", opt->pull.strainRate, "with --pull: the strain rate (default 1/ns)")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--pull-final-strain", opt->pull.finalStrain, "with --pull: the final strain (default 0.3)")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--pull-ramp-ns", opt->pull.ramp, "with --pull: the grips' velocity ramp (default 0.02 ns)")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--quadrature-points", opt->quadraturePoints,
                       "with --inertia-scales, --mass-scales or --step-fractions: the vdW kernel's Gauss points from "
                       "the relaxed state on (the relaxation keeps the scene's)")
        ->check(CLI::Range(2, 64));
    (*sub)->add_flag("--pull-knobs-only", opt->pull.knobsOnly,
                     "with --pull: only the scaled runs, without the reference and its repeat (another process)");
    (*sub)->add_flag("--pull-repeat-only", opt->pull.repeatOnly, "with --pull: only the perturbed repeat of the scene");
    (*sub)->add_option("--pull-perturbation-nm", opt->pull.perturbation,
                       "with --pull: the repeat moves every element by up to this per axis (default 1e-6)")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--pull-relax-ns", opt->pull.relaxNs,
                       "with --pull: relax each run this long with local damping before its pull")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--scene", opt->scene,
                       "a scene file (e.g. a deposited film) instead of the generated networks: its bodies, effects "
                       "and [run] time step")
        ->check(CLI::ExistingFile);
    (*sub)->add_option("--coarsen-to", opt->coarsenTo,
                       "with --scene: the same film with the element and bond type of this scene file, elements twice "
                       "as long (pairs of consecutive elements merged; docs/benchmarks.md, \"The element length\")")
        ->check(CLI::ExistingFile);
    (*sub)->add_flag("--coarsen-relaxed", opt->coarsenRelaxed,
                     "with --coarsen-to and --inertia-scales: coarsen the film after --relax-ns (one relaxed state for both "
                     "lengths) instead of before");
    (*sub)->add_option("--relax-ns", opt->relaxNs,
                       "relax the network or scene for this long first (local damping; the bundled case), then measure")
        ->check(CLI::PositiveNumber);
    (*sub)->add_option("--relaxed-state", opt->relaxedState,
                       "with --relax-ns: checkpoint of the relaxed state, read when it exists, else written");
    (*sub)->add_option("--state-from-run", opt->stateFromRun,
                       "with --scene: start from the state in this checkpoint of a `mesochain dem` run of that scene "
                       "(e.g. a film relaxed for nanoseconds: RUN/checkpoint.mdem)")
        ->check(CLI::ExistingFile);
    (*sub)->add_option("--aligned-window", opt->alignedWindow,
                       "[vdw_contact] aligned_window_deg of the measured runs (after any relaxation); with "
                       "--kernel-points: the aligned path's window")
        ->check(CLI::Range(0.0, 10.0));
    (*sub)->add_option("--kernel-path", opt->kernelPath, "with --kernel-points: table (D, one lookup) or line (H, three)")
        ->check(CLI::IsMember({"table", "line"}));
    (*sub)->add_option("--kernel-isa", opt->kernelIsa,
                       "the vdW table kernel's loop: cpu (AVX2 where the CPU has it) or baseline (SSE2), to compare")
        ->check(CLI::IsMember({"cpu", "baseline"}));
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    const bool knob = !opt->inertiaScales.empty() || !opt->massScales.empty() || !opt->stepFractions.empty();
    if (opt->quadraturePoints > 0 && !knob)
      throw InputError("<command line>", "option --quadrature-points", "without a step knob",
                       "--inertia-scales, --mass-scales or --step-fractions as well (it applies to their runs)");
    if (opt->crossingPoints > 0 && !knob && !(opt->kernelCurve && opt->kernelPoints > 0))
      throw InputError("<command line>", "option --crossing-quadrature-points", "without a step knob or --kernel-points",
                       "--inertia-scales, --mass-scales or --step-fractions, or --kernel-curve --kernel-points, as well");
    mdem::forceBaselineVdwKernel(opt->kernelIsa == "baseline");
    std::cout << "vdW table kernel: "
              << (mdem::vdwKernelIsa() == mdem::VdwKernelIsa::Avx2 ? "AVX2" : "baseline (SSE2)") << "\n";
    if (opt->kernelCurve) {
      KernelCurveOptions k;
      k.points = opt->kernelPoints, k.repeat = opt->kernelRepeat, k.path = opt->kernelPath;
      k.alignedWindow = opt->alignedWindow, k.seconds = opt->seconds, k.crossingPoints = opt->crossingPoints;
      return printKernelCurve(curveScene(*opt), k);
    }
    if (opt->bondSpectrum || !opt->inertiaScales.empty() || !opt->massScales.empty() || !opt->stepFractions.empty()) {
      mdem::Scene s =
          opt->scene.empty() ? networkScene(opt->totals.front(), opt->tubeLength, opt->isotropic) : sceneFile(*opt);
      if (opt->relaxNs > 0.0) s = relaxedScene(std::move(s), opt->relaxNs, opt->relaxedState);
      if (opt->coarsenRelaxed && !opt->coarsenTo.empty()) s = coarsenedFilm(s, opt->coarsenTo);
      if (opt->quadraturePoints > 0) s.contacts.vdw.quadraturePoints = opt->quadraturePoints;
      if (opt->crossingPoints > 0) s.contacts.vdw.crossingQuadraturePoints = opt->crossingPoints;
      const bool mass = !opt->massScales.empty(), fraction = !opt->stepFractions.empty();
      const std::vector<double> given = mass ? opt->massScales : fraction ? opt->stepFractions : opt->inertiaScales;
      const std::vector<double> scales = given.empty() ? std::vector<double>{1.0} : given;
      const bool body = opt->criticalStep.empty() ? s.run.bodyFrameCriticalStep : opt->criticalStep == "gershgorin_body";
      if (opt->bondSpectrum) return printBondSpectrum(s, scales, body);
      const StepKnob knob = mass ? StepKnob::Mass : fraction ? StepKnob::Fraction : StepKnob::Rotational;
      return printInertiaScaleCurve(s, knob, scales, body, opt->seconds, opt->threads, opt->pull);
    }
    if (!opt->skins.empty()) {
      mdem::Scene s =
          opt->scene.empty() ? networkScene(opt->totals.front(), opt->tubeLength, opt->isotropic) : sceneFile(*opt);
      if (opt->relaxNs > 0.0) s = relaxedScene(std::move(s), opt->relaxNs, opt->relaxedState);
      return printSkinCurve(s, opt->skins, opt->seconds, opt->threads, opt->skinCheckSteps);
    }
    if (!opt->outerRatios.empty()) {
      mdem::Scene s =
          opt->scene.empty() ? networkScene(opt->totals.front(), opt->tubeLength, opt->isotropic) : sceneFile(*opt);
      if (opt->relaxNs > 0.0) s = relaxedScene(std::move(s), opt->relaxNs, opt->relaxedState);
      return printOuterRatioCurve(s, opt->outerRatios, opt->seconds, opt->threads);
    }
    if (!opt->lammps.empty()) {
      for (int total : opt->totals) {
        const mdem::Scene s = networkScene(total, opt->tubeLength, true);
        const mdem::Simulation sim(s);
        const std::string prefix = fmt::format("{}-{}", opt->lammps, s.bodies.size());
        mdem::writeLammpsNetwork(s, sim.timeStep(), prefix);
        std::cout << fmt::format("{}.data, .table, .settings: {} elements, time step {:.4g} ns\n", prefix,
                                 s.bodies.size(), sim.timeStep());
      }
      return 0;
    }
    std::vector<mdem::Scene> scenes;
    if (!opt->scene.empty()) scenes.push_back(sceneFile(*opt));
    else
      for (int total : opt->totals) scenes.push_back(networkScene(total, opt->tubeLength, opt->isotropic));
    if (opt->relaxNs > 0.0)
      for (mdem::Scene& s : scenes) s = relaxedScene(std::move(s), opt->relaxNs, opt->relaxedState);
    if (opt->alignedWindow >= 0.0)
      for (mdem::Scene& s : scenes) s.contacts.vdw.alignedWindowDegrees = opt->alignedWindow;
    std::cout << "elements  tubes  pairs     threads  element-steps/s  neighbour-search  vdw-contact (items + gather, first thread)\n";
    for (const mdem::Scene& s : scenes) {
      // Tubes: elements minus bonds for chains (a filament of n elements has n - 1 bonds).
      const int tubes = s.bodies.size() - static_cast<int>(s.bonds.size());
      std::vector<int> threadCounts{1};
      if (opt->threads != 1) threadCounts.push_back(opt->threads);
      for (int threads : threadCounts) {
        omp_set_num_threads(threads);
        const Measurement m = measure(s, opt->seconds, opt->steps);
        const auto share = [](double x) { return std::isnan(x) ? std::string("-") : fmt::format("{:.1f}%", 100 * x); };
        std::cout << fmt::format("{:8d}  {:5d}  {:8d}  {:7d}  {:15.4g}  {:>16}  {:>14}\n", s.bodies.size(), tubes, m.pairs,
                                 threads, m.rate, share(m.neighbourShare), share(m.contactShare))
                  << std::flush;
      }
    }
    if (opt->effectsCost) printEffectsCost(*opt);
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
