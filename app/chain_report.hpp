#pragma once
// The Markdown report of `mesochain chain` (chain.md) and its --check listing (docs/chain.md).
#include <string>

#include <nlohmann/json.hpp>

#include "app/chain_file.hpp"
#include "beam/beam_run.hpp"

namespace mesochain::app {

// chain.md from the report of chain.json (stages, reference, constants, beam, brick,
// cantilever check, knobs' table, warnings); run is null with beam = false.
std::string chainMarkdown(const ChainFile& chain, const nlohmann::json& report, const beam::BeamRun* run);

// --check: reads the cell file and every generated scan file (in a temporary folder, removed
// after) with the scan reader, and the [knobs] settings, and lists the stages on stdout without
// computing anything. Returns 0; bad input throws InputError as a run would.
int checkChain(const ChainFile& chain);

}  // namespace mesochain::app
