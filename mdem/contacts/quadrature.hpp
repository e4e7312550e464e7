#pragma once
// Gauss-Legendre rules on [-1, 1] (nodes by Newton iteration on the Legendre recurrence).
#include <vector>

namespace mesochain::mdem {

struct QuadratureRule {
  std::vector<double> x, w;
};

QuadratureRule gaussLegendre(int n);

}  // namespace mesochain::mdem
