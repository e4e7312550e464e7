// mesochain-bench: the timing benchmarks, a program beside mesochain (not compiled into it).
// Each prints ratios, shares and rates of one part of the code (never timed tests); how to run
// them and what they measured is docs/benchmarks.md, dated inputs and results are in bench/.
// One file per benchmark (bench_*.cpp, `Command makeBenchNameCommand()`), listed here; the
// global options, MPI and the error handling are mesochain's own (app/cli/program.hpp).
#include <vector>

#include "app/cli/program.hpp"

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

namespace {

std::vector<Command> benchmarkCommands() {
  return {makeBenchDftbCommand(),    makeBenchKpointsCommand(), makeBenchDemCommand(),     makeBenchEwaldCommand(),
          makeBenchSccCommand(),     makeBenchNetworkCommand(), makeBenchSlidingCommand(), makeBenchZippingCommand(),
          makeBenchScanCommand(),    makeBenchSkgenCommand()};
}

}  // namespace

}  // namespace mesochain::app

int main(int argc, char** argv) {
  using namespace mesochain::app;
  return runProgram(argc, argv,
                    Program{"mesochain-bench",
                            "mesochain-bench: timing benchmarks of mesochain (docs/benchmarks.md): "
                            "dftb, kpoints, dem, ewald, scc, network, sliding, zipping, scan, skgen",
                            &benchmarkCommands});
}
