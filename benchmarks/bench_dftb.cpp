// Benchmarks of the DFTB engine.
// `mesochain-bench dftb`: time per energy+forces evaluation and the share of it spent in the
// LAPACK eigensolver, for (i) a (10,10) tube as a 2-atom helical cell with 800 kappa points and
// (ii) the 120-atom translational cell of a (30,30) tube with 20 kappa points; for (ii) also the
// time LAPACK's own drivers need, stand-alone on the same matrices, for the eigenpairs the
// evaluation uses (bench_dftb_lapack.cpp) and the share of the total spent in LAPACK.
// --compare-paths: every case with each eigenvector path forced (eigensolver.hpp), to place
// the size at which Automatic switches.
// `mesochain-bench kpoints`: error against time of the helical k-point count (accuracy knob),
// as a table, optionally CSV and a PNG (error vs kappa points and error vs time, log-log).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include "benchmarks/bench_dftb_lapack.hpp"
#include "app/cli/command.hpp"
#include "benchmarks/default_parameters.hpp"
#include "common/atomic_file.hpp"
#include "common/csv.hpp"
#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "common/units.hpp"
#include "dftb/band_solver.hpp"
#include "dftb/calculator.hpp"
#include "dftb/density_matrix.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::app {

namespace {
using Clock = std::chrono::steady_clock;

std::shared_ptr<const dftb::ParameterSet> carbon(const std::string& table) {
  return std::make_shared<const dftb::ParameterSet>(
      dftb::ParameterSet::load({"C"}, {{"C-C", table}}, "<bench>"));
}

dftb::Calculator calculator(const std::string& table, int nKappa, double kelvin,
                            dftb::EigenvectorPath path = dftb::EigenvectorPath::Automatic) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = nKappa;
  s.band.eigenvectors = path;
  s.band.electronicTemperature = kelvin * units::kBoltzmannHartreePerKelvin;
  return dftb::Calculator(carbon(table), s);
}

struct Timing {
  double perEvaluation = 0, eigensolver = 0, assembly = 0, density = 0, forces = 0, other = 0;
  double densityProducts = 0;  // the BLAS-3 part of `density` (zherk / dsyrk)
  // Each rank's process CPU seconds per evaluation (all its threads), rank order (one entry
  // without MPI); the largest is the critical path, less sensitive to other load on a shared
  // machine than the wall time.
  std::vector<double> cpuPerRank;
};

Timing timeEvaluations(const dftb::Calculator& calc, const objective::ObjectiveCell& cell,
                       int repeats) {
  calc.evaluate(cell, {true, true});  // warm-up
  Timing t;
  const std::clock_t cpu0 = std::clock();
  for (int r = 0; r < repeats; ++r) {
    const auto a = Clock::now();
    const dftb::Result res = calc.evaluate(cell, {true, true});
    t.perEvaluation += std::chrono::duration<double>(Clock::now() - a).count();
    t.eigensolver += res.extras.at("time_eigensolver");
    t.assembly += res.extras.at("time_assembly");
    t.density += res.extras.at("time_density");
    t.densityProducts += res.extras.at("time_density_products");
    t.forces += res.extras.at("time_forces");
  }
  for (double* x : {&t.perEvaluation, &t.eigensolver, &t.assembly, &t.density, &t.densityProducts,
                    &t.forces})
    *x /= repeats;
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC / repeats;
  t.cpuPerRank = calc.communicator().allgather({cpu});
  t.other = t.perEvaluation - t.eigensolver - t.assembly - t.density - t.forces;
  return t;
}

void report(const std::string& name, const Timing& t) {
  std::cout << fmt::format(
      "{:<44} {:9.4f} s/eval | eigensolver {:5.1f}% | assembly {:5.1f}% | density {:5.1f}% | "
      "forces {:5.1f}% | other {:5.1f}%\n",
      name, t.perEvaluation, 100 * t.eigensolver / t.perEvaluation,
      100 * t.assembly / t.perEvaluation, 100 * t.density / t.perEvaluation,
      100 * t.forces / t.perEvaluation, 100 * t.other / t.perEvaluation);
  if (!t.cpuPerRank.empty()) {
    std::string ranks;
    double sum = 0, most = 0;
    for (double c : t.cpuPerRank) {
      ranks += fmt::format(" {:.4f}", c);
      sum += c;
      most = std::max(most, c);
    }
    std::cout << fmt::format("  CPU s per evaluation by rank:{} | sum {:.4f} | largest {:.4f}\n",
                             ranks, sum, most);
  }
}

const char* pathName(dftb::EigenvectorPath p) {
  switch (p) {
    case dftb::EigenvectorPath::AllVectors: return "all vectors (heevd)";
    case dftb::EigenvectorPath::OccupiedOnly: return "occupied only (stedc)";
    default: return "automatic";
  }
}

