#include "mdem/contacts/element_pairs.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/neighbour_list.hpp"

namespace mesochain::mdem {

namespace {
}  // namespace

std::vector<ClosePair> closePairs(const Scene& scene, double maxGap, int excludeWithin) {
  const Bodies& b = scene.bodies;
  std::vector<ClosePair> out;
  if (b.size() < 2) return out;
  double longest = 0.0, thickest = 0.0;
  std::vector<double> halfLength(scene.elementTypes.size());
  for (std::size_t t = 0; t < scene.elementTypes.size(); ++t) {
    halfLength[t] = 0.5 * scene.elementTypes[t].length;
    longest = std::max(longest, scene.elementTypes[t].length);
    thickest = std::max(thickest, scene.elementTypes[t].contactRadius());
  }
  // Centre distance below which the wall gap can be below maxGap: two half lengths + 2 R + gap.
  const double range = longest + 2.0 * thickest + std::max(0.0, maxGap);
  NeighbourList list(range, 1e-6, scene.periodic);
  const FilamentTopology topo = buildTopology(b.size(), scene.bonds, excludeWithin, scene.contacts.closedFilaments);
  list.update(b, halfLength, topo);
  for (const auto& [i, j] : list.pairs()) {
    const Segment si{b.position[i], rotate(b.orientation[i], Vec3::UnitZ()), halfLength[b.type[i]]};
    const Segment sj{b.position[i] + scene.periodic.minimumImage(b.position[j] - b.position[i]),
                     rotate(b.orientation[j], Vec3::UnitZ()), halfLength[b.type[j]]};
    const double gap = wallGap(si, sj, scene.elementTypes[b.type[i]].contactRadius(), scene.elementTypes[b.type[j]].contactRadius());
    if (gap < maxGap) out.push_back({i, j, gap});
  }
  return out;
}

void checkNoOverlapsCellList(const Scene& scene, double minimumGap, int excludeWithin) {
  const std::vector<ClosePair> close = closePairs(scene, minimumGap, excludeWithin);
  if (close.empty()) return;
  const ClosePair& p = *std::min_element(close.begin(), close.end(), [](const ClosePair& a, const ClosePair& b) { return a.gap < b.gap; });
  throw InputError(scene.source, "elements",
                   fmt::format("{} overlapping pairs, the closest elements {} and {} (wall gap {:.4g} nm)", close.size(), p.i, p.j, p.gap),
                   fmt::format("elements at least {:.4g} nm apart (wall to wall), except neighbours along a tube", minimumGap));
}

}  // namespace mesochain::mdem
