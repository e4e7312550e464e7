#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeDemCommand();
Command makeBenchCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(), makeDemCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
