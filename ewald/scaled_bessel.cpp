#include "ewald/scaled_bessel.hpp"

#include <algorithm>
#include <cmath>

namespace mesochain::ewald {

void scaledBesselISequence(double x, int lmax, std::vector<double>& out) {
  out.assign(static_cast<size_t>(lmax) + 1, 0.0);
  if (x == 0.0) {
    out[0] = 1.0;
    return;
  }
  // Start far enough above both lmax and the width of the order distribution: for large x,
  // Ie_l ~ exp(-l^2 / 2x) / sqrt(2 pi x), so orders beyond sqrt(90 x) are below 1e-19 of Ie_0.
  const int start = std::max(lmax, static_cast<int>(std::ceil(std::sqrt(90.0 * x)))) + 25 +
                    static_cast<int>(std::min(x, 40.0));
  double above = 0.0;    // a_{l+1}
  double current = 1e-280;  // a_l, l = start
  double sum = 0.0;      // a_0 + 2 sum_{l>=1} a_l over the orders passed so far
  const double twoOverX = 2.0 / x;
  for (int l = start; l >= 1; --l) {
    if (l <= lmax) out[l] = current;
    sum += 2.0 * current;
    const double below = above + twoOverX * l * current;
    above = current;
    current = below;
    if (current > 1e250) {  // rescale everything kept so far
      constexpr double s = 1e-250;
      above *= s;
      current *= s;
      sum *= s;
      for (int m = l; m <= lmax; ++m) out[m] *= s;
    }
  }
  out[0] = current;
  sum += current;
  const double inv = 1.0 / sum;
  for (double& v : out) v *= inv;
}

}  // namespace mesochain::ewald
