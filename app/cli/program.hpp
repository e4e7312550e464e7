#pragma once
// The main of every mesochain program (`mesochain`, app/main.cpp; `mesochain-bench`,
// benchmarks/main.cpp): MPI's session, the global options (--version, -q, -v, --set), one
// subcommand out of `commands`, and the error handling with the exit codes of
// app/exit_codes.hpp (docs/command-line.md).
#include <string>
#include <vector>

#include "app/cli/command.hpp"

namespace mesochain::app {

struct Program {
  std::string name;         // what errors and warnings start with ("mesochain: error: ...")
  std::string description;  // the first line of --help
  // The subcommands; called once MPI has started, before the command line is parsed.
  std::vector<Command> (*commands)();
};

// Parses argv, runs the chosen subcommand and returns the process exit code.
int runProgram(int argc, char** argv, const Program& program);

}  // namespace mesochain::app
