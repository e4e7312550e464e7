#pragma once
// Logarithmic radial grid r_i = exp(x0 + i h), i = 0..n-1, uniform in x = ln r.
//
// On a uniform x grid, integrals of functions that decay at both ends (r -> 0 as a power of r,
// r -> infinity exponentially) converge faster than any power of h with the trapezoid rule
// (Euler-Maclaurin), so `integrate` is the reference quadrature; cumulative integrals and
// derivatives use 4th / 6th order finite differences in x.
#include <vector>

namespace mesochain::skgen {

struct LogGrid {
  double x0 = 0.0;
  double h = 0.0;
  std::vector<double> r;

  // rMin, rMax in Bohr; h the step in ln r. Throws std::invalid_argument for bad values.
  static LogGrid make(double rMin, double rMax, double h);

  int size() const { return static_cast<int>(r.size()); }
  double rMax() const { return r.back(); }

  // Integral over x of f (trapezoid rule): ∫ f dx. Callers fold in the r-powers, e.g.
  // ∫ g(r) dr = integrateDx(g * r), ∫ g d^3r = 4π integrateDx(g * r^3).
  double integrateDx(const std::vector<double>& f) const;
  // F_i = ∫_{x_0}^{x_i} f dx, 4th-order (cubic through four points per interval).
  std::vector<double> cumulativeDx(const std::vector<double>& f) const;
  // df/dx, 6th-order central differences (lower order at the two ends).
  std::vector<double> derivativeDx(const std::vector<double>& f) const;
  // Value at radius r by 4-point Lagrange interpolation in x; `f` must live on this grid.
  // Below r[0] the first value is returned, beyond r.back() zero.
  double interpolate(const std::vector<double>& f, double radius) const;
  // Value and derivative d/dr at radius r (same rules).
  void interpolateWithDerivative(const std::vector<double>& f, double radius, double& value,
                                 double& dvalue_dr) const;
};

}  // namespace mesochain::skgen
