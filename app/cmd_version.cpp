#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "common/build_info.hpp"

namespace mesochain::app {

// `mesochain version`, the same line as `mesochain --version`.
Command makeVersionCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [sub](CLI::App& app) {
    *sub = app.add_subcommand("version", "print the version and git commit (as --version)");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [] {
    std::cout << versionLine() << "\n";
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
