#pragma once
// `mesochain chain FILE.toml` (issue 15, item 1; docs/chain.md): one file names the filament
// (a cell file) and the protocol; the stages run in order, each skipped when its inputs are
// unchanged and its output exists, an interrupted one resumed:
//   reference                              the straight reference relaxed once and T0 found
//                                          (objective/drivers/scan_reference.hpp): reference.json
//   stretch, twist, bend_soft, bend_hard   `mesochain scan` of a generated scan file starting
//                                          from the reference (the scan's own checkpoint: a
//                                          killed stage resumes point by point)
//   beam                                   `mesochain beam` of the curves (beam.json, model.toml,
//                                          cantilever.toml, fit PNGs)
//   cantilever                             the cantilever scene run by mdem against beam theory
//                                          of the fitted constants (mdem/cantilever_check.hpp)
//   knobs (with [knobs])                   the accuracy-against-time table of the knobs
// and writes chain.json and chain.md: per stage its status (ran, resumed, skipped), seconds
// and outputs; T0 and the reference energy; the constants with their uncertainties; the beam
// and the brick; the cantilever check; the knobs' table.
#include <string>

namespace mesochain::app {

struct ChainOptions {
  std::string file;
  int stopAfter = -1;  // >= 0: stop after this many new relaxations (exit 4), resume by rerunning
  bool check = false;  // validate the chain file and its scan files, list the stages, compute nothing
};

// Exit code: 0 done, 3 a relaxation did not converge, 4 stopped by stopAfter.
int runChain(const ChainOptions& options);

}  // namespace mesochain::app
