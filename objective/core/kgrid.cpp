#include "objective/core/kgrid.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

using units::kPi;

namespace {
// Angles that are multiples of pi give real phases.
bool isMultipleOfPi(double a) {
  const double m = a / kPi;
  return std::abs(m - std::round(m)) < 1e-12;
}

// The mu values used and their weights (summing to 1/1 over the set).
std::vector<int> angularSet(int na, const AngularSampling& a) {
  std::vector<int> mus;
  if (a.samples <= 0 || a.samples >= na) {
    for (int mu = 0; mu < na; ++mu) mus.push_back(mu);
  } else {
    // Midpoint sampling of the angular zone: mu_m = floor((m + 1/2) N_a / M).
    for (int m = 0; m < a.samples; ++m)
      mus.push_back(static_cast<int>(std::floor((m + 0.5) * na / a.samples)));
  }
  return mus;
}
}  // namespace

HelicalKGrid::HelicalKGrid(const Symmetry& symmetry, int nKappa, AngularSampling angular)
    : rotationOrder_(symmetry.rotationOrder()) {
  if (nKappa < 1)
    throw InputError("<kpoints>", "kpoints.helical", std::to_string(nKappa),
                     "a number of helical k-points >= 1");
  if (angular.samples < 0)
    throw InputError("<kpoints>", "kpoints.angular", std::to_string(angular.samples),
                     "\"all\" or a positive number of sampled mu");
  const int na = rotationOrder_;
  if (symmetry.isRing()) {
    // mu and N_a - mu are time-reversal partners: keep 0 <= mu <= N_a/2.
    nKappa_ = 1;
    std::vector<std::pair<int, double>> kept;
    if (angular.samples <= 0 || angular.samples >= na / 2 + 1) {
      for (int mu = 0; 2 * mu <= na; ++mu)
        kept.emplace_back(mu, (mu == 0 || 2 * mu == na) ? 1.0 / na : 2.0 / na);
      nMu_ = na;
    } else {
      // Midpoint samples of the half zone [0, N_a/2]; each stands for an equal share of it.
      const int m = angular.samples;
      for (int s = 0; s < m; ++s)
        kept.emplace_back(static_cast<int>(std::lround((s + 0.5) * 0.5 * na / m)), 1.0 / m);
      nMu_ = m;
      sampled_ = true;
    }
    int index = 0;
    for (auto [mu, w] : kept)
      points_.push_back(HelicalKPoint{0.0, mu, w, isMultipleOfPi(2.0 * kPi * mu / na), index++});
    return;
  }
  nKappa_ = nKappa;
  const std::vector<int> mus = angularSet(na, angular);
  nMu_ = static_cast<int>(mus.size());
  sampled_ = nMu_ < na;
  const double muWeight = 1.0 / nMu_;
  // Midpoint grid kappa_m = -pi + (m + 1/2) 2 pi / N; keep kappa >= 0.
  for (int m = 0; m < nKappa; ++m) {
    const double kappa = -kPi + (m + 0.5) * 2.0 * kPi / nKappa;
    if (kappa < -1e-14) continue;
    const bool zero = std::abs(kappa) < 1e-14;
    const double w = (zero ? 1.0 : 2.0) / nKappa * muWeight;
    for (int index = 0; index < nMu_; ++index) {
      const int mu = mus[index];
      const bool real = isMultipleOfPi(kappa) && isMultipleOfPi(2.0 * kPi * mu / na);
      points_.push_back(HelicalKPoint{zero ? 0.0 : kappa, mu, w, real, index});
    }
  }
}

double HelicalKGrid::phase(const HelicalKPoint& k, const GroupElement& g) const {
  return k.kappa * static_cast<double>(g.zeta) + 2.0 * kPi * k.mu * g.c / rotationOrder_;
}

}  // namespace mesochain::objective
