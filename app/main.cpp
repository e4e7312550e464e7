// mesochain: from quantum mechanics to a mesoscale model of carbon filaments.
// One subcommand per driver file (app/cmd_*.cpp); each registers itself in commands.hpp.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "common/errors.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mesochain: objective-cell DFTB, beams and mesoscale DEM for carbon filaments"};
  app.require_subcommand(1);
  std::vector<mesochain::app::Command> commands = mesochain::app::allCommands();
  for (auto& c : commands) c.attach(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (auto& c : commands)
      if (c.selected()) return c.run();
  } catch (const mesochain::InputError& e) {
    std::cerr << "mesochain: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mesochain: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
