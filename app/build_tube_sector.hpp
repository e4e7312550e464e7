#pragma once
// `mesochain build tube-sector`: an angular sector of concentric walls, each wall an exact
// sector with its own atom count (objective/core/tube_sector_builder.hpp, docs/cell-file.md).
// Walls are given as n,m pairs or as a family (armchair or zigzag) with an inner index, a count
// and an index step. Attached under `build` by cmd_build.cpp.
#include <string>
#include <utility>
#include <vector>

#include "objective/core/cell.hpp"

namespace CLI {
class App;
}

namespace mesochain::app {

struct TubeSectorOptions {
  std::vector<std::string> walls;  // "n,m" (parsed by cmd_build.cpp)
  std::string family;              // "armchair" | "zigzag" (instead of walls)
  int inner = 0, count = 0, step = 0;  // step 0: the index step nearest the spacing
  double spacing = 3.4;            // Å, for the default step
  int rotationOrder = 0;           // 0: the largest exact sector, gcd of all indices
};

void addTubeSectorOptions(CLI::App& sub, TubeSectorOptions& o);

struct BuiltTubeSector {
  objective::ObjectiveCell cell;
  std::string fileName;  // default output name
  std::string what;      // for the message
};

// `walls` are the parsed n,m pairs of o.walls (empty with a family); bond length in Bohr.
BuiltTubeSector buildTubeSector(const TubeSectorOptions& o, std::vector<std::pair<int, int>> walls, double bond);

}  // namespace mesochain::app