int benchDftb(const std::string& table, int repeats, bool comparePaths) {
  std::cout << fmt::format("mesochain-bench dftb: {} MPI ranks x {} OpenMP threads, {} repeats, table {}\n",
                           parallel::Communicator::world().size(), omp_get_max_threads(), repeats,
                           table);
  const double bond = 1.42 * units::kAngstromInBohr;
  using dftb::EigenvectorPath;
  std::vector<EigenvectorPath> paths{EigenvectorPath::Automatic};
  if (comparePaths) paths = {EigenvectorPath::AllVectors, EigenvectorPath::OccupiedOnly};
  struct Case {
    std::string name;
    objective::ObjectiveCell cell;
    int nKappa;
  };
  std::vector<Case> cases;
  cases.push_back({"(10,10) helical 2 atoms, 800 kappa, 300 K", objective::buildNanotubeHelical(10, 10, bond), 800});
  if (comparePaths)
    for (int n : {5, 10, 15}) {
      auto cell = objective::buildNanotubeTranslational(n, n, bond, false);
      cases.push_back({fmt::format("({},{}) translational {} atoms, 20 kappa, 300 K", n, n,
                                   cell.atomCount()), cell, 20});
    }
  {
    auto cell = objective::buildNanotubeTranslational(30, 30, bond, false);
    cases.push_back({fmt::format("(30,30) translational {} atoms, 20 kappa, 300 K", cell.atomCount()),
                     cell, 20});
  }
  for (const Case& c : cases)
    for (EigenvectorPath p : paths) {
      const std::string name = comparePaths ? c.name + ", " + pathName(p) : c.name;
      const Timing t = timeEvaluations(calculator(table, c.nKappa, 300, p), c.cell, repeats);
      report(name, t);
      if (comparePaths || c.nKappa != 20) continue;
      // The stand-alone LAPACK reference on the same matrices (one thread).
      const auto params = carbon(table);
      const LapackReference ref =
          lapackReference(c.cell, *params, c.nKappa, 300 * units::kBoltzmannHartreePerKelvin, 3);
      std::cout << fmt::format(
          "  LAPACK alone, {} k-points of order {}, {} of {} eigenpairs used (one thread, best of 3):\n"
          "    zhegvd all pairs {:.4f} s | zhegvx used pairs {:.4f} s | faster per k-point {:.4f} s\n"
          "    total / LAPACK alone {:.2f} | share of the total in LAPACK (eigensolver) {:.1f}%, "
          "with the BLAS-3 density products {:.1f}%\n"
          "    zpotrf of S(k), reused by SCC iterations: {:.4f} s per evaluation\n",
          ref.kpoints, ref.orbitals, ref.vectorsUsed, ref.kpoints * ref.orbitals, ref.allPairs,
          ref.usedPairs, ref.best, t.perEvaluation / ref.best,
          100 * t.eigensolver / t.perEvaluation,
          100 * (t.eigensolver + t.densityProducts) / t.perEvaluation, ref.choleskyFactor);
      const dftb::BandGeometry geo(c.cell, *params, c.nKappa, objective::AngularSampling{});
      std::cout << fmt::format("    density blocks formed (BLAS-3): {:.1f}% of the n^2 elements\n",
                               100 * dftb::DensityBlockPlan(geo.layout, geo.images).fraction);
    }
  return 0;
}

// One convergence curve of the k-point benchmark.
struct KpointCurve {
  std::string name;
  std::vector<double> kappa, seconds, error;
};

// Two log-log panels side by side: |error| against kappa points and against time. An error of
// exactly zero (converged to the last bit) cannot sit on a log axis: it is left out and the
// legend says so.
void plotKpoints(const std::vector<KpointCurve>& curves, const std::string& path) {
  plot::Figure byCount("Free energy error per atom against kappa points");
  byCount.x.label = "helical kappa points";
  byCount.y.label = "|F - F(4096)| per atom (Ha)";
  byCount.x.scale = byCount.y.scale = plot::Scale::Log10;
  plot::Figure byTime("... and against time per evaluation");
  byTime.x.label = "seconds per energy evaluation (2-atom cell)";
  byTime.x.scale = plot::Scale::Log10;
  byTime.y = byCount.y;
  const plot::Marker markers[] = {plot::Marker::Circle, plot::Marker::Square, plot::Marker::Triangle,
                                  plot::Marker::Diamond};
  int i = 0;
  for (const KpointCurve& c : curves) {
    KpointCurve kept{c.name, {}, {}, {}};
    for (std::size_t k = 0; k < c.error.size(); ++k)
      if (c.error[k] > 0) {
        kept.kappa.push_back(c.kappa[k]);
        kept.seconds.push_back(c.seconds[k]);
        kept.error.push_back(c.error[k]);
      }
    const std::size_t zeros = c.error.size() - kept.error.size();
    const std::string name = zeros ? fmt::format("{} ({} exact zeros not shown)", c.name, zeros) : c.name;
    plot::SeriesStyle style;
    style.marker = markers[i++ % 4];
    style.dashed = c.name.find("30 K") != std::string::npos;
    byCount.add(name, kept.kappa, kept.error, style);
    byTime.add(name, kept.seconds, kept.error, style);
  }
  plot::writePng(path, plot::besideEachOther(byCount.render(900, 600, path), byTime.render(900, 600, path)));
  std::cout << "wrote " << path << "\n";
}

