// `mesochain bench knobs`: what each accuracy knob of a finished scan costs and changes
// (bench_knobs.cpp). The timing benchmarks (dftb, kpoints, dem, ewald, scc, network, sliding,
// zipping, scan, skgen) are the program mesochain-bench (benchmarks/main.cpp).
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"

namespace mesochain::app {

Command makeBenchKnobsCommand();

Command makeBenchCommand() {
  auto subs = std::make_shared<std::vector<Command>>(std::vector<Command>{makeBenchKnobsCommand()});
  Command c;
  c.attach = [subs](CLI::App& app) {
    auto* bench = app.add_subcommand(
        "bench", "knobs: accuracy against cost of a finished scan (the timing benchmarks are the program "
                 "mesochain-bench: `mesochain-bench --help`)");
    bench->require_subcommand(1);
    for (auto& s : *subs) s.attach(*bench);
  };
  c.selected = [subs] {
    for (auto& s : *subs)
      if (s.selected()) return true;
    return false;
  };
  c.run = [subs] {
    for (auto& s : *subs)
      if (s.selected()) return s.run();
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
