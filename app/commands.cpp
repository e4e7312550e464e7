#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand();

std::vector<Command> allCommands() {
  return {makeVersionCommand()};
}

}  // namespace mesochain::app
