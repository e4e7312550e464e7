#pragma once
// The chain file of `mesochain chain` (TOML, format 1; docs/chain.md): the filament's cell file,
// the protocol and the stages; and the scan files the chain generates from it.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <toml.hpp>

namespace mesochain::app {

struct ScanStage {
  const char* name;       // the chain file's table and the stage name
  const char* kind;       // scan kind
  const char* direction;  // bend direction, "" otherwise
};

// The knob settings of the [knobs] table (values as `mesochain bench knobs` takes them on its
// command line, docs/benchmarks.md) and the scan stages they are applied to.
struct ChainKnobs {
  bool given = false;
  std::vector<std::string> stages;  // default: every scan stage of the chain
  std::vector<std::string> kpoints, angular, sampling, dispersion, temperature;
};

struct ChainFile {
  std::filesystem::path file, dir;  // the chain file and the stages' folder (absolute)
  std::string cellPath;             // absolute
  // An inline [cell] table (the cell file's sections in the chain file itself) instead of
  // `cell = "FILE"`: written by the run to chain-cell.toml in the stages' folder (cellPath).
  std::optional<toml::value> inlineCell;
  std::map<std::string, std::string> inlineCellTables;  // its "A-B" tables as the cell reader found them
  double forceTolerance = 1e-4;     // Ha/Bohr
  int cellsPerBrick = 0;
  std::string section;              // "" = automatic
  std::vector<std::pair<const ScanStage*, toml::value>> scans;  // in stage order
  // false: no beam, bricks or cantilever (cells that are no filament, e.g. a sector of a stack,
  // whose bend curve is per sector cell); each curve is fitted alone instead.
  bool beam = true;
  double cantileverTolerance = 0.01;  // relative ([cantilever] tolerance)
  ChainKnobs knobs;
};

// Reads and checks the chain file; InputError naming the file and key (line) otherwise.
ChainFile readChainFile(const std::string& path);

// The inline cell as a cell file (its relative paths, [geometry] file and the [parameters]
// prefix and tables, made absolute from the chain file's folder, where they were written).
std::string inlineCellText(const ChainFile& chain);
// The inline cell's content in a canonical form (keys sorted, numbers in shortest round-trip
// form): part of the stages' input hash, independent of how toml11 orders a table.
std::string inlineCellIdentity(const ChainFile& chain);

// The scan file of a stage: the chain's table keys verbatim, the cell, the kind, the relaxation,
// the outputs (curve, checkpoint, relaxed structures) in the chain's folder, and (withReference)
// the shared reference `reference.json`. `outputName` names the outputs (the stage's name).
std::string scanFileText(const ChainFile& chain, const ScanStage& stage, const toml::value& keys,
                         const std::string& outputName, bool withReference);

// FNV-1a, 64 bit (Fowler, Noll & Vo), of a stage's inputs, as 16 hex digits.
std::string chainHash(const std::string& text);

}  // namespace mesochain::app
