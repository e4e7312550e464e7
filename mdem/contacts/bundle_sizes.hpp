#pragma once
// The bundle-size distribution of a tube network (issue 12, item 4): a bundle is a connected
// group of elements joined by aligned contacts (two elements of different tubes, or of one tube
// far apart along it, whose walls are closer than a contact gap and whose axes cross below an
// aligned angle); an element in no aligned contact belongs to no bundle. Sizes are counted in
// elements and grouped in classes [2^k, 2^(k+1)) elements, k = 1, 2, ... (a bundle has at least
// two elements); for each class: how many bundles, and the fraction of all elements in them
// (the element-weighted distribution, which a few large bundles dominate, as in papers that
// report the share of tubes in bundles of a given size).
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "mdem/contacts/element_pairs.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

struct BundleSizeDistribution {
  int elements = 0;  // all elements of the network
  int bundles = 0, elementsInBundles = 0, largest = 0;
  double mean = 0.0;                          // elements per bundle
  std::vector<int> bundlesInClass;            // class k - 1 holds sizes [2^k, 2^(k+1))
  std::vector<double> elementFractionInClass; // elements in those bundles / elements
  // Lower edge of class c (2, 4, 8, ...).
  static long classLower(std::size_t c) { return 2L << c; }
};

// Union-find over the aligned pairs (i, j index elements 0..elements-1).
BundleSizeDistribution bundleSizeDistribution(int elements, const std::vector<std::pair<int, int>>& alignedPairs);

// The pairs of `contacts` whose element axes cross below alignedAngle (rad).
std::vector<std::pair<int, int>> alignedPairs(const Bodies& bodies, const std::vector<ClosePair>& contacts,
                                              double alignedAngle);

// The aligned contacts of a scene's elements from their positions alone (element_pairs.hpp:
// closePairs with the scene's periodic axes and the exclusion along a tube of `excludeWithin`
// elements), then their bundles.
BundleSizeDistribution sceneBundleSizes(const Scene& scene, double contactGap, double alignedAngle, int excludeWithin);

// {elements, bundles, elements_in_bundles, largest, mean, classes: [{from, to, bundles,
// element_fraction}, ...]}; `to` is exclusive.
nlohmann::ordered_json bundleSizesJson(const BundleSizeDistribution& d);

}  // namespace mesochain::mdem
