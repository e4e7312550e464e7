#include "mdem/contacts/network_structure.hpp"

#include <cmath>
#include <numeric>
#include <vector>

namespace mesochain::mdem {

namespace {
int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];  // path halving
  return i;
}
}  // namespace

NetworkStructure networkStructure(const ContactNeighbourhood& nb, const Bodies& b, double maxGap, double maxAngle,
                                  int axis) {
  NetworkStructure r;
  const double cosMax = std::cos(maxAngle);
  std::vector<int> parent(b.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> joined(b.size(), 0);
  for (const auto& [i, j] : nb.list().pairs()) {
    const Segment a = nb.segment(b, i), s = nb.imageNear(b, j, a.centre);
    if (wallGap(a, s, nb.radius(b.type[i]), nb.radius(b.type[j])) > maxGap) continue;
    ++r.contacts;
    if (std::abs(a.axis.dot(s.axis)) < cosMax) continue;
    ++r.aligned;
    joined[i] = joined[j] = 1;
    parent[root(parent, i)] = root(parent, j);
  }
  std::vector<int> size(b.size(), 0);
  for (int i = 0; i < b.size(); ++i)
    if (joined[i]) ++size[root(parent, i)];
  for (int s : size)
    if (s > 0) ++r.bundles, r.elementsInBundles += s, r.largestBundle = std::max(r.largestBundle, s);
  r.meanBundle = r.bundles > 0 ? static_cast<double>(r.elementsInBundles) / r.bundles : 0.0;
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
