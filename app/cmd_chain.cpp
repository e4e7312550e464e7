// `mesochain chain FILE.toml [--stop-after N] [--check]`: the reference, scans, beam, bricks and
// mDEM cantilever check of one filament from one file, every stage checkpointed and resumable
// (app/chain_run.hpp, docs/chain.md).
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/chain_run.hpp"
#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "common/errors.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::app {

Command makeChainCommand() {
  auto opt = std::make_shared<ChainOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [opt, sub](CLI::App& app) {
    CLI::App* s = app.add_subcommand("chain", "reference -> scans -> beam -> bricks -> mDEM check of one filament, resumable (docs/chain.md)");
    s->add_option("file", opt->file, "chain file (TOML)")->required();
    s->add_option("--stop-after", opt->stopAfter, "compute at most N new relaxations (the reference, scan points), then stop (rerun to resume)")
        ->check(integerIn(0, 1000000000));
    s->add_flag("--check", opt->check,
                "validate the chain file and the scan files it generates, list the stages, compute nothing");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    // The chain reads back the curves it wrote, which only rank 0 writes (docs/cluster.md).
    if (parallel::Communicator::world().size() > 1)
      throw InputError("<command line>", "mesochain chain",
                       fmt::format("{} MPI ranks", parallel::Communicator::world().size()),
                       "one process (run the chain without mpirun; `mpirun ... mesochain scan` "
                       "distributes a scan)");
    return runChain(*opt);
  };
  return c;
}

}  // namespace mesochain::app