int benchKpoints(const std::string& table, const std::string& csv, std::string png) {
  // Error of the free energy per atom against the number of kappa points, and its cost, for a
  // metallic (10,10) and a semiconducting (10,0) tube; the reference is a 4x denser grid.
  const double bond = 1.42 * units::kAngstromInBohr;
  // The CSV is written (atomically) at the end; with --csv - it is the standard output and the
  // table goes to stderr.
  std::string out;
  if (!csv.empty()) {
    out = "tube,kelvin,kappa_points,seconds,free_energy_per_atom_hartree,abs_error_hartree\n";
    if (png.empty() && !isStandardOutput(csv))
      png = std::filesystem::path(csv).replace_extension(".png").string();
  }
  // Checked before the (minutes of) computation.
  if (!csv.empty()) requireWritableOutput(csv, "<command line>", "option --csv");
  if (!png.empty()) requireWritableOutput(png, "<command line>", "option --png");
  std::ostream& human = isStandardOutput(csv) ? std::cerr : std::cout;
  std::vector<KpointCurve> curves;
  human << fmt::format("{:<8} {:>7} {:>8} {:>12} {:>22} {:>12}\n", "tube", "T (K)", "kappa",
                           "seconds", "F per atom (Ha)", "|error| (Ha)");
  for (auto [n, m] : {std::pair{10, 10}, std::pair{10, 0}})
    for (double kelvin : {300.0, 30.0}) {
      const auto cell = objective::buildNanotubeHelical(n, m, bond);
      const double ref = calculator(table, 4096, kelvin).evaluate(cell, {}).freeEnergy / 2;
      const std::string tube = fmt::format("({},{})", n, m);
      KpointCurve& curve = curves.emplace_back();
      curve.name = fmt::format("{} {}, {:.0f} K", tube, n == m ? "metallic" : "semiconducting", kelvin);
      for (int nk : {8, 16, 32, 64, 128, 256, 512, 1024}) {
        const auto a = Clock::now();
        const double f = calculator(table, nk, kelvin).evaluate(cell, {}).freeEnergy / 2;
        const double s = std::chrono::duration<double>(Clock::now() - a).count();
        human << fmt::format("{:<8} {:>7.0f} {:>8} {:>12.5f} {:>22.12f} {:>12.3e}\n", tube, kelvin, nk, s, f,
                             std::abs(f - ref))
              << std::flush;
        if (!csv.empty())
          out += csvField(tube) + fmt::format(",{},{},{},{:.15g},{:.6e}\n", kelvin, nk, s, f, std::abs(f - ref));
        curve.kappa.push_back(nk);
        curve.seconds.push_back(s);
        curve.error.push_back(std::abs(f - ref));
      }
    }
  if (!csv.empty()) writeFileAtomically(csv, out);
  if (!png.empty()) plotKpoints(curves, png);
  return 0;
}
}  // namespace

Command makeBenchDftbCommand() {
  struct Opts {
    std::string table = defaultCarbonTable();
    int repeats = 3;
    bool comparePaths = false;
  };
  auto o = std::make_shared<Opts>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& bench) {
    auto* s = bench.add_subcommand("dftb", "time per energy+forces evaluation, eigensolver share");
    s->add_option("--table", o->table, "C-C Slater-Koster table");
    s->add_option("--repeats", o->repeats, "evaluations to average");
    s->add_flag("--compare-paths", o->comparePaths,
                "time every case with each eigenvector path forced (and more cell sizes)");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return benchDftb(o->table, o->repeats, o->comparePaths); };
  return c;
}

Command makeBenchKpointsCommand() {
  struct Opts {
    std::string table = defaultCarbonTable(), csv, png;
  };
  auto o = std::make_shared<Opts>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& bench) {
    auto* s = bench.add_subcommand("kpoints", "error against time of the helical k-point count");
    s->add_option("--table", o->table, "C-C Slater-Koster table");
    s->add_option("--csv", o->csv, "write the curve as CSV (- for the standard output)");
    s->add_option("--png", o->png,
                  "plot error vs kappa points and vs time (log-log) here (default with --csv: "
                  "the CSV path with .png)");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return benchKpoints(o->table, o->csv, o->png); };
  return c;
}

}  // namespace mesochain::app
