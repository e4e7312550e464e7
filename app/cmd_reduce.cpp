// `mesochain reduce CELL -o OUT.toml [--tolerance-bohr TOL]`: finds the largest rotation about
// the axis that maps the cell's structure onto itself beyond its declared rotation order N_a
// (objective/core/rotation_reduction.hpp) and writes the cell with rotation order N_a m and one
// atom per orbit, every other setting kept (input/cell_reduction.hpp): `mesochain run OUT.toml`
// gives the same energy per atom with m problems of 1/m the size per k-point. With no extra
// rotation (m = 1) nothing is written and the exit code is 0.
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "input/cell_file.hpp"
#include "input/cell_input_file.hpp"
#include "input/cell_reduction.hpp"
#include "objective/core/rotation_reduction.hpp"

namespace mesochain::app {

namespace {
struct ReduceOptions {
  std::string input;
  std::string output;
  double toleranceBohr = objective::kDefaultReductionToleranceBohr;
};

int reduce(const ReduceOptions& o) {
  requireWritableOutput(o.output, "<command line>", "option --output");
  const objective::CellInput in = input::readCellInputFile(o.input);
  const objective::RotationReduction r = objective::findExtraRotation(in.cell, o.toleranceBohr);
  std::ostream& log = isStandardOutput(o.output) ? std::cerr : std::cout;
  const int na = in.cell.symmetry.rotationOrder();
  if (r.extraOrder == 1) {
    log << fmt::format("no extra rotational symmetry (rotation order {}, {} atoms, tolerance {:g} Bohr); "
                       "nothing written\n",
                       na, in.cell.atomCount(), o.toleranceBohr);
    return 0;
  }
  const objective::CellInput out = objective::reducedCellInput(in, r);
  objective::writeCellFile(o.output, out);
  log << fmt::format("rotation order {} -> {}: {} atoms -> {} atoms; run {} for the same energy per atom\n",
                     na, out.cell.symmetry.rotationOrder(), in.cell.atomCount(), out.cell.atomCount(),
                     o.output);
  // The representatives keep their positions, so their forces in the reduced run are the
  // original atoms' forces; the other atoms' are rotated copies (docs/command-line.md).
  bool leading = true;
  for (size_t i = 0; i < r.representatives.size(); ++i) leading = leading && r.representatives[i] == static_cast<int>(i);
  if (leading) {
    log << fmt::format("its atoms are atoms 1..{} of the original (same positions, same forces)\n",
                       r.representatives.size());
  } else {
    log << "its atoms are these atoms of the original (same positions, same forces):";
    for (int a : r.representatives) log << ' ' << a + 1;
    log << "\n";
  }
  return 0;
}
}  // namespace

Command makeReduceCommand() {
  auto opts = std::make_shared<ReduceOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [opts, sub](CLI::App& app) {
    auto* s = app.add_subcommand("reduce", "write the cell with the rotational symmetry it has but does not declare");
    s->add_option("input", opts->input, "the cell: a cell file or a DFTB+ input (*.hsd)")->required();
    s->add_option("-o,--output", opts->output, "the reduced cell file to write (- for the standard output)")
        ->required()
        ->check(nonEmptyPath());
    s->add_option("--tolerance-bohr", opts->toleranceBohr,
                  "how far (Bohr) a rotated atom may lie from its image (default 1e-5)")
        ->check(finiteNumber(false, objective::kMaximumReductionToleranceBohr));
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opts] { return reduce(*opts); };
  return c;
}

}  // namespace mesochain::app
