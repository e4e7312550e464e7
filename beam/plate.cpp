#include "beam/plate.hpp"

#include <stdexcept>

namespace mesochain::beam {

double plateBendingRigidity(int n, double c2, double z0, double nu, double d1) {
  if (n < 1 || !(nu > -1.0 && nu < 1.0))
    throw std::invalid_argument("plateBendingRigidity: needs N >= 1 and -1 < nu < 1");
  const double dn = n;
  return dn * d1 + c2 * z0 * z0 * dn * (dn * dn - 1.0) / (12.0 * (1.0 - nu * nu));
}

double slidingLayersRigidity(int n, double d1) { return n * d1; }

double ribbonBendingConstant(double plate, double width, double cellLength) {
  return plate * width * cellLength;
}

}  // namespace mesochain::beam
