// `mesochain-bench scan [--csv FILE]`: how a fitted stiffness and its time change with the
// helical k-points and the relaxation tolerance, for small tubes (2-atom helical cells).
// The stiffness is the curvature of the quadratic through three scan points
// (E(-h), E(0), E(+h)): C = (E+ + E- - 2 E0) / h^2 per slice of length T0 (N_a helical cells) (stretch, h = 0.5 %)
// and K likewise for twist (h = 0.25 degrees per cell). Each row runs the whole scan: the T0
// search of the reference and the two deformed points, each relaxed to the tolerance. The
// error is relative to 1024 k-points at 1e-7 Ha/Bohr.
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/command.hpp"
#include "benchmarks/default_parameters.hpp"
#include "common/atomic_file.hpp"
#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/drivers/scan.hpp"

namespace mesochain::app {

namespace {

struct Row {
  std::string tube, kind;
  int kpoints = 0;
  double tolerance = 0, stiffness = 0, seconds = 0;
  int evaluations = 0;
};

Row runOne(const std::string& table, int n, int m, objective::ScanKind kind, int kpoints,
           double tolerance) {
  auto params = std::make_shared<const dftb::ParameterSet>(
      dftb::ParameterSet::load({"C"}, {{"C-C", table}}, "<bench>"));
  dftb::CalculatorSettings cs;
  cs.band.helicalKPoints = kpoints;
  cs.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
  objective::ScanSettings s;
  s.kind = kind;
  const double h = kind == objective::ScanKind::Stretch ? 0.005 : 0.25 * units::kDegree;
  s.values = {-h, h};
  s.relax.forceTolerance = tolerance;
  s.relax.axialTolerance = tolerance;
  s.relax.relaxTranslation = true;
  s.progressBar = false;
  const auto cell = objective::buildNanotubeHelical(n, m, 1.42 * units::kAngstromInBohr);
  const auto start = std::chrono::steady_clock::now();
  const objective::ScanResult r = objective::runScan(cell, params, cs, s);
  Row row;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  row.tube = fmt::format("({},{})", n, m);
  row.kind = objective::scanKindName(kind);
  row.kpoints = kpoints;
  row.tolerance = tolerance;
  row.stiffness = r.cellsPerSlice *
                  (r.points[0].energy + r.points[2].energy - 2 * r.points[1].energy) / (h * h);
  for (const auto& p : r.points) row.evaluations += p.evaluations;
  return row;
}

int benchScan(const std::string& table, const std::string& csv) {
  if (!csv.empty()) requireWritableOutput(csv, "<command line>", "option --csv");  // before the scans
  std::vector<Row> rows;
  std::ostream& human = isStandardOutput(csv) ? std::cerr : std::cout;  // --csv -: the CSV on stdout
  human << "stiffness per slice of length T0 from a 3-point quadratic; error against 1024 "
               "k-points at 1e-7 Ha/Bohr\n";
  human << fmt::format("{:7} {:8} {:>6} {:>9} {:>16} {:>10} {:>8} {:>6}\n", "tube", "kind", "k",
                           "tol", "stiffness [Ha]", "rel.error", "time[s]", "evals");
  for (auto [n, m] : std::vector<std::pair<int, int>>{{5, 5}, {10, 0}})
    for (auto kind : {objective::ScanKind::Stretch, objective::ScanKind::Twist}) {
      const Row ref = runOne(table, n, m, kind, 1024, 1e-7);
      std::vector<Row> set;
      for (int k : {16, 32, 64, 128, 256}) set.push_back(runOne(table, n, m, kind, k, 1e-5));
      for (double tol : {1e-3, 1e-4, 1e-6}) set.push_back(runOne(table, n, m, kind, 128, tol));
      set.push_back(ref);
      for (const Row& r : set) {
        human << fmt::format("{:7} {:8} {:>6} {:>9.0e} {:>16.8f} {:>10.1e} {:>8.3f} {:>6}\n",
                                 r.tube, r.kind, r.kpoints, r.tolerance, r.stiffness,
                                 std::abs(r.stiffness / ref.stiffness - 1), r.seconds,
                                 r.evaluations);
        rows.push_back(r);
      }
      human << std::flush;
    }
  if (!csv.empty()) {
    std::string f = "tube,kind,kpoints,force_tolerance_hartree_per_bohr,stiffness_hartree,time_s,evaluations\n";
    for (const Row& r : rows)
      f += csvField(r.tube) + "," + csvField(r.kind) +
           fmt::format(",{},{:.0e},{:.12g},{:.4f},{}\n", r.kpoints, r.tolerance, r.stiffness, r.seconds, r.evaluations);
    writeFileAtomically(csv, f);
  }
  return 0;
}

}  // namespace

Command makeBenchScanCommand() {
  struct Opts {
    std::string table = defaultCarbonTable(), csv;
  };
  auto o = std::make_shared<Opts>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& bench) {
    auto* s = bench.add_subcommand(
        "scan", "fitted stretch/twist stiffness and time against k-points and relax tolerance");
    s->add_option("--table", o->table, "C-C Slater-Koster table");
    s->add_option("--csv", o->csv, "write the rows as CSV (- for the standard output)");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return benchScan(o->table, o->csv); };
  return c;
}

}  // namespace mesochain::app
