// `mesochain-bench dem`: element-steps per second of bonded filaments (10^4 and 10^5 elements
// in total), on 1 thread and on OpenMP threads; `--lammps PREFIX` writes the same filaments for
// LAMMPS's bpm/rotational (bench/lammps/in.chain-bpm).
//
// Instructions per element-step: run with a fixed step count under callgrind, e.g.
//   valgrind --tool=callgrind build/mesochain-bench dem --totals 10000 --threads 1 --repeats 1 --steps 20
// The measured steps are dumped as their own profile part (callgrind.out.PID.1, from the
// client requests below: stats zeroed before and dumped after the timed run), so its total Ir
// divided by the printed element-step count is the cost per element-step without start-up.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define MESOCHAIN_CALLGRIND_BEGIN() CALLGRIND_ZERO_STATS
#define MESOCHAIN_CALLGRIND_END() CALLGRIND_DUMP_STATS_AT("measured steps")
#else
#define MESOCHAIN_CALLGRIND_BEGIN()
#define MESOCHAIN_CALLGRIND_END()
#endif

#include "app/cli/command.hpp"
#include "mdem/lammps_export.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::app {

namespace {
struct BenchOptions {
  std::vector<int> totals{10000, 100000};
  int filamentLength = 100;
  int threads = 2;
  double seconds = 2.0;
  long steps = 0;   // > 0: a fixed number of steps per measurement (for callgrind) instead of time
  int repeats = 3;  // measurements per case; the median is printed
  bool bondsOnly = false;  // without local damping: the work of LAMMPS's bpm/rotational peer
  std::string lammps;      // prefix of the LAMMPS export (then nothing is timed)
};

mdem::Scene benchScene(int total, int perFilament, bool bondsOnly) {
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
  s.effects = bondsOnly ? std::vector<std::string>{"bonds"} : std::vector<std::string>{"bonds", "local_damping"};
  s.run.timeStepFraction = 0.5;
  return s;
}

// CPU time of each OpenMP worker thread (libgomp keeps the same pool threads from region to
// region, so differences over a run are the CPU each thread spent on it).
std::vector<double> threadCpuSeconds() {
  std::vector<double> t(omp_get_max_threads(), 0.0);
#pragma omp parallel
  {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    t[omp_get_thread_num()] = ts.tv_sec + 1e-9 * ts.tv_nsec;
  }
  return t;
}

// Element-steps per second of wall time, and per second of the busiest thread's CPU time (what
// the wall rate would be if each thread had a core to itself: on a shared machine the wall
// rate mostly measures the other processes).
struct Rates {
  double wall, cpu;
};

Rates measureOnce(const mdem::Scene& scene, double seconds, long fixedSteps) {
  mdem::Simulation sim(scene);
  sim.run(10);  // warm-up
  long steps = 0;
  const std::vector<double> cpu0 = threadCpuSeconds();
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  if (fixedSteps > 0) {
    MESOCHAIN_CALLGRIND_BEGIN();
    sim.run(fixedSteps);
    MESOCHAIN_CALLGRIND_END();
    steps = fixedSteps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  // Runs of about 10^6 element-steps: one OpenMP region each (see mdem/stepper.hpp).
  const long chunk = std::max(1L, 1000000L / std::max(1, scene.bodies.size()));
  while (fixedSteps <= 0 && elapsed < seconds) {
    sim.run(chunk);
    steps += chunk;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  const std::vector<double> cpu1 = threadCpuSeconds();
  double busiest = 0.0;
  for (std::size_t k = 0; k < cpu0.size(); ++k) busiest = std::max(busiest, cpu1[k] - cpu0[k]);
  const double work = static_cast<double>(steps) * scene.bodies.size();
  return {work / elapsed, work / busiest};
}

// Medians and spread of repeated measurements (the machine may be shared).
struct Measured {
  double median, low, high, cpuMedian;
};
Measured measure(const mdem::Scene& scene, const BenchOptions& o) {
  std::vector<double> wall, cpu;
  for (int k = 0; k < std::max(1, o.repeats); ++k) {
    const Rates r = measureOnce(scene, o.seconds, o.steps);
    wall.push_back(r.wall);
    cpu.push_back(r.cpu);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], wall.front(), wall.back(), cpu[cpu.size() / 2]};
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
    (*dem)->add_option("--steps", opt->steps, "fixed steps per measurement instead of --seconds");
    (*dem)->add_option("--repeats", opt->repeats, "measurements per case (median printed)");
    (*dem)->add_flag("--bonds-only", opt->bondsOnly,
                     "bonds alone, without the local damping (the work of LAMMPS's bpm/rotational peer)");
    (*dem)->add_option("--lammps", opt->lammps,
                       "write PREFIX-<elements>.data/.settings for bench/lammps/in.chain-bpm and exit");
  };
  c.selected = [dem] { return *dem && (*dem)->parsed(); };
  c.run = [opt] {
    if (!opt->lammps.empty()) {
      for (int total : opt->totals) {
        const mdem::Scene s = benchScene(total, opt->filamentLength, opt->bondsOnly);
        const mdem::Simulation sim(s);
        const std::string prefix = fmt::format("{}-{}", opt->lammps, total);
        mdem::writeLammpsBpmChains(s, sim.timeStep(), prefix);
        std::cout << fmt::format("wrote {}.data and {}.settings (time step {:.6g} ns)\n", prefix, prefix,
                                 sim.timeStep());
      }
      return 0;
    }
    std::cout << "element-steps per second: wall clock (median, min .. max of the repeats) and per\n"
                 "CPU second of the busiest thread (median)\n"
                 "elements  filaments  threads      wall/s  min .. max                 cpu/s\n";
    for (int total : opt->totals) {
      const mdem::Scene s = benchScene(total, opt->filamentLength, opt->bondsOnly);
      const int filaments = (total + opt->filamentLength - 1) / opt->filamentLength;
      std::vector<int> threadCounts{1};
      if (opt->threads != 1) threadCounts.push_back(opt->threads);
      for (int threads : threadCounts) {
        omp_set_num_threads(threads);
        const Measured m = measure(s, *opt);
        std::cout << fmt::format("{:8d}  {:9d}  {:7d}  {:10.4g}  {:<10.4g} .. {:<10.4g}  {:10.4g}\n",
                                 total, filaments, threads, m.median, m.low, m.high, m.cpuMedian)
                  << std::flush;
        if (opt->steps > 0)
          std::cout << fmt::format("  element-steps per measurement: {} ({} steps x {} elements)\n",
                                   opt->steps * static_cast<long>(s.bodies.size()), opt->steps,
                                   s.bodies.size());
      }
    }
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
