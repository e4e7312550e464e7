// `mesochain bench dem`: element-steps per second of bonded filaments (10^4 and 10^5 elements
// in total), on 1 thread and on OpenMP threads.
#include <chrono>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include "app/commands.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::app {

namespace {
struct BenchOptions {
  std::vector<int> totals{10000, 100000};
  int filamentLength = 100;
  int threads = 2;
  double seconds = 2.0;
};

mdem::Scene benchScene(int total, int perFilament) {
  mdem::Scene s;
  mdem::ElementType t;
  t.name = "brick", t.thickness = 0.8, t.width = 2.4, t.length = 2.0, t.mass = 0.01;
  s.elementTypes.push_back(t);
  mdem::BondType b;
  b.name = "cnt", b.fromModuli = true, b.youngModulus = 1e6, b.shearModulus = 0.4e6;
  s.bondTypes.push_back(b);
  for (int placed = 0, k = 0; placed < total; placed += perFilament, ++k) {
    mdem::FilamentSpec f;
    f.count = std::min(perFilament, total - placed);
    f.start = {5.0 * (k % 100), 5.0 * (k / 100), 0.0};
    mdem::addFilament(s, f);
  }
  // Small random-looking initial velocities so that the kernels do real work.
  for (int i = 0; i < s.bodies.size(); ++i) {
    s.bodies.velocity[i] = 0.01 * mdem::Vec3(std::sin(1.3 * i), std::cos(0.7 * i), std::sin(0.3 * i));
    s.bodies.setAngularVelocityWorld(i, 0.01 * mdem::Vec3(std::cos(1.1 * i), std::sin(0.9 * i), 0.5));
  }
  s.effects = {"bonds", "local_damping"};
  s.run.timeStepFraction = 0.5;
  return s;
}

double measure(const mdem::Scene& scene, double seconds) {
  mdem::Simulation sim(scene);
  sim.run(10);  // warm-up
  long steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < seconds) {
    sim.run(10);
    steps += 10;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return static_cast<double>(steps) * scene.bodies.size() / elapsed;
}
}  // namespace

Command makeBenchDemCommand() {
  auto dem = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<BenchOptions>();
  Command c;
  c.attach = [dem, opt](CLI::App& bench) {
    *dem = bench.add_subcommand("dem", "mDEM element-steps per second for bonded filaments");
    (*dem)->add_option("--totals", opt->totals, "total element counts");
    (*dem)->add_option("--filament-length", opt->filamentLength, "elements per filament");
    (*dem)->add_option("--threads", opt->threads, "OpenMP threads of the parallel run");
    (*dem)->add_option("--seconds", opt->seconds, "time per measurement");
  };
  c.selected = [dem] { return *dem && (*dem)->parsed(); };
  c.run = [opt] {
    std::cout << "elements  filaments  threads  element-steps/s\n";
    for (int total : opt->totals) {
      const mdem::Scene s = benchScene(total, opt->filamentLength);
      const int filaments = (total + opt->filamentLength - 1) / opt->filamentLength;
      for (int threads : {1, opt->threads}) {
        omp_set_num_threads(threads);
        std::cout << fmt::format("{:8d}  {:9d}  {:7d}  {:.4g}\n", total, filaments, threads,
                                 measure(s, opt->seconds))
                  << std::flush;
      }
    }
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
