#include "dftb/fermi.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/errors.hpp"

namespace mesochain::dftb {

namespace {
double softplus(double x) { return std::max(x, 0.0) + std::log1p(std::exp(-std::abs(x))); }

// Levels of all k-points sorted once, with their k weights and prefix sums, so that an electron
// count touches only the levels within +-40 kT of mu: further below a level holds 2 electrons
// and further above none, to a relative 1e-17.
class SortedLevels {
 public:
  SortedLevels(const std::vector<Eigen::VectorXd>& levels, const std::vector<double>& weights) {
    for (size_t k = 0; k < levels.size(); ++k)
      for (Eigen::Index i = 0; i < levels[k].size(); ++i) items_.push_back({levels[k][i], weights[k]});
    std::sort(items_.begin(), items_.end(), [](const Item& a, const Item& b) { return a.e < b.e; });
    prefix_.resize(items_.size() + 1, 0.0);
    for (size_t i = 0; i < items_.size(); ++i) prefix_[i + 1] = prefix_[i] + items_[i].w;
  }
  double electronCount(double mu, double kT) const {
    auto below = std::lower_bound(items_.begin(), items_.end(), mu - 40.0 * kT,
                                  [](const Item& a, double e) { return a.e < e; });
    double n = 2.0 * prefix_[static_cast<size_t>(below - items_.begin())];
    for (auto it = below; it != items_.end() && it->e <= mu + 40.0 * kT; ++it)
      n += it->w * fermiOccupation((it->e - mu) / kT);
    return n;
  }

 private:
  struct Item {
    double e, w;
  };
  std::vector<Item> items_;
  std::vector<double> prefix_;
};
}  // namespace

double fermiOccupation(double x) {
  if (x > 0) {
    const double e = std::exp(-x);
    return 2.0 * e / (1.0 + e);
  }
  return 2.0 / (1.0 + std::exp(x));
}

double fermiEntropy(double x) {
  // Per spin orbital: -[f ln f + (1-f) ln(1-f)] = ln(1 + e^x) - (1 - f) x, f = 1/(1+e^x).
  const double f = 0.5 * fermiOccupation(x);
  return softplus(x) - (1.0 - f) * x;
}

Filling fillFermiDirac(const std::vector<Eigen::VectorXd>& levels,
                       const std::vector<double>& weights, double electrons, double kT) {
  if (!(kT > 0.0) || !std::isfinite(kT))
    throw NumericalError("Fermi filling needs a positive electronic temperature");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  size_t capacity = 0;
  for (const auto& e : levels) {
    if (e.size() == 0) continue;
    lo = std::min(lo, e.minCoeff());
    hi = std::max(hi, e.maxCoeff());
    capacity = std::max<size_t>(capacity, static_cast<size_t>(e.size()));
  }
  if (electrons < 0.0 || electrons > 2.0 * static_cast<double>(capacity) + 1e-9)
    throw NumericalError("cannot place " + std::to_string(electrons) + " electrons in " +
                         std::to_string(capacity) + " levels per k-point");
  const SortedLevels sorted(levels, weights);
  const double margin = 60.0 * kT + 1.0;
  // Lower end: the smallest mu with N(mu) >= N_el; upper end: the largest with N(mu) <= N_el.
  // Where N is strictly increasing both are the root; where it is flat to double precision (a
  // gap at low temperature) the Fermi level is the middle of the flat interval. Bisection runs
  // to full double precision (until the midpoint equals an end).
  auto bisect = [&](bool lower) {
    double a = lo - margin, b = hi + margin;  // N(a) ~ 0, N(b) ~ 2 n
    for (int it = 0; it < 2200; ++it) {
      const double m = 0.5 * (a + b);
      if (m <= a || m >= b) break;
      const double n = sorted.electronCount(m, kT);
      if (lower ? (n >= electrons) : (n > electrons)) b = m; else a = m;
    }
    return 0.5 * (a + b);
  };
  const double muLow = bisect(true);
  const double muHigh = bisect(false);
  Filling out;
  out.fermiLevel = 0.5 * (muLow + std::max(muLow, muHigh));
  if (muHigh > muLow) {
    // N(mu) = N_el over a whole interval: a gap. Put the Fermi level in the middle between the
    // highest level below and the lowest level above it (DFTB+ does the same).
    double below = -std::numeric_limits<double>::infinity();
    double above = std::numeric_limits<double>::infinity();
    for (const auto& e : levels)
      for (Eigen::Index i = 0; i < e.size(); ++i) {
        if (e[i] <= out.fermiLevel) below = std::max(below, e[i]);
        else above = std::min(above, e[i]);
      }
    if (std::isfinite(below) && std::isfinite(above)) {
      const double mid = 0.5 * (below + above);
      if (sorted.electronCount(mid, kT) == electrons) out.fermiLevel = mid;
    }
  }
  out.highestOccupied = -std::numeric_limits<double>::infinity();
  out.lowestUnoccupied = std::numeric_limits<double>::infinity();
  out.occupations.resize(levels.size());
  for (size_t k = 0; k < levels.size(); ++k) {
    const Eigen::VectorXd& e = levels[k];
    Eigen::VectorXd& f = out.occupations[k];
    f.resize(e.size());
    double ts = 0.0, eb = 0.0;
    for (Eigen::Index i = 0; i < e.size(); ++i) {
      const double x = (e[i] - out.fermiLevel) / kT;
      f[i] = fermiOccupation(x);
      eb += f[i] * e[i];
      ts += 2.0 * fermiEntropy(x);
      if (e[i] <= out.fermiLevel) out.highestOccupied = std::max(out.highestOccupied, e[i]);
      else out.lowestUnoccupied = std::min(out.lowestUnoccupied, e[i]);
    }
    out.bandEnergy += weights[k] * eb;
    out.entropyTerm += weights[k] * kT * ts;
  }
  return out;
}

}  // namespace mesochain::dftb
