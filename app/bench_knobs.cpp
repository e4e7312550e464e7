// `mesochain bench knobs SCAN.toml [--kpoints ...] [--angular ...] [--dispersion ...]
// [--temperature ...] [--compare-curve OTHER.json ...] [--csv F] [--json F] [--png F]`:
// what each accuracy knob of a finished scan costs and changes, without relaxing again.
//
// The relaxed cell of every curve point (the scan's [output] structures) is re-evaluated,
// energy only, at the scan's own settings (a consistency check: it must reproduce the curve)
// and then one knob at a time; each set of energies is fitted with the fitter and options of
// `mesochain beam` (beam/beam_run.hpp fitScanCurve). The relaxed energy is stationary in the
// atomic coordinates, so the change of a point's relaxed energy with a setting equals the
// change at fixed geometry to first order; the relaxation response is second order
// (docs/benchmarks.md, "mesochain bench knobs"). The relaxation tolerance itself changes the
// geometry and is measured by comparing whole scans (--compare-curve).
#include <time.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "app/bench_knobs.hpp"
#include "app/commands.hpp"
#include "beam/beam_run.hpp"
#include "common/atomic_file.hpp"
#include "common/csv.hpp"
#include "common/build_info.hpp"
#include "common/errors.hpp"
#include "common/plot/figure.hpp"
#include "common/progress_bar.hpp"
#include "objective/drivers/cell_calculator.hpp"
#include "objective/drivers/relax.hpp"

