#include "dftb/mulliken.hpp"

namespace mesochain::dftb {

Eigen::VectorXd mullikenPopulations(const OrbitalLayout& layout,
                                    const objective::ImageList& images,
                                    const Eigen::VectorXd& onsiteDensity,
                                    const std::vector<OrbitalBlock>& p,
                                    const std::vector<OrbitalBlock>& s) {
  const int n = static_cast<int>(layout.offset.size());
  Eigen::VectorXd q(n);
  for (int a = 0; a < n; ++a) q[a] = onsiteDensity.segment(layout.offset[a], layout.count[a]).sum();
  const auto& pairs = images.pairs();
  for (size_t k = 0; k < pairs.size(); ++k) q[pairs[k].i] += p[k].cwiseProduct(s[k]).sum();
  return q;
}

}  // namespace mesochain::dftb
