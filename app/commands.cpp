#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeDemCommand();
Command makeBenchCommand();
Command makeBuildCommand();
Command makeBeamCommand();
Command makeScanCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(), makeScanCommand(), makeBuildCommand(),
          makeBeamCommand(),    makeDemCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
