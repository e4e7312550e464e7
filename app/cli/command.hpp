#pragma once
// One subcommand of a mesochain program (`mesochain`: app/commands.cpp; `mesochain-bench`:
// benchmarks/main.cpp): how it attaches to the parser and how it runs.
#include <functional>

namespace CLI {
class App;
}

namespace mesochain::app {

struct Command {
  // Adds the subcommand and its options to the parser; stores what run() needs.
  std::function<void(CLI::App&)> attach;
  // True when the user chose this subcommand (valid after parsing).
  std::function<bool()> selected;
  // Runs it; returns the process exit code.
  std::function<int()> run;
};

}  // namespace mesochain::app
