#pragma once
// Pairs of elements closer than a wall gap, found with a cell list (NeighbourList) in O(n):
// the overlap check of large generated films and the contact count of the film report.
// Gaps are wall to wall between the axis segments of the elements (cylinder radius, or half a
// brick's thickness), with the minimum image on the scene's periodic axes.
#include <vector>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

struct ClosePair {
  int i = -1, j = -1;  // i < j
  double gap = 0.0;    // nm, wall to wall
};

// All pairs with wall gap < maxGap, except pairs of one filament (connected bonds) at most
// `excludeWithin` elements apart along it. Sorted by (i, j).
std::vector<ClosePair> closePairs(const Scene& scene, double maxGap, int excludeWithin);

// Throws InputError when two elements of different filaments, or of one filament more than
// `excludeWithin` apart along it (a tube meeting itself, or its periodic image), have a wall
// gap below minimumGap. The cell-list counterpart of checkNoOverlaps (network_generator.hpp).
void checkNoOverlapsCellList(const Scene& scene, double minimumGap, int excludeWithin);

}  // namespace mesochain::mdem
