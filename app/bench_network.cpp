// `mesochain bench network`: element-steps per second of random tube networks with van der
// Waals contacts and dashpots (10^4 and 10^5 elements), on 1 thread and on OpenMP threads, with
// the shares of time in the neighbour search and in the contact kernels.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include "app/bench_network_lammps.hpp"
#include "app/commands.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/contacts/network_generator.hpp"
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
  double rate = 0.0, neighbourShare = 0.0, contactShare = 0.0;
  long pairs = 0;
};

Measurement measure(const mdem::Scene& scene, double seconds, long fixedSteps) {
  mdem::Simulation sim(scene);
  sim.run(5);  // warm-up
  auto* vdw = dynamic_cast<mdem::VdwContactEffect*>(sim.effect("vdw_contact"));
  const double nb0 = vdw->neighbourSeconds();
  vdw->seconds = 0.0;
  long steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (fixedSteps > 0 ? steps < fixedSteps : elapsed < seconds) {
    sim.run(5);
    steps += 5;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  Measurement m;
  m.rate = static_cast<double>(steps) * scene.bodies.size() / elapsed;
  m.contactShare = vdw->seconds / elapsed;
  m.neighbourShare = (vdw->neighbourSeconds() - nb0) / elapsed;
  m.pairs = vdw->pairCount();
  return m;
}
// Element-steps per second of wall time of any scene (no effect required).
double stepRate(const mdem::Scene& scene, double seconds) {
  mdem::Simulation sim(scene);
  sim.run(5);
  long steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < seconds) {
    sim.run(5);
    steps += 5;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return static_cast<double>(steps) * scene.bodies.size() / elapsed;
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
    const double rate = stepRate(s, o.seconds);
    if (base == 0.0) base = rate;
    std::string names;
    for (const auto& e : list) names += (names.empty() ? "" : " + ") + e;
    std::cout << fmt::format("  {:<52s} {:10.4g} element-steps/s  ({:.2f} of the first)\n", names, rate,
                             rate / base)
              << std::flush;
  }
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
    (*sub)->add_option("--steps", opt->steps, "fixed number of steps per measurement (multiple of 5; for callgrind)");
    (*sub)->add_flag("--isotropic", opt->isotropic, "isotropic (central) contact form instead of the anisotropic one");
    (*sub)->add_flag("--effects-cost", opt->effectsCost,
                     "also time the same network without the contact effects named (1 thread)");
    (*sub)->add_option("--lammps", opt->lammps,
                       "write PREFIX-<elements>.data/.table/.settings for bench/lammps/in.network and exit");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    if (!opt->lammps.empty()) {
      for (int total : opt->totals) {
        const mdem::Scene s = networkScene(total, opt->tubeLength, true);
        const mdem::Simulation sim(s);
        const std::string prefix = fmt::format("{}-{}", opt->lammps, s.bodies.size());
        writeLammpsNetwork(s, sim.timeStep(), prefix);
        std::cout << fmt::format("{}.data, .table, .settings: {} elements, time step {:.4g} ns\n", prefix,
                                 s.bodies.size(), sim.timeStep());
      }
      return 0;
    }
    std::cout << "elements  tubes  pairs     threads  element-steps/s  neighbour-search  contact-forces\n";
    for (int total : opt->totals) {
      const mdem::Scene s = networkScene(total, opt->tubeLength, opt->isotropic);
      for (int threads : {1, opt->threads}) {
        omp_set_num_threads(threads);
        const Measurement m = measure(s, opt->seconds, opt->steps);
        std::cout << fmt::format("{:8d}  {:5d}  {:8d}  {:7d}  {:15.4g}  {:15.1f}%  {:13.1f}%\n", s.bodies.size(),
                                 total / opt->tubeLength, m.pairs, threads, m.rate, 100 * m.neighbourShare,
                                 100 * m.contactShare)
                  << std::flush;
      }
    }
    if (opt->effectsCost) printEffectsCost(*opt);
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
