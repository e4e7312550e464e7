#include "workflows/knobs.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "beam/beam_run.hpp"
#include "common/errors.hpp"
#include "common/progress_bar.hpp"
#include "input/cell_calculator.hpp"
#include "objective/drivers/relax.hpp"

namespace mesochain::workflows {

namespace {

using nlohmann::json;

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The energies (Hartree per slice, as in the curve) of every structure at one setting.
struct Evaluation {
  std::vector<double> energies;
  double wall = 0, cpu = 0;
  double largestForce = kKnobNaN;  // with forces: the largest atom force over the structures
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
void fitInto(KnobRow& row, beam::ScanCurve curve, const std::vector<double>* energies,
             const KnobsRequest& o) {
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

KnobRow timedRow(const KnobSetting& s, const Evaluation& e) {
  KnobRow r;
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
void markReference(std::vector<KnobRow>& rows, std::size_t first) {
  if (first >= rows.size()) return;
  KnobRow& ref = rows.back();
  ref.reference = true;
  for (std::size_t k = first; k < rows.size(); ++k)
    rows[k].relative = rows[k].constant / ref.constant - 1.0;  // NaN when either fit failed
}

// Rings sample M angular quantum numbers at the midpoints of the half zone only when N_a is a
// multiple of 4 M (objective/core/kgrid.cpp; docs/scan-file.md): otherwise the rounded samples
// are uneven and the ring energies carry a sampling bias. Noted on the row.
void ringSamplingNote(KnobRow& r, const FinishedScan& f) {
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

KnobRow relaxationRow(const std::string& path, const beam::ScanCurve& curve, const KnobsRequest& o) {
  const CurveCost cost = curveCost(path);
  KnobRow r;
  r.knob = "relaxation";
  r.setting = fmt::format("{} (max|F| {:.1e})", std::filesystem::path(path).filename().string(),
                          cost.largestForce);
  r.totalWall = cost.seconds;
  r.evaluations = cost.evaluations;
  r.wallPerEvaluation = cost.evaluations > 0 ? cost.seconds / cost.evaluations : kKnobNaN;
  r.maxForce = cost.largestForce;
  fitInto(r, curve, nullptr, o);
  return r;
}

}  // namespace

KnobsTable runKnobs(const KnobsRequest& o) {
  if (o.linearTerm != "auto" && o.linearTerm != "on" && o.linearTerm != "off")
    throw InputError(o.where.source, o.where.option("linear-term"), "'" + o.linearTerm + "'", "auto, on or off");
  KnobsTable t;
  t.scan = readFinishedScan(o.scanFile, o.scanOutputDir);
  const FinishedScan& f = t.scan;
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
    series.push_back(kpointSettings(o.kpoints, straight.band.helicalKPoints, o.where));
    if (anyRing)
      notes.push_back("kpoints: the rings (T = 0) have one kappa point; only the straight "
                      "points depend on this knob");
  }
  // Every value is checked, also of a knob that does not apply to this scan.
  if (!o.angular.empty()) {
    auto settings = angularSettings(
        o.angular, anyRing ? f.input.settings.ringAngular.samples : straight.band.angular.samples,
        o.where);
    if (f.curve.kind != "bend")
      notes.push_back("angular: only for bend scans; --angular ignored for a " + f.curve.kind +
                      " scan");
    else
      series.push_back(std::move(settings));
  }
  if (!o.sampling.empty()) {
    auto settings = samplingSettings(o.sampling, straight.band.helicalKPoints,
                                            f.input.settings.ringAngular.samples, o.where);
    if (f.curve.kind != "bend")
      notes.push_back("sampling: only for bend scans (use --kpoints otherwise); --sampling ignored "
                      "for a " + f.curve.kind + " scan");
    else
      series.push_back(std::move(settings));
  }
  if (!o.dispersion.empty()) {
    auto settings = dispersionSettings(o.dispersion, straight.dispersion, o.where);
    if (!straight.dispersion.enabled)
      notes.push_back("dispersion: the cell file has no dispersion ([dispersion] model = \"lj\"); "
                      "--dispersion ignored");
    else
      series.push_back(std::move(settings));
  }
  if (!o.temperature.empty())
    series.push_back(temperatureSettings(o.temperature, straight.band.electronicTemperature, o.where));

  // A curve the fitter refuses as it stands has nothing to compare: stop before the work.
  KnobRow fromCurve;
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
  if (!o.progressBar) bar.finish();
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
  KnobRow reevaluated;
  fitInto(reevaluated, f.curve, &own.energies, o);

  std::vector<KnobRow> rows;
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
  for (KnobRow& r : rows) {
    if (r.knob == "angular" || r.knob == "sampling") ringSamplingNote(r, f);
    if (r.maxForce > tolerance)
      r.note += fmt::format("{}max|F| above the scan's tolerance {:.0e} Ha/Bohr",
                            r.note.empty() ? "" : "; ", tolerance);
  }

  // Whole scans: the scan's own curve and the others, the most tightly relaxed as reference.
  if (!o.compare.empty()) {
    // (largest max|F|, row): sorted loosest first, so the tightest is last (the reference).
    std::vector<std::pair<double, KnobRow>> relax;
    auto add = [&](const std::string& path, const beam::ScanCurve& curve, bool own) {
      KnobRow r = relaxationRow(path, curve, o);
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
  t.scanSeconds = scanCost.seconds;
  t.scanEvaluations = scanCost.evaluations;
  t.largestDifference = largest;
  t.fromCurve = fromCurve;
  t.notes = notes;
  t.header = {{"format", 1},
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
  t.rows = std::move(rows);
  return t;
}


}  // namespace mesochain::workflows
