// Outputs of the knobs' table (workflows/knobs.hpp): the printed table, JSON, CSV and the plot.
#include <cmath>
#include <filesystem>
#include <ostream>

#include <fmt/format.h>

#include "beam/beam_run.hpp"
#include "common/build_info.hpp"
#include "common/csv.hpp"
#include "common/plot/figure.hpp"
#include "workflows/knobs.hpp"

namespace mesochain::workflows {

using nlohmann::json;

void printKnobsTable(std::ostream& out, const KnobsTable& t) {
  const FinishedScan& f = t.scan;
  const beam::CurveConstant q = beam::curveConstant(f.curve);
  out << fmt::format(
      "{} scan {} ({}): {} points, {} atoms per cell, {} cell(s) per slice; relaxed in {} "
      "evaluations, {:.1f} s (curve JSON)\n",
      f.curve.label(), f.input.source, f.input.jsonPath, f.cells.size(), f.cells[0].atomCount(),
      f.cellsPerSlice, t.scanEvaluations, t.scanSeconds);
  out << fmt::format(
      "consistency: the structures re-evaluated at the scan's settings reproduce the curve "
      "energies to {:.2e} Ha per slice (largest difference)\n", t.largestDifference);
  out << fmt::format("{} from the curve JSON: {:.8g} +- {:.2g} {}\n", q.name, t.fromCurve.constant,
                     t.fromCurve.uncertainty, q.unit);
  for (const std::string& note : t.notes) out << "note: " << note << "\n";
  // Not measured: "-" (CPU time of whole scans; forces without --forces).
  auto cell = [](double x, const char* spec) {
    return std::isnan(x) ? std::string("-") : fmt::format(fmt::runtime(spec), x);
  };
  out << fmt::format("{:<11} {:<44} {:>16} {:>10} {:>10} {:>11} {:>11} {:>10} {:>9}\n", "knob",
                     "setting", q.name + " [" + q.unit + "]", "+-", "rel.diff", "cpu/eval[s]",
                     "wall/eval[s]", "total[s]", "max|F|");
  for (const KnobRow& r : t.rows) {
    std::string setting = r.setting + (r.own ? " (scan)" : "") + (r.reference ? " (ref)" : "");
    out << fmt::format("{:<11} {:<44} {:>16} {:>10} {:>10} {:>11} {:>11} {:>10} {:>9}{}\n", r.knob,
                       setting, cell(r.constant, "{:.8g}"), cell(r.uncertainty, "{:.2g}"),
                       cell(r.relative, "{:.2e}"), cell(r.cpuPerEvaluation, "{:.3g}"),
                       cell(r.wallPerEvaluation, "{:.3g}"), cell(r.totalWall, "{:.3g}"),
                       cell(r.maxForce, "{:.1e}"), r.note.empty() ? "" : "  " + r.note);
  }
  out << std::flush;
}

json knobsJson(const KnobsTable& t) {
  json j = t.header;
  j["rows"] = json::array();
  auto num = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
  for (const KnobRow& r : t.rows)
    j["rows"].push_back({{"knob", r.knob}, {"setting", r.setting}, {"scan_setting", r.own},
                         {"reference", r.reference}, {"constant", num(r.constant)},
                         {"uncertainty", num(r.uncertainty)},
                         {"relative_difference", num(r.relative)},
                         {"cpu_s_per_evaluation", num(r.cpuPerEvaluation)},
                         {"wall_s_per_evaluation", num(r.wallPerEvaluation)},
                         {"total_wall_s", num(r.totalWall)}, {"evaluations", r.evaluations},
                         {"max_force_hartree_per_bohr", num(r.maxForce)}, {"note", r.note}});
  j["program"] = buildInfoJson();
  return j;
}

std::string knobsCsv(const KnobsTable& t) {
  std::string out =
      "knob,setting,scan_setting,reference,constant,uncertainty,relative_difference,"
      "cpu_s_per_evaluation,wall_s_per_evaluation,total_wall_s,evaluations,"
      "max_force_hartree_per_bohr,note\n";
  for (const KnobRow& r : t.rows)
    out += fmt::format("{},{},{},{},{:.12g},{:.4g},{:.4g},{:.4g},{:.4g},{:.4g},{},{:.4g},{}\n",
                       csvField(r.knob), csvField(r.setting), r.own, r.reference, r.constant,
                       r.uncertainty, r.relative, r.cpuPerEvaluation, r.wallPerEvaluation,
                       r.totalWall, r.evaluations, r.maxForce, csvField(r.note));
  return out;
}

bool writeKnobsPlot(const KnobsTable& t, const std::string& png) {
  // |relative difference| against the CPU time of one energy evaluation (not inflated by the
  // load of a shared machine; with several threads, their sum), one series per knob.
  // The reference of each knob (0) cannot sit on a log axis. Whole-scan comparisons
  // (relaxation) are left to the table: their cost is in the number of evaluations.
  plot::Figure fig(fmt::format("{}: {} of {}", "bench knobs", beam::curveConstant(t.scan.curve).name,
                               std::filesystem::path(t.scan.input.source).filename().string()));
  fig.x.label = "CPU time per energy evaluation (s)";
  fig.y.label = "|relative difference| to the reference";
  fig.x.scale = fig.y.scale = plot::Scale::Log10;
  const plot::Marker markers[] = {plot::Marker::Circle, plot::Marker::Square, plot::Marker::Triangle,
                                  plot::Marker::Diamond, plot::Marker::Circle};
  int m = 0;
  for (const char* knob : {"kpoints", "angular", "sampling", "dispersion", "temperature"}) {
    std::vector<double> x, y;
    for (const KnobRow& r : t.rows)
      if (r.knob == knob && std::isfinite(r.relative) && r.relative != 0 && r.cpuPerEvaluation > 0)
        x.push_back(r.cpuPerEvaluation), y.push_back(std::abs(r.relative));
    if (x.empty()) continue;
    plot::SeriesStyle style;
    style.marker = markers[m++ % 5];
    fig.add(knob, x, y, style);
  }
  if (fig.series.empty()) return false;
  fig.savePng(png);
  return true;
}

}  // namespace mesochain::workflows
