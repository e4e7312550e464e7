// `mesochain run CELL.toml [--json OUT] [--structure PREFIX] [--unroll N]`: energy, forces or
// relaxation of an objective cell.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include "app/commands.hpp"
#include "app/run_report.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "objective/core/cell_file.hpp"
#include "objective/core/gen_file.hpp"
#include "objective/core/xyz_file.hpp"
#include "objective/drivers/cell_calculator.hpp"
#include "objective/drivers/relax.hpp"

namespace mesochain::app {

namespace {
struct RunOptions {
  std::string cellFile;
  std::string json;
  std::string structure;
  long unroll = 0;
};

void writeStructures(const std::string& prefix, const objective::ObjectiveCell& cell,
                     const dftb::Result& r, long unroll) {
  objective::XyzExtras extras;
  extras.energy = r.freeEnergy;
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
  const objective::CellInput in = objective::readCellFile(o.cellFile);
  const dftb::Calculator calc = objective::makeCalculator(in);
  const bool tty = isatty(STDERR_FILENO);
  std::unique_ptr<objective::RelaxOutcome> relax;
  dftb::Result result;
  objective::ObjectiveCell cell = in.cell;
  if (in.task.type == "relax") {
    objective::RelaxSettings rs;
    rs.forceTolerance = in.task.forceTolerance;
    rs.axialTolerance = in.task.forceTolerance;
    rs.maxSteps = in.task.maxSteps;
    rs.relaxTranslation = in.task.relaxTranslation;
    rs.progress = [tty](int step, double f, double fmax) {
      std::cerr << fmt::format("{}relax: evaluation {:4d}  F = {:.10f} Ha  max|force| = {:.2e} Ha/Bohr{}",
                               tty ? "\r" : "", step, f, fmax, tty ? "   " : "\n");
    };
    relax = std::make_unique<objective::RelaxOutcome>(objective::relax(calc, cell, rs));
    if (tty) std::cerr << "\n";
    cell = relax->cell;
    result = relax->result;
  } else {
    const bool forces = in.task.type == "forces";
    result = calc.evaluate(cell, {forces, forces});
  }
  printSummary(std::cout, in, cell, result, relax.get());
  if (!o.json.empty()) {
    std::ofstream f(o.json);
    if (!f) throw InputError(o.json, "cannot open the JSON output file for writing");
    f << resultJson(in, cell, result, relax.get()).dump(2) << "\n";
    std::cerr << "wrote " << o.json << "\n";
  }
  std::string prefix = o.structure;
  if (prefix.empty() && relax)
    prefix = std::filesystem::path(o.cellFile).stem().string() + "-relaxed";
  if (!prefix.empty()) writeStructures(prefix, cell, result, o.unroll);
  if (relax && !relax->converged) {
    std::cerr << "mesochain: warning: relaxation did not converge within the step limit\n";
    return 3;
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
    s->add_option("cell", opts->cellFile, "objective-cell input file (TOML)")->required();
    s->add_option("--json", opts->json, "write the results JSON here");
    s->add_option("--structure", opts->structure,
                  "write the final cell as PREFIX.xyz and PREFIX.gen (default for relax: "
                  "<cell>-relaxed)");
    s->add_option("--unroll", opts->unroll,
                  "also write PREFIX-unrolled.xyz with this many screw steps of images");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opts] { return runCell(*opts); };
  return c;
}

}  // namespace mesochain::app
