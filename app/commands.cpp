#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeDemCommand();
Command makeBenchCommand();
Command makeBuildCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(), makeBuildCommand(), makeDemCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
