#pragma once
// Default parameter paths of the benchmarks: the pbc-0-3 set found where `[parameters] set`
// finds it (MESOCHAIN_PARAMS_PATH, the installed params beside the binary, the source tree;
// input/cell_file.hpp), so an installed binary runs them without the source tree.
#include <filesystem>
#include <string>

#include "input/cell_file.hpp"

namespace mesochain::app {

// The folder of the default set (the source tree's when none is found: its error then names it).
inline std::string defaultParameterSetFolder() {
  for (const std::string& folder : objective::parameterSetSearchPath()) {
    std::error_code ec;
    if (std::filesystem::is_directory(std::filesystem::path(folder) / "pbc-0-3", ec))
      return (std::filesystem::path(folder) / "pbc-0-3").string();
  }
  return objective::parameterSetsDirectory() + "/pbc-0-3";
}

inline std::string defaultCarbonTable() { return defaultParameterSetFolder() + "/C-C.skf"; }

}  // namespace mesochain::app
