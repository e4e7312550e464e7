#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeDemCommand();
Command makeBenchCommand();
Command makeBuildCommand();
Command makeBeamCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(), makeBuildCommand(), makeBeamCommand(), makeDemCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
