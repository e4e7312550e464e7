#include "mdem/contacts/bundle_sizes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

#include <nlohmann/json.hpp>


namespace mesochain::mdem {

namespace {
int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];  // path halving
  return i;
}
}  // namespace

BundleSizeDistribution bundleSizeDistribution(int elements, const std::vector<std::pair<int, int>>& alignedPairs) {
  BundleSizeDistribution d;
  d.elements = elements;
  std::vector<int> parent(elements);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> joined(elements, 0);
  for (const auto& [i, j] : alignedPairs) {
    joined[i] = joined[j] = 1;
    parent[root(parent, i)] = root(parent, j);
  }
  std::vector<int> size(elements, 0);
  for (int i = 0; i < elements; ++i)
    if (joined[i]) ++size[root(parent, i)];
  for (int s : size) {
    if (s == 0) continue;
    ++d.bundles, d.elementsInBundles += s, d.largest = std::max(d.largest, s);
    // s >= 2: class index floor(log2 s) - 1, exact in integers.
    const std::size_t c = static_cast<std::size_t>(std::bit_width(static_cast<unsigned>(s)) - 2);
    if (d.bundlesInClass.size() <= c) d.bundlesInClass.resize(c + 1, 0), d.elementFractionInClass.resize(c + 1, 0.0);
    ++d.bundlesInClass[c];
    d.elementFractionInClass[c] += s;
  }
  for (double& f : d.elementFractionInClass) f /= elements;
  d.mean = d.bundles > 0 ? static_cast<double>(d.elementsInBundles) / d.bundles : 0.0;
  return d;
}

std::vector<std::pair<int, int>> alignedPairs(const Bodies& b, const std::vector<ClosePair>& contacts, double alignedAngle) {
  const double cosMax = std::cos(alignedAngle);
  std::vector<std::pair<int, int>> aligned;
  for (const ClosePair& p : contacts)
    if (std::abs(rotate(b.orientation[p.i], Vec3::UnitZ()).dot(rotate(b.orientation[p.j], Vec3::UnitZ()))) >= cosMax)
      aligned.emplace_back(p.i, p.j);
  return aligned;
}

BundleSizeDistribution sceneBundleSizes(const Scene& scene, double contactGap, double alignedAngle, int excludeWithin) {
  return bundleSizeDistribution(scene.bodies.size(),
                                alignedPairs(scene.bodies, closePairs(scene, contactGap, excludeWithin), alignedAngle));
}

nlohmann::ordered_json bundleSizesJson(const BundleSizeDistribution& d) {
  nlohmann::ordered_json j;
  j["elements"] = d.elements;
  j["bundles"] = d.bundles;
  j["elements_in_bundles"] = d.elementsInBundles;
  j["largest_elements"] = d.largest;
  j["mean_elements"] = d.mean;
  j["classes"] = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < d.bundlesInClass.size(); ++c)
    j["classes"].push_back({{"from_elements", BundleSizeDistribution::classLower(c)},
                            {"to_elements_exclusive", BundleSizeDistribution::classLower(c + 1)},
                            {"bundles", d.bundlesInClass[c]},
                            {"element_fraction", d.elementFractionInClass[c]}});
  return j;
}

}  // namespace mesochain::mdem
