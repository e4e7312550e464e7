#pragma once
// Which rank computes which item of a list of independent items of known relative cost (the
// k-points of a band solve: a complex-phase point costs about four real ones). Greedy longest-
// processing-time assignment (Graham, SIAM J. Appl. Math. 17, 416 (1969)): items by descending
// cost (ties by index) each to the least loaded rank (ties by rank), deterministic on every rank.
#include <vector>

namespace mesochain::parallel {

// owner[i] in [0, ranks) for every item; ranks >= 1.
std::vector<int> balancedOwners(const std::vector<double>& cost, int ranks);

}  // namespace mesochain::parallel