namespace mesochain::app {

namespace {

using knobs::FinishedScan;
using knobs::KnobSetting;
using nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct KnobsOptions {
  std::string scanFile;
  std::string scanOutputDir;
  std::vector<std::string> kpoints, angular, sampling, dispersion, temperature, compare;
  std::string csv, json, png;
  double tolerance = 0.02;
  std::string linearTerm = "auto";
  bool measuredCurvature = false;
  bool forces = false;
};

struct Row {
  std::string knob, setting;
  bool own = false, reference = false;
  double constant = kNaN, uncertainty = kNaN, relative = kNaN;
  double cpuPerEvaluation = kNaN, wallPerEvaluation = kNaN, totalWall = kNaN;
  double maxForce = kNaN;  // largest |force| on the structures at this setting, Ha/Bohr
  int evaluations = 0;
  std::string note;
};

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The energies (Hartree per slice, as in the curve) of every structure at one setting.
struct Evaluation {
  std::vector<double> energies;
  double wall = 0, cpu = 0;
  double largestForce = kNaN;  // with forces: the largest atom force over the structures
};

Evaluation evaluate(const FinishedScan& f, const std::shared_ptr<const dftb::ParameterSet>& params,
                    const dftb::CalculatorSettings& straightSettings,
                    const dftb::CalculatorSettings& ringSettings, bool forces, ProgressBar& bar,
                    int& done, const std::string& what) {
  const dftb::Calculator straight(params, straightSettings), ring(params, ringSettings);
  Evaluation e;
  if (forces) e.largestForce = 0;
  dftb::EvaluationRequest request;
  request.gradient = forces;
  const int n = static_cast<int>(f.cells.size());
  for (int k = 0; k < n; ++k) {
    bar.update(done, fmt::format("{}: point {}/{}", what, k + 1, n));
    const objective::ObjectiveCell& cell = f.cells[k];
    const dftb::Calculator& calc = cell.symmetry.isRing() ? ring : straight;
    const double c0 = cpuSeconds();
    const auto w0 = std::chrono::steady_clock::now();
    const dftb::Result result = calc.evaluate(cell, request);
    e.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    e.cpu += cpuSeconds() - c0;
    e.energies.push_back(result.freeEnergy * f.cellsPerSlice);
    if (forces) e.largestForce = std::max(e.largestForce, objective::maxForce(result.gradient));
    bar.update(++done);
  }
  return e;
}

// Fits the curve with its energies replaced; a refused curve leaves the constant NaN and the
// fitter's reason in the note.
void fitInto(Row& row, beam::ScanCurve curve, const std::vector<double>* energies,
             const KnobsOptions& o) {
  if (energies)
    for (std::size_t k = 0; k < curve.points.size(); ++k) curve.points[k].energy = (*energies)[k];
  const beam::CurveConstant q = beam::curveConstant(curve);
  try {
    const beam::FittedCurve fc =
        beam::fitScanCurve(curve, q.name, q.key, o.tolerance, o.linearTerm, o.measuredCurvature);
    row.constant = fc.fit.stiffness;
    row.uncertainty = fc.fit.uncertainty;
  } catch (const InputError& e) {
    row.note = std::string("fit refused: ") + e.what();
  }
}

Row timedRow(const KnobSetting& s, const Evaluation& e) {
  Row r;
  r.knob = s.knob;
  r.setting = s.label;
  r.own = s.own;
  r.evaluations = static_cast<int>(e.energies.size());
  r.totalWall = e.wall;
  r.wallPerEvaluation = e.wall / r.evaluations;
  r.cpuPerEvaluation = e.cpu / r.evaluations;
  r.maxForce = e.largestForce;
  return r;
}

// Relative differences to the reference row (the last of the series: the most accurate).
void markReference(std::vector<Row>& rows, std::size_t first) {
  if (first >= rows.size()) return;
  Row& ref = rows.back();
  ref.reference = true;
  for (std::size_t k = first; k < rows.size(); ++k)
    rows[k].relative = rows[k].constant / ref.constant - 1.0;  // NaN when either fit failed
}

// Rings sample M angular quantum numbers at the midpoints of the half zone only when N_a is a
// multiple of 4 M (objective/core/kgrid.cpp; docs/scan-file.md): otherwise the rounded samples
// are uneven and the ring energies carry a sampling bias. Noted on the row.
void ringSamplingNote(Row& r, const FinishedScan& f) {
  // "M" (angular) or "K:M" (sampling): the ring samples are M.
  const std::string mu = r.setting.substr(r.setting.find(':') + 1);
  if (mu == "all") return;
  const int m = std::stoi(mu);
  std::vector<int> uneven;
  for (const auto& c : f.cells) {
    const int na = c.symmetry.rotationOrder();
    if (c.symmetry.isRing() && m < na / 2 + 1 && na % (4 * m) != 0) uneven.push_back(na);
  }
  if (uneven.empty()) return;
  r.note += fmt::format("{}uneven samples: N_a = {} not a multiple of 4 x {}",
                        r.note.empty() ? "" : "; ", fmt::join(uneven, ", "), m);
}

// The cost of a relaxed scan from its curve JSON: time_s and evaluations summed, and the
// largest max|F| of its converged points (how tightly it was relaxed).
struct CurveCost {
  double seconds = 0, largestForce = 0;
  int evaluations = 0;
};

CurveCost curveCost(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "the curve JSON cannot be opened");
  CurveCost c;
  try {
    const json j = json::parse(in);
    for (const json& p : j.at("points")) {
      c.seconds += p.value("time_s", 0.0);
      c.evaluations += p.value("evaluations", 0);
      if (p.value("converged", true))
        c.largestForce = std::max(c.largestForce, p.value("max_force_hartree_per_bohr", 0.0));
    }
  } catch (const json::exception& e) {
    throw InputError(path, "points", e.what(), "a curve JSON written by mesochain scan");
  }
  return c;
}

Row relaxationRow(const std::string& path, const beam::ScanCurve& curve, const KnobsOptions& o) {
  const CurveCost cost = curveCost(path);
  Row r;
  r.knob = "relaxation";
  r.setting = fmt::format("{} (max|F| {:.1e})", std::filesystem::path(path).filename().string(),
                          cost.largestForce);
  r.totalWall = cost.seconds;
  r.evaluations = cost.evaluations;
  r.wallPerEvaluation = cost.evaluations > 0 ? cost.seconds / cost.evaluations : kNaN;
  r.maxForce = cost.largestForce;
  fitInto(r, curve, nullptr, o);
  return r;
}

void writeOutputs(const KnobsOptions& o, const FinishedScan& f, const std::vector<Row>& rows,
                  const json& header) {
  // Under mpirun only rank 0 writes (common/atomic_file.hpp, fileOutputEnabled).
  if (!o.csv.empty() && fileOutputEnabled()) {
    std::ofstream out(o.csv);
    if (!out) throw InputError(o.csv, "cannot open the CSV output for writing");
    out << "knob,setting,scan_setting,reference,constant,uncertainty,relative_difference,"
           "cpu_s_per_evaluation,wall_s_per_evaluation,total_wall_s,evaluations,"
           "max_force_hartree_per_bohr,note\n";
    for (const Row& r : rows)
      out << fmt::format("{},{},{},{},{:.12g},{:.4g},{:.4g},{:.4g},{:.4g},{:.4g},{},{:.4g},{}\n",
                         csvField(r.knob), csvField(r.setting), r.own, r.reference, r.constant,
                         r.uncertainty, r.relative, r.cpuPerEvaluation, r.wallPerEvaluation,
                         r.totalWall, r.evaluations, r.maxForce, csvField(r.note));
    std::cerr << "wrote " << o.csv << "\n";
  }
  if (!o.json.empty() && fileOutputEnabled()) {
    json j = header;
    j["rows"] = json::array();
    auto num = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    for (const Row& r : rows)
      j["rows"].push_back({{"knob", r.knob}, {"setting", r.setting}, {"scan_setting", r.own},
                           {"reference", r.reference}, {"constant", num(r.constant)},
                           {"uncertainty", num(r.uncertainty)},
                           {"relative_difference", num(r.relative)},
                           {"cpu_s_per_evaluation", num(r.cpuPerEvaluation)},
                           {"wall_s_per_evaluation", num(r.wallPerEvaluation)},
                           {"total_wall_s", num(r.totalWall)}, {"evaluations", r.evaluations},
                           {"max_force_hartree_per_bohr", num(r.maxForce)},
                           {"note", r.note}});
    j["program"] = buildInfoJson();
    std::ofstream out(o.json);
    if (!out) throw InputError(o.json, "cannot open the JSON output for writing");
    out << j.dump(2) << "\n";
    std::cerr << "wrote " << o.json << "\n";
  }
  if (!o.png.empty()) {
    // |relative difference| against the CPU time of one energy evaluation (not inflated by the
    // load of a shared machine; with several threads, their sum), one series per knob.
    // The reference of each knob (0) cannot sit on a log axis. Whole-scan comparisons
    // (relaxation) are left to the table: their cost is in the number of evaluations.
    plot::Figure fig(fmt::format("{}: {} of {}", "bench knobs", beam::curveConstant(f.curve).name,
                                 std::filesystem::path(f.input.source).filename().string()));
    fig.x.label = "CPU time per energy evaluation (s)";
    fig.y.label = "|relative difference| to the reference";
    fig.x.scale = fig.y.scale = plot::Scale::Log10;
    const plot::Marker markers[] = {plot::Marker::Circle, plot::Marker::Square,
                                    plot::Marker::Triangle, plot::Marker::Diamond,
                                    plot::Marker::Circle};
    int m = 0;
    for (const char* knob : {"kpoints", "angular", "sampling", "dispersion", "temperature"}) {
      std::vector<double> x, y;
      for (const Row& r : rows)
        if (r.knob == knob && std::isfinite(r.relative) && r.relative != 0 &&
            r.cpuPerEvaluation > 0)
          x.push_back(r.cpuPerEvaluation), y.push_back(std::abs(r.relative));
      if (x.empty()) continue;
      plot::SeriesStyle style;
      style.marker = markers[m++ % 5];
      fig.add(knob, x, y, style);
    }
    if (fig.series.empty())
      std::cerr << "mesochain: note: no nonzero relative difference to plot; " << o.png
                << " not written\n";
    else {
      fig.savePng(o.png);
      std::cerr << "wrote " << o.png << "\n";
    }
  }
}

int benchKnobs(const KnobsOptions& o) {
  if (o.linearTerm != "auto" && o.linearTerm != "on" && o.linearTerm != "off")
    throw InputError("<command line>", "--linear-term", "'" + o.linearTerm + "'", "auto, on or off");
  // The outputs are checked before the (minutes of) evaluations.
  if (!o.csv.empty()) requireWritableOutput(o.csv, "<command line>", "option --csv");
  if (!o.json.empty()) requireWritableOutput(o.json, "<command line>", "option --json");
  if (!o.png.empty()) requireWritableOutput(o.png, "<command line>", "option --png");
  const FinishedScan f = knobs::readFinishedScan(o.scanFile, o.scanOutputDir);
  const objective::CellInput& cellInput = f.input.cell;
  const auto params = objective::loadParameters(cellInput);
  const dftb::CalculatorSettings straight = objective::calculatorSettings(cellInput);
  dftb::CalculatorSettings ring = straight;  // as runScan: rings use one kappa point
  ring.band.helicalKPoints = 1;
  ring.band.angular = f.input.settings.ringAngular;
  bool anyRing = false;
  for (const auto& c : f.cells) anyRing = anyRing || c.symmetry.isRing();
  // The other curves are read and checked before any evaluation (a heavy run must not end in
  // a typo).
  std::vector<beam::ScanCurve> others;
  for (const std::string& path : o.compare) {
    others.push_back(beam::readScanTable(path));
    if (others.back().label() != f.curve.label())
      throw InputError(path, "key kind", others.back().label(),
                       f.curve.label() + ", the kind of " + f.input.jsonPath);
    curveCost(path);
  }

  std::vector<std::string> notes;
  std::vector<std::vector<KnobSetting>> series;
  if (!o.kpoints.empty()) {
    series.push_back(knobs::kpointSettings(o.kpoints, straight.band.helicalKPoints));
    if (anyRing)
      notes.push_back("kpoints: the rings (T = 0) have one kappa point; only the straight "
                      "points depend on this knob");
  }
  // Every value is checked, also of a knob that does not apply to this scan.
  if (!o.angular.empty()) {
    auto settings = knobs::angularSettings(
        o.angular, anyRing ? f.input.settings.ringAngular.samples : straight.band.angular.samples);
    if (f.curve.kind != "bend")
      notes.push_back("angular: only for bend scans; --angular ignored for a " + f.curve.kind +
                      " scan");
    else
      series.push_back(std::move(settings));
  }
  if (!o.sampling.empty()) {
    auto settings = knobs::samplingSettings(o.sampling, straight.band.helicalKPoints,
                                            f.input.settings.ringAngular.samples);
    if (f.curve.kind != "bend")
      notes.push_back("sampling: only for bend scans (use --kpoints otherwise); --sampling ignored "
                      "for a " + f.curve.kind + " scan");
    else
      series.push_back(std::move(settings));
  }
  if (!o.dispersion.empty()) {
    auto settings = knobs::dispersionSettings(o.dispersion, straight.dispersion);
    if (!straight.dispersion.enabled)
      notes.push_back("dispersion: the cell file has no dispersion ([dispersion] model = \"lj\"); "
                      "--dispersion ignored");
    else
      series.push_back(std::move(settings));
  }
  if (!o.temperature.empty())
    series.push_back(knobs::temperatureSettings(o.temperature, straight.band.electronicTemperature));

  // A curve the fitter refuses as it stands has nothing to compare: stop before the work.
  Row fromCurve;
  fitInto(fromCurve, f.curve, nullptr, o);
  if (!fromCurve.note.empty())
    throw InputError(f.input.jsonPath, "the curve of the scan", fromCurve.note,
                     "a curve the fitter of mesochain beam accepts (see --linear-term, "
                     "--tolerance, --measured-curvature)");

  const int n = static_cast<int>(f.cells.size());
  int total = n;
  for (const auto& s : series)
    for (const KnobSetting& k : s) total += k.own ? 0 : n;
  ProgressBar bar("bench knobs", total, std::max(1, total / 20));  // off a terminal: about 20 lines
  int done = 0;
  // One untimed evaluation first: the first one of a process also pays one-off start-up costs.
  {
    const objective::ObjectiveCell& c = f.cells[0];
    dftb::EvaluationRequest request;
    request.gradient = o.forces;
    dftb::Calculator(params, c.symmetry.isRing() ? ring : straight).evaluate(c, request);
  }
  const Evaluation own = evaluate(f, params, straight, ring, o.forces, bar, done, "scan settings");

  double largest = 0;
  for (int k = 0; k < n; ++k)
    largest = std::max(largest, std::abs(own.energies[k] - f.curve.points[k].energy));
  Row reevaluated;
  fitInto(reevaluated, f.curve, &own.energies, o);

  std::vector<Row> rows;
  for (const auto& s : series) {
    const std::size_t first = rows.size();
    for (const KnobSetting& k : s) {
      if (k.own) {
        rows.push_back(timedRow(k, own));
        rows.back().constant = reevaluated.constant;
        rows.back().uncertainty = reevaluated.uncertainty;
        rows.back().note = reevaluated.note;
        continue;
      }
      dftb::CalculatorSettings a = straight, b = ring;
      k.apply(a, b);
      const Evaluation e = evaluate(f, params, a, b, o.forces, bar, done, k.knob + " " + k.label);
      rows.push_back(timedRow(k, e));
      fitInto(rows.back(), f.curve, &e.energies, o);
    }
    markReference(rows, first);
  }
  bar.finish();
  const double tolerance = f.input.settings.relax.forceTolerance;
  for (Row& r : rows) {
    if (r.knob == "angular" || r.knob == "sampling") ringSamplingNote(r, f);
    if (r.maxForce > tolerance)
      r.note += fmt::format("{}max|F| above the scan's tolerance {:.0e} Ha/Bohr",
                            r.note.empty() ? "" : "; ", tolerance);
  }

  // Whole scans: the scan's own curve and the others, the most tightly relaxed as reference.
  if (!o.compare.empty()) {
    // (largest max|F|, row): sorted loosest first, so the tightest is last (the reference).
    std::vector<std::pair<double, Row>> relax;
    auto add = [&](const std::string& path, const beam::ScanCurve& curve, bool own) {
      Row r = relaxationRow(path, curve, o);
      r.own = own;
      relax.emplace_back(curveCost(path).largestForce, std::move(r));
    };
    add(f.input.jsonPath, f.curve, true);
    for (std::size_t k = 0; k < others.size(); ++k) add(o.compare[k], others[k], false);
    std::stable_sort(relax.begin(), relax.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    const std::size_t first = rows.size();
    for (auto& r : relax) rows.push_back(std::move(r.second));
    markReference(rows, first);
  }

  const beam::CurveConstant q = beam::curveConstant(f.curve);
  const CurveCost scanCost = curveCost(f.input.jsonPath);
  std::cout << fmt::format(
      "{} scan {} ({}): {} points, {} atoms per cell, {} cell(s) per slice; relaxed in {} "
      "evaluations, {:.1f} s (curve JSON)\n",
      f.curve.label(), f.input.source, f.input.jsonPath, n, f.cells[0].atomCount(),
      f.cellsPerSlice, scanCost.evaluations, scanCost.seconds);
  std::cout << fmt::format(
      "consistency: the structures re-evaluated at the scan's settings reproduce the curve "
      "energies to {:.2e} Ha per slice (largest difference)\n", largest);
  std::cout << fmt::format("{} from the curve JSON: {:.8g} +- {:.2g} {}\n", q.name,
                           fromCurve.constant, fromCurve.uncertainty, q.unit);
  for (const std::string& note : notes) std::cout << "note: " << note << "\n";
  // Not measured: "-" (CPU time of whole scans; forces without --forces).
  auto cell = [](double x, const char* spec) {
    return std::isnan(x) ? std::string("-") : fmt::format(fmt::runtime(spec), x);
  };
  std::cout << fmt::format("{:<11} {:<44} {:>16} {:>10} {:>10} {:>11} {:>11} {:>10} {:>9}\n",
                           "knob", "setting", q.name + " [" + q.unit + "]", "+-", "rel.diff",
                           "cpu/eval[s]", "wall/eval[s]", "total[s]", "max|F|");
  for (const Row& r : rows) {
    std::string setting = r.setting + (r.own ? " (scan)" : "") + (r.reference ? " (ref)" : "");
    std::cout << fmt::format("{:<11} {:<44} {:>16} {:>10} {:>10} {:>11} {:>11} {:>10} {:>9}{}\n",
                             r.knob, setting, cell(r.constant, "{:.8g}"),
                             cell(r.uncertainty, "{:.2g}"), cell(r.relative, "{:.2e}"),
                             cell(r.cpuPerEvaluation, "{:.3g}"), cell(r.wallPerEvaluation, "{:.3g}"),
                             cell(r.totalWall, "{:.3g}"), cell(r.maxForce, "{:.1e}"),
                             r.note.empty() ? "" : "  " + r.note);
  }
  std::cout << std::flush;
  if (largest > 1e-7)
    std::cerr << fmt::format("mesochain: warning: the re-evaluated energies differ from the curve "
                             "by up to {:.2e} Ha: the structures, the cell file or the parameters "
                             "changed since the scan ran\n", largest);

  json header = {{"format", 1},
                 {"scan_file", f.input.source},
                 {"curve", f.input.jsonPath},
                 {"kind", f.curve.kind},
                 {"direction", f.curve.direction},
                 {"quantity", q.name},
                 {"constant_key", q.key},
                 {"points", n},
                 {"atoms_per_cell", f.cells[0].atomCount()},
                 {"cells_per_slice", f.cellsPerSlice},
                 {"scan_evaluations", scanCost.evaluations},
                 {"scan_time_s", scanCost.seconds},
                 {"max_abs_energy_difference_hartree", largest},
                 {"constant_from_curve", std::isfinite(fromCurve.constant) ? json(fromCurve.constant)
                                                                           : json(nullptr)},
                 {"notes", notes}};
  writeOutputs(o, f, rows, header);
  return 0;
}

}  // namespace

Command makeBenchKnobsCommand() {
  auto o = std::make_shared<KnobsOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& bench) {
    auto* s = bench.add_subcommand(
        "knobs", "a finished scan's fitted constant and time against k-points, angular samples, "
                 "dispersion and temperature (its relaxed structures re-evaluated)");
    s->add_option("scan", o->scanFile, "the scan file (with [output] structures), already run")
        ->required();
    s->add_option("--scan-output-dir", o->scanOutputDir,
                  "the -o folder the scan ran with, where its [output] files are (default: the working folder)");
    s->add_option("--kpoints", o->kpoints, "helical k-points to try, e.g. 12,24,48")->delimiter(',');
    s->add_option("--angular", o->angular, "ring angular samples to try (bend), e.g. 6,12,24,all")
        ->delimiter(',');
    s->add_option("--sampling", o->sampling,
                  "bend: helical k-points of the straight reference and ring angular samples "
                  "together, K:M, e.g. 12:6,24:12,48:24 (consistent when K = 2M)")
        ->delimiter(',');
    s->add_option("--dispersion", o->dispersion,
                  "LJ tail treatments to try: cutoff:R (Å), ewald, ewald:TOL")
        ->delimiter(',');
    s->add_option("--temperature", o->temperature, "electronic temperatures to try (K)")
        ->delimiter(',');
    s->add_option("--compare-curve", o->compare,
                  "curve JSON of the same scan made otherwise (e.g. another force tolerance)");
    s->add_option("--csv", o->csv, "write the rows as CSV");
    s->add_option("--json", o->json, "write the rows as JSON");
    s->add_option("--png", o->png, "plot |relative difference| against CPU time per evaluation");
    s->add_option("--tolerance", o->tolerance,
                  "relative tolerance of the fit's quadratic regime (as mesochain beam; 0.02)");
    s->add_option("--linear-term", o->linearTerm, "auto (stretch, twist: on; bend: off), on, off");
    s->add_flag("--measured-curvature", o->measuredCurvature,
                "fit bends against the measured curvature");
    s->add_flag("--forces", o->forces,
                "evaluate forces too: the largest force on the relaxed structures at each "
                "setting, and the time of an evaluation as in a relaxation step");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return benchKnobs(*o); };
  return c;
}

}  // namespace mesochain::app
