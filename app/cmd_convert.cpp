// `mesochain convert INPUT -o CELL.toml`: reads any input mesochain runs (a DFTB+ dftb_in.hsd or
// a cell file) and writes the equivalent cell file (docs/cell-file.md): `mesochain run` of the
// written file computes what `mesochain run INPUT` computes.
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/units.hpp"
#include "input/cell_input_file.hpp"
#include "input/cell_file.hpp"

namespace mesochain::app {

namespace {
struct ConvertOptions {
  std::string input;
  std::string output;
};

int convert(const ConvertOptions& o) {
  requireWritableOutput(o.output, "<command line>", "option --output");
  const objective::CellInput in = input::readCellInputFile(o.input);
  objective::writeCellFile(o.output, in);
  (isStandardOutput(o.output) ? std::cerr : std::cout)
      << fmt::format("wrote {}: {} atoms, T = {:.6f} Å, rotation order {}, task {}\n", o.output,
                     in.cell.atomCount(), in.cell.symmetry.translation() * units::kBohrInAngstrom,
                     in.cell.symmetry.rotationOrder(), in.task.type);
  return 0;
}
}  // namespace

Command makeConvertCommand() {
  auto opts = std::make_shared<ConvertOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [opts, sub](CLI::App& app) {
    auto* s = app.add_subcommand("convert", "write the cell file (TOML) equivalent to an input (a DFTB+ dftb_in.hsd)");
    s->add_option("input", opts->input, "the input: a DFTB+ input (*.hsd) or a cell file")->required();
    s->add_option("-o,--output", opts->output, "the cell file to write (- for the standard output)")
        ->required()
        ->check(nonEmptyPath());
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opts] { return convert(*opts); };
  return c;
}

}  // namespace mesochain::app
