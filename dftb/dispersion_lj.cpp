#include "dftb/dispersion_lj.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::dftb {

UffLennardJones::UffLennardJones(double epsilon, double r0, double cutoff)
    : eps_(epsilon), r0_(r0), cutoff_(cutoff), rs_(std::pow(2.0, -1.0 / 6.0) * r0) {
  const std::string src = "<Lennard-Jones dispersion>";
  requireFinite(epsilon, src, "epsilon");
  requireFinite(r0, src, "r0");
  requireFinite(cutoff, src, "cutoff");
  if (!(epsilon >= 0.0)) throw InputError(src, "epsilon", "a negative well depth", ">= 0");
  if (!(r0 > 0.0)) throw InputError(src, "r0", "r0 <= 0", "a positive distance");
  if (!(cutoff > 0.0)) throw InputError(src, "cutoff", "cutoff <= 0", "a positive distance");
  // Matching at r_s (Zhechkov et al. 2005): with A = U5 r_s^5 and B = U10 r_s^10,
  //   value:  U0 - A - B = V(r_s)
  //   first:  -5A - 10B  = r_s V'(r_s)
  //   second: -20A - 90B = r_s^2 V''(r_s)
  // and for the Lennard-Jones form with (r0/r_s)^6 = 2: V = 0, r_s V' = -24 eps,
  // r_s^2 V'' = 456 eps.
  const double v = 0.0, rv1 = -24.0 * eps_, r2v2 = 456.0 * eps_;
  const double b = (r2v2 - 4.0 * rv1) / (-50.0);  // from the two derivative conditions
  const double a = (-rv1 - 10.0 * b) / 5.0;
  u0_ = v + a + b;
  u5_ = a / std::pow(rs_, 5);
  u10_ = b / std::pow(rs_, 10);
}

UffLennardJones UffLennardJones::carbonDefaults(double cutoff) {
  return UffLennardJones(0.069 * units::kKcalPerMolInHartree, 3.80 * units::kAngstromInBohr,
                         cutoff);
}

void UffLennardJones::evaluate(double r, double& value, double& derivative) const {
  value = 0.0;
  derivative = 0.0;
  if (r >= cutoff_) return;
  if (r >= rs_) {
    const double x6 = std::pow(r0_ / r, 6);
    value = eps_ * (x6 * x6 - 2.0 * x6);
    derivative = eps_ * (-12.0 * x6 * x6 + 12.0 * x6) / r;
  } else {
    const double r4 = (r * r) * (r * r);
    const double r5 = r4 * r;
    const double r9 = r4 * r5;
    value = u0_ - u5_ * r5 - u10_ * r5 * r5;
    derivative = -5.0 * u5_ * r4 - 10.0 * u10_ * r9;
  }
}

}  // namespace mesochain::dftb
