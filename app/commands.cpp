#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();
Command makeDemCommand();
Command makeBenchCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand(), makeDemCommand(), makeBenchCommand()};
}

}  // namespace mesochain::app
