#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeDemCommand();
Command makeBenchCommand();
Command makeBuildCommand();
Command makeBeamCommand();
Command makeSkgenCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(), makeBuildCommand(), makeBeamCommand(), makeSkgenCommand(), makeDemCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
