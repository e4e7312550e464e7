#pragma once
// Registry of subcommands. Each app/cmd_NAME.cpp defines `Command makeNameCommand()`; add it to
// allCommands() in commands.cpp.
#include <functional>
#include <vector>

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

std::vector<Command> allCommands();

}  // namespace mesochain::app
