// `mesochain bench WHAT`: benchmarks that print ratios and shares (never timed tests).
// Each benchmark is a Command attached under `bench` (bench_*.cpp).
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"

namespace mesochain::app {

Command makeBenchDftbCommand();
Command makeBenchKpointsCommand();
Command makeBenchDemCommand();
Command makeBenchEwaldCommand();
Command makeBenchSccCommand();
Command makeBenchNetworkCommand();
Command makeBenchSlidingCommand();
Command makeBenchZippingCommand();
Command makeBenchScanCommand();
Command makeBenchSkgenCommand();
Command makeBenchKnobsCommand();

Command makeBenchCommand() {
  auto subs = std::make_shared<std::vector<Command>>(std::vector<Command>{
      makeBenchDftbCommand(), makeBenchKpointsCommand(), makeBenchDemCommand(),
      makeBenchEwaldCommand(), makeBenchSccCommand(), makeBenchNetworkCommand(), makeBenchSlidingCommand(), makeBenchZippingCommand(),
      makeBenchScanCommand(), makeBenchSkgenCommand(), makeBenchKnobsCommand()});
  Command c;
  c.attach = [subs](CLI::App& app) {
    auto* bench = app.add_subcommand(
        "bench", "benchmarks: dftb, kpoints, dem, ewald, scc, network, sliding, zipping, scan, skgen, knobs");
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
