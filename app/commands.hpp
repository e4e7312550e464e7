#pragma once
// Registry of subcommands. Each app/cmd_NAME.cpp defines `Command makeNameCommand()`; add it to
// allCommands() in commands.cpp.
#include <vector>

#include "app/cli/command.hpp"

namespace mesochain::app {

std::vector<Command> allCommands();

}  // namespace mesochain::app
