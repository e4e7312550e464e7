// `mesochain scan SCAN.toml [--resume] [--stop-after N]`: a deformation scan (stretch, twist
// or bend) of an objective cell, written as a curve JSON and CSV (docs/scan-file.md).
#include <algorithm>
#include <limits>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "beam/beam_run.hpp"
#include "beam/fit_plot.hpp"
#include "beam/scan_table.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/plot/figure.hpp"
#include "common/units.hpp"
#include "input/cell_calculator.hpp"
#include "objective/drivers/scan.hpp"
#include "input/scan_file.hpp"
#include "input/scan_output.hpp"

namespace mesochain::app {

namespace {
struct ScanOptions {
  std::string scanFile;
  bool resume = false;
  int stopAfter = -1;
  std::string png;  // default: the curve JSON with .png
  std::string outputDir = ".";
};

// PNG of the finished curve read back from its JSON: with the quadratic fit of beam/ (window,
// stiffness +- uncertainty, residuals; beam/fit_plot.hpp) when the fitter accepts the curve,
// else the points alone and the fitter's reason on stderr (e.g. too few points so far).
void writeScanPlot(const std::string& jsonPath, const std::string& pngPath) {
  const beam::ScanCurve curve = beam::readScanTable(jsonPath);
  const beam::CurveConstant q = beam::curveConstant(curve);
  try {
    beam::writeFitPlot(beam::fitScanCurve(curve, q.name, q.key, 0.02, "auto", false), pngPath);
    std::cerr << "wrote " << pngPath << " (curve with its quadratic fit)\n";
    return;
  } catch (const InputError& e) {
    std::cerr << "mesochain: note: the plot shows the points without a fit: " << e.what() << "\n";
  }
  plot::Figure f(curve.label() + " scan (" + curve.source + ")");
  f.x.label = curve.deformationUnit == "strain"         ? "strain"
              : curve.deformationUnit == "rad_per_cell" ? "twist per cell (rad)"
                                                        : "curvature 1/R (1/Bohr)";
  f.y.label = "energy per cell - lowest (meV)";
  std::vector<double> x, y;
  double lowest = 0.0;
  for (std::size_t k = 0; k < curve.points.size(); ++k)
    if (k == 0 || curve.points[k].energy < lowest) lowest = curve.points[k].energy;
  for (const auto& p : curve.points) {
    x.push_back(p.deformation);
    y.push_back((p.energy - lowest) * units::kHartreeInEv * 1000.0);
  }
  plot::SeriesStyle dots;
  dots.marker = plot::Marker::Circle;
  f.add("scan points", x, y, dots);
  f.savePng(pngPath);
  std::cerr << "wrote " << pngPath << "\n";
}

void printTable(std::ostream& os, const objective::ScanResult& r) {
  const bool bend = r.kind == objective::ScanKind::Bend;
  // E0: the straight reference (deformation 0); a sector scan (bent graphene) has none, and
  // its energies are shown relative to the least-bent ring instead.
  double e0 = std::numeric_limits<double>::quiet_NaN();
  for (const auto& p : r.points)
    if (p.deformation == 0.0) e0 = p.energy * r.cellsPerSlice;
  const bool straightReference = !std::isnan(e0);
  if (!straightReference && !r.points.empty()) {
    const auto least = std::min_element(
        r.points.begin(), r.points.end(), [](const auto& a, const auto& b) {
          return std::abs(a.deformation) < std::abs(b.deformation);
        });
    e0 = least->energy * r.cellsPerSlice;
  }
  os << fmt::format("scan {}{}: T0 = {:.6f} Bohr, {} atoms per cell, {} cell(s) per slice of "
                    "length T0 (energies per slice)\n",
                    objective::scanKindName(r.kind),
                    bend ? std::string(" (") + objective::bendDirectionName(r.direction) + ")" : "",
                    r.translation0, r.atomsPerCell, r.cellsPerSlice);
  if (!std::isnan(r.thickness))
    os << fmt::format("thickness {:.4f} Bohr ({:.3f} Å), width {:.4f} Bohr ({:.3f} Å)\n",
                      r.thickness, r.thickness * units::kBohrInAngstrom, r.width,
                      r.width * units::kBohrInAngstrom);
  os << fmt::format("{:>14} {:>20} {:>14} {:>12} {:>5} {:>10} {:>8} {:>6} {:>6}{}\n",
                    std::string("deformation[") + objective::deformationUnit(r.kind) + "]",
                    "energy [Ha/slice]", straightReference ? "E - E0 [Ha]" : "E - Eleast [Ha]",
                    straightReference ? "E - E0 [meV]" : "E-Eleast[meV]", "conv", "max|F|", "time[s]", "evals",
                    "k x mu", bend ? "  measured 1/R" : "");
  for (const auto& p : r.points) {
    const double de = p.energy * r.cellsPerSlice - e0;
    os << fmt::format("{:>14.6e} {:>20.10f} {:>14.6e} {:>12.6f} {:>5} {:>10.2e} {:>8.1f} {:>6} {:>6}",
                      p.deformation, p.energy * r.cellsPerSlice, de, de * units::kHartreeInEv * 1000.0,
                      p.converged ? "yes" : "NO",
                      p.maxForce, p.timeSeconds, p.evaluations,
                      fmt::format("{}x{}", p.helicalKPoints, p.angularPoints));
    if (bend) os << fmt::format("  {:.6e}", std::isnan(p.measuredCurvature) ? 0.0 : p.measuredCurvature);
    os << "\n";
  }
}

int runScanCommand(const ScanOptions& o) {
  objective::ScanInput in = objective::readScanFile(o.scanFile, o.outputDir);
  prepareOutputFolder(o.outputDir, "<command line>", "option --output-dir");
  in.settings.resume = o.resume;
  in.settings.stopAfter = o.stopAfter;
  // Every output is checked before the first point is computed.
  requireWritableOutput(in.jsonPath, o.scanFile, "key output.json");
  if (!in.csvPath.empty()) requireWritableOutput(in.csvPath, o.scanFile, "key output.csv");
  if (!in.settings.checkpointPath.empty())
    requireWritableOutput(in.settings.checkpointPath, o.scanFile, "key output.checkpoint");
  if (!in.structurePrefix.empty())
    requireWritableOutput(in.structurePrefix + "-000.xyz", o.scanFile, "key output.structures");
  if (!o.png.empty()) requireWritableOutput(o.png, "<command line>", "option --png");
  std::error_code ec;
  if (!o.resume && !in.settings.checkpointPath.empty() &&
      std::filesystem::exists(in.settings.checkpointPath, ec))
    std::cerr << "mesochain: note: starting afresh; the checkpoint " << in.settings.checkpointPath
              << " will be overwritten (use --resume to continue it)\n";
  // A row per point as it finishes, flushed (a redirected log follows the scan), before the
  // table sorted by deformation at the end.
  double reference = 0.0;
  const char* unit = objective::deformationUnit(in.settings.kind);
  in.settings.pointDone = [&reference, unit](const objective::ScanPoint& p, int index, int total) {
    if (index == 0) {
      reference = p.energy;
      std::cout << fmt::format("{:>9} {:>14} {:>20} {:>14} {:>5} {:>10} {:>8} {:>6}\n", "point",
                               std::string("deformation[") + unit + "]", "energy [Ha/cell]", "E - E(1) [Ha]",
                               "conv", "max|F|", "time[s]", "evals");
    }
    std::cout << fmt::format("{:>9} {:>14.6e} {:>20.10f} {:>14.6e} {:>5} {:>10.2e} {:>8.1f} {:>6}\n",
                             fmt::format("{}/{}", index + 1, total), p.deformation, p.energy,
                             p.energy - reference, p.converged ? "yes" : "NO", p.maxForce, p.timeSeconds,
                             p.evaluations)
              << std::flush;
  };
  const objective::ScanResult r =
      objective::runScan(in.cell.cell, objective::loadParameters(in.cell),
                         objective::calculatorSettings(in.cell), in.settings);
  printTable(std::cout, r);
  objective::writeScanCurve(r, in.jsonPath, in.csvPath);
  std::cerr << "wrote " << in.jsonPath << (in.csvPath.empty() ? "" : " and " + in.csvPath) << "\n";
  if (r.complete && fileOutputEnabled()) {  // read back from the JSON, which rank 0 alone writes
    std::string png = o.png;
    if (png.empty()) png = std::filesystem::path(in.jsonPath).replace_extension(".png").string();
    writeScanPlot(in.jsonPath, png);
  }
  objective::writeScanStructures(r, in.structurePrefix);
  if (!r.complete) {
    std::cerr << fmt::format("mesochain: stopped after {} new points as asked; continue with "
                             "--resume\n", r.computed);
    return kStoppedAsAsked;
  }
  for (const auto& p : r.points)
    if (!p.converged) {
      std::cerr << "mesochain: warning: some points did not converge within the step limit\n";
      return kNotConverged;
    }
  return 0;
}
}  // namespace

Command makeScanCommand() {
  auto opts = std::make_shared<ScanOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [opts, sub](CLI::App& app) {
    auto* s = app.add_subcommand("scan", "deformation scan (stretch, twist, bend) of a cell");
    s->add_option("scan", opts->scanFile, "scan input file (TOML, docs/scan-file.md)")->required();
    s->add_flag("--resume", opts->resume,
                "continue from the checkpoint of the scan file (refused if the input changed)");
    s->add_option("--stop-after", opts->stopAfter,
                  "compute at most N new points, then stop (resume later with --resume)")
        ->check(integerIn(0, 1000000000));
    s->add_option("-o,--output-dir", opts->outputDir,
                  "folder of the outputs: the [output] paths of the scan file are relative to it")
        ->check(nonEmptyPath());
    s->add_option("--png", opts->png,
                  "PNG of the finished curve with its fit (default: the curve JSON with .png)")
        ->check(nonEmptyPath());
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opts] { return runScanCommand(*opts); };
  return c;
}

}  // namespace mesochain::app
