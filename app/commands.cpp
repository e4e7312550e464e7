#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeRunCommand();
Command makeConvertCommand();
Command makeDemCommand();
Command makeBenchCommand();
Command makeBuildCommand();
Command makeBeamCommand();
Command makeScanCommand();
Command makeSkgenCommand();
Command makeChainCommand();
Command makeReduceCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeRunCommand(),   makeConvertCommand(), makeScanCommand(), makeBuildCommand(),
          makeBeamCommand(),    makeSkgenCommand(), makeDemCommand(),  makeBenchCommand(), makeChainCommand(),
          makeReduceCommand()};
}

}  // namespace mesochain::app
