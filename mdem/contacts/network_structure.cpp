#include "mdem/contacts/network_structure.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "mdem/contacts/bundle_sizes.hpp"

namespace mesochain::mdem {

NetworkStructure networkStructure(const ContactNeighbourhood& nb, const Bodies& b, double maxGap, double maxAngle,
                                  int axis) {
  NetworkStructure r;
  const double cosMax = std::cos(maxAngle);
  std::vector<std::pair<int, int>> aligned;
  for (const auto& [i, j] : nb.list().pairs()) {
    const Segment a = nb.segment(b, i), s = nb.imageNear(b, j, a.centre);
    if (wallGap(a, s, nb.radius(b.type[i]), nb.radius(b.type[j])) > maxGap) continue;
    ++r.contacts;
    if (std::abs(a.axis.dot(s.axis)) < cosMax) continue;
    ++r.aligned;
    aligned.emplace_back(i, j);
  }
  const BundleSizeDistribution d = bundleSizeDistribution(b.size(), aligned);
  r.bundles = d.bundles, r.elementsInBundles = d.elementsInBundles, r.largestBundle = d.largest, r.meanBundle = d.mean;
  // Orientation tensor of the in-plane projections.
  double qxx = 0.0, qxy = 0.0, qyy = 0.0;
  int counted = 0;
  for (int i = 0; i < b.size(); ++i) {
    const Vec3 u = rotate(b.orientation[i], Vec3::UnitZ());
    const double n = std::hypot(u.x(), u.y());
    if (n < 1e-6) continue;
    const double x = u.x() / n, y = u.y() / n;
    qxx += x * x, qxy += x * y, qyy += y * y;
    ++counted;
  }
  if (counted > 0) {
    qxx /= counted, qxy /= counted, qyy /= counted;
    r.orderParameter = std::sqrt((qxx - qyy) * (qxx - qyy) + 4.0 * qxy * qxy);  // lambda1 - lambda2
    r.axisAlignment = axis == 0 ? qxx - qyy : qyy - qxx;
  }
  return r;
}

}  // namespace mesochain::mdem
