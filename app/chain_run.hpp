#pragma once
// `mesochain chain FILE.toml` (issue 15, item 1; docs/chain.md): one file names the filament
// (a cell file) and the protocol; the stages run in order, each checkpointed and skipped when
// its inputs are unchanged and its output exists:
//   stretch, twist, bend_soft, bend_hard   `mesochain scan` of a generated scan file (the scan's
//                                          own checkpoint: a killed stage resumes point by point)
//   beam                                   `mesochain beam` of the curves (beam.json, model.toml,
//                                          cantilever.toml, fit PNGs)
// and writes chain.json and chain.md: per stage its status (ran, resumed, skipped), seconds
// and outputs; the constants with their uncertainties; the beam and the brick.
#include <string>

namespace mesochain::app {

struct ChainOptions {
  std::string file;
  int stopAfter = -1;  // >= 0: stop after this many new scan points (exit 4), resume by rerunning
};

// Exit code: 0 done, 3 a scan point did not converge, 4 stopped by stopAfter.
int runChain(const ChainOptions& options);

}  // namespace mesochain::app
