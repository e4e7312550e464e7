#include "parallel/work_split.hpp"

#include <algorithm>
#include <numeric>

namespace mesochain::parallel {

std::vector<int> balancedOwners(const std::vector<double>& cost, int ranks) {
  const int n = static_cast<int>(cost.size());
  std::vector<int> owner(n, 0);
  if (ranks <= 1) return owner;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
  std::vector<double> load(ranks, 0.0);
  for (int i : order) {
    const int r = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[i] = r;
    load[r] += cost[i];
  }
  return owner;
}

}  // namespace mesochain::parallel
