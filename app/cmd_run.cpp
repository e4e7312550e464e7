// `mesochain run CELL.toml|dftb_in.hsd [--json OUT] [--structure PREFIX] [--unroll N] [--plot PNG]`: energy,
// forces or relaxation of an objective cell.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/run_report.hpp"
#include "common/atomic_file.hpp"
#include "common/finite_output.hpp"
#include "common/errors.hpp"
#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "common/progress_bar.hpp"
#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "input/cell_input_file.hpp"
#include "input/cell_file.hpp"
#include "input/gen_file.hpp"
#include "input/xyz_file.hpp"
#include "input/cell_calculator.hpp"
#include "objective/drivers/relax.hpp"
#include "objective/drivers/relax_checkpoint.hpp"

namespace mesochain::app {

namespace {
struct RunOptions {
  std::string cellFile;
  std::string json;
  std::string structure;
  long unroll = 0;
  std::string plot;
  // Task relax: where the relaxation stands, every checkpointMinutes (objective/drivers/relax_checkpoint.hpp).
  std::string checkpoint;  // default <cell>-relax.checkpoint.json
  double checkpointMinutes = 10.0;
  bool resume = false;
  long stopAfter = -1;  // evaluations, then stop with the checkpoint written (exit 4)
};

// Thrown from the snapshot callback once --stop-after evaluations are done (at the first accepted
// step after them: a line search may take more than one).
struct StoppedAsAsked {
  int evaluations = 0;
};

// One accepted relaxation step as reported by the progress callback.
struct RelaxTrace {
  std::vector<double> evaluation, freeEnergy, maxForce;
};

// Two panels, log y: the largest atomic force with the tolerance, and |F_k - F_(k-1)| between
// consecutive accepted steps (a step that left F unchanged to the last bit is not drawn; the
// legend counts it).
void writeRelaxPlot(const std::string& path, const RelaxTrace& t, double tolerance) {
  plot::Figure forces("Relaxation: largest atomic force");
  forces.x.label = "energy evaluations";
  forces.y.label = "max |force| (Ha/Bohr)";
  forces.y.scale = plot::Scale::Log10;
  plot::SeriesStyle dots;
  dots.marker = plot::Marker::Circle;
  dots.markerSize = 6;
  forces.add("max |force|", t.evaluation, t.maxForce, dots);
  plot::SeriesStyle dashed;
  dashed.dashed = true;
  dashed.color = plot::Color{110, 110, 110};
  if (!t.evaluation.empty())
    forces.add("tolerance", {t.evaluation.front(), t.evaluation.back()}, {tolerance, tolerance}, dashed);
  plot::Figure change("Relaxation: change of the free energy per step");
  change.x.label = "energy evaluations";
  change.y.label = "|F(k) - F(k-1)| (Ha)";
  change.y.scale = plot::Scale::Log10;
  std::vector<double> x, dF;
  for (std::size_t k = 1; k < t.freeEnergy.size(); ++k)
    if (const double d = std::abs(t.freeEnergy[k] - t.freeEnergy[k - 1]); d > 0) {
      x.push_back(t.evaluation[k]);
      dF.push_back(d);
    }
  const std::size_t zeros = t.freeEnergy.empty() ? 0 : t.freeEnergy.size() - 1 - dF.size();
  dots.color = plot::paletteColor(1);
  change.add(zeros ? fmt::format("|dF| ({} unchanged steps not shown)", zeros) : "|dF|", x, dF, dots);
  plot::writePng(path, plot::aboveEachOther(forces.render(900, 450, path), change.render(900, 450, path)));
  std::cerr << "wrote " << path << "\n";
}

void writeStructures(const std::string& prefix, const objective::CellInput& in,
                     const objective::ObjectiveCell& cell, const dftb::Result& r, long unroll) {
  objective::XyzExtras extras;
  extras.energy = r.freeEnergy;
  extras.settings = &in;  // the settings of the energy, for mesochain.ase (docs/python.md)
  Eigen::Matrix3Xd forces;
  if (r.gradient.size()) {
    forces = -r.gradient;
    extras.forces = &forces;
  }
  objective::writeXyzFile(prefix + ".xyz", cell, extras);
  objective::writeGenFile(prefix + ".gen", cell);
  std::cerr << "wrote " << prefix << ".xyz and " << prefix << ".gen\n";
  if (unroll > 0 && !cell.symmetry.isRing()) {
    objective::writeUnrolledXyzFile(prefix + "-unrolled.xyz", cell, 0, unroll - 1);
    std::cerr << "wrote " << prefix << "-unrolled.xyz (" << unroll << " screw steps)\n";
  }
}

int runCell(const RunOptions& o) {
  const objective::CellInput in = input::readCellInputFile(o.cellFile);
  // Every output is checked before the computation: a relaxation is not lost to a bad path.
  const std::string cl = "<command line>";
  if (!o.json.empty()) requireWritableOutput(o.json, cl, "option --json");
  if (!o.plot.empty()) requireWritableOutput(o.plot, cl, "option --plot");
  const std::string prefix = !o.structure.empty() ? o.structure
                             : in.task.type == "relax"
                                 ? std::filesystem::path(o.cellFile).stem().string() + "-relaxed"
                                 : std::string();
  if (!prefix.empty()) requireWritableOutput(prefix + ".xyz", cl, "option --structure");
  const bool relaxing = in.task.type == "relax";
  const std::string checkpoint =
      !relaxing ? std::string()
      : !o.checkpoint.empty() ? o.checkpoint
                              : std::filesystem::path(o.cellFile).stem().string() + "-relax.checkpoint.json";
  if (!relaxing && (!o.checkpoint.empty() || o.resume || o.stopAfter >= 0))
    throw InputError(cl, o.resume ? "option --resume" : o.stopAfter >= 0 ? "option --stop-after" : "option --checkpoint",
                     "task " + in.task.type + " in " + o.cellFile, "a cell file with task relax (only a relaxation is checkpointed)");
  std::error_code ec;
  const bool haveCheckpoint = relaxing && std::filesystem::exists(checkpoint, ec);
  if (haveCheckpoint && !o.resume)
    throw InputError(checkpoint, "", "the checkpoint of an interrupted relaxation of a cell",
                     "--resume to continue it, or remove the file to start afresh");
  if (relaxing) requireWritableOutput(checkpoint, cl, "option --checkpoint");
  if (o.unroll > 0 && !prefix.empty()) {
    const long long atoms = objective::unrolledAtomCount(in.cell, 0, o.unroll - 1);
    if (atoms > objective::kMaxUnrolledAtoms)
      throw InputError(cl, "option --unroll",
                       fmt::format("{} screw steps: {} atoms (about {:.3g} GB)", o.unroll, atoms,
                                   atoms * 60e-9),
                       fmt::format("at most {} unrolled atoms ({} steps of this cell)",
                                   objective::kMaxUnrolledAtoms,
                                   objective::kMaxUnrolledAtoms /
                                       (in.cell.atomCount() * in.cell.symmetry.rotationOrder())));
  }
  if (!o.plot.empty() && in.task.type != "relax")
    throw InputError("<command line>", "option --plot", "task " + in.task.type + " in " + o.cellFile,
                     "a cell file with task relax (the plot shows the relaxation history)");
  const dftb::Calculator calc = objective::makeCalculator(in);
  // The terminal rule of common/progress_bar.hpp: one redrawn line on a terminal, a line per
  // evaluation otherwise, nothing with -q.
  const ProgressMode mode = progressMode();
  const bool tty = mode == ProgressMode::Bar;
  std::unique_ptr<objective::RelaxOutcome> relax;
  dftb::Result result;
  objective::ObjectiveCell cell = in.cell;
  if (in.task.type == "relax") {
    objective::RelaxSettings rs;
    rs.forceTolerance = in.task.forceTolerance;
    rs.axialTolerance = in.task.forceTolerance;
    rs.maxSteps = in.task.maxSteps;
    rs.relaxTranslation = in.task.relaxTranslation;
    RelaxTrace trace;
    rs.progress = [tty, mode, &trace](int step, double f, double fmax) {
      trace.evaluation.push_back(step);
      trace.freeEnergy.push_back(f);
      trace.maxForce.push_back(fmax);
      if (mode == ProgressMode::Silent) return;
      std::cerr << fmt::format("{}relax: evaluation {:4d}  F = {:.10f} Ha  max|force| = {:.2e} Ha/Bohr{}",
                               tty ? "\r" : "", step, f, fmax, tty ? "   " : "\n");
    };
    const objective::RelaxInput identity{in.cell, calc.settings(), rs, objective::parameterIdentity(in)};
    if (haveCheckpoint) {
      rs.resumeFrom = objective::readRelaxCheckpoint(checkpoint, identity);
      std::cerr << fmt::format("mesochain: continuing the relaxation from {} ({} evaluations, {} fixed-T relaxation(s) done)\n",
                               checkpoint, rs.resumeFrom->evaluations, rs.resumeFrom->history.size());
    }
    rs.snapshotSeconds = o.stopAfter >= 0 ? 0.0 : 60.0 * o.checkpointMinutes;
    rs.snapshot = [&](const objective::RelaxProgress& p) {
      objective::writeRelaxCheckpoint(checkpoint, identity, p);
      if (o.stopAfter >= 0 && p.evaluations >= o.stopAfter) throw StoppedAsAsked{p.evaluations};
    };
    try {
      relax = std::make_unique<objective::RelaxOutcome>(objective::relax(calc, cell, rs));
    } catch (const StoppedAsAsked& stop) {
      if (tty) std::cerr << "\n";
      std::cerr << fmt::format("mesochain: stopped after {} evaluations as asked; {} holds where the relaxation stands "
                               "(rerun with --resume to continue)\n", stop.evaluations, checkpoint);
      return kStoppedAsAsked;
    }
    std::filesystem::remove(checkpoint, ec);  // finished: the outputs below hold the result
    if (tty && !trace.evaluation.empty()) std::cerr << "\n";
    cell = relax->cell;
    result = relax->result;
    if (!o.plot.empty()) writeRelaxPlot(o.plot, trace, rs.forceTolerance);
  } else {
    const bool forces = in.task.type == "forces";
    result = calc.evaluate(cell, {forces, forces});
  }
  // With --json - the JSON is the standard output and the summary goes to stderr.
  printSummary(isStandardOutput(o.json) ? std::cerr : std::cout, in, cell, result, relax.get());
  if (!o.json.empty()) {
    const nlohmann::json j = resultJson(in, cell, result, relax.get());
    requireFiniteJson(j, o.json);
    writeFileAtomically(o.json, j.dump(2) + "\n");
    if (!isStandardOutput(o.json)) std::cerr << "wrote " << o.json << "\n";
  }
  if (!prefix.empty()) writeStructures(prefix, in, cell, result, o.unroll);
  if (relax && !relax->converged) {
    std::cerr << "mesochain: warning: relaxation did not converge within the step limit\n";
    return kNotConverged;
  }
  return 0;
}
}  // namespace

Command makeRunCommand() {
  auto opts = std::make_shared<RunOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [opts, sub](CLI::App& app) {
    auto* s = app.add_subcommand("run", "energy, forces or relaxation of an objective cell");
    s->add_option("cell", opts->cellFile,
                  "objective-cell input: a cell file (TOML) or a DFTB+ input (*.hsd, the subset of "
                  "docs/cell-file.md)")
        ->required();
    s->add_option("--json", opts->json, "write the results JSON here (- for the standard output)")
        ->check(nonEmptyPath());
    s->add_option("--structure", opts->structure,
                  "write the final cell as PREFIX.xyz and PREFIX.gen (default for relax: "
                  "<cell>-relaxed)");
    s->add_option("--unroll", opts->unroll,
                  "also write PREFIX-unrolled.xyz with this many screw steps of images")
        ->check(integerIn(1, 1000000000));
    s->add_option("--plot", opts->plot,
                  "task relax: write the relaxation history (max force, energy change) as PNG");
    s->add_option("--checkpoint", opts->checkpoint,
                  "task relax: where the relaxation stands, rewritten every --checkpoint-minutes (default "
                  "<cell>-relax.checkpoint.json; removed when the relaxation ends)")
        ->check(nonEmptyPath());
    s->add_option("--checkpoint-minutes", opts->checkpointMinutes,
                  "task relax: minutes between checkpoints (default 10; 0: every accepted step)")
        ->check(CLI::Range(0.0, 1e9));
    s->add_flag("--resume", opts->resume, "task relax: continue from the checkpoint when it exists");
    s->add_option("--stop-after", opts->stopAfter,
                  "task relax: stop after this many energy evaluations with the checkpoint written (exit 4)")
        ->check(integerIn(1, 1000000000));
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opts] { return runCell(*opts); };
  return c;
}

}  // namespace mesochain::app
