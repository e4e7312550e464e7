#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeBenchCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
