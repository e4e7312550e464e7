// mesochain: from quantum mechanics to a mesoscale model of carbon filaments.
// One subcommand per driver file (app/cmd_*.cpp); each registers itself in commands.hpp.
// Global options (before or after the subcommand): --version, -q, -v, --set, --unset; exit codes in
// app/exit_codes.hpp (docs/command-line.md). The parsing, MPI and error handling shared with
// mesochain-bench (benchmarks/) are app/cli/program.cpp.
#include "app/cli/program.hpp"
#include "app/commands.hpp"

int main(int argc, char** argv) {
  using namespace mesochain::app;
  return runProgram(argc, argv,
                    Program{"mesochain",
                            "mesochain: objective-cell DFTB, beams and mesoscale DEM for carbon filaments",
                            &allCommands});
}
