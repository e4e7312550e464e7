#include "mdem/contacts/quadrature.hpp"

#include <cmath>

#include "mdem/units.hpp"

namespace mesochain::mdem {

QuadratureRule gaussLegendre(int n) {
  QuadratureRule r;
  r.x.resize(n), r.w.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(units::kPi * (i + 0.75) / (n + 0.5));  // Tricomi's initial guess
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1, p1 = p2;
      }
      if (n == 1) p1 = x, p0 = 1.0;
      dp = n * (x * p1 - p0) / (x * x - 1.0);  // P_n'
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    r.x[i] = -x, r.x[n - 1 - i] = x;
    r.w[i] = r.w[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return r;
}

}  // namespace mesochain::mdem
