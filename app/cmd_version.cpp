#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"

namespace mesochain::app {

Command makeVersionCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [sub](CLI::App& app) { *sub = app.add_subcommand("version", "print the version"); };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [] {
    std::cout << "mesochain 0.1.0\n";
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
