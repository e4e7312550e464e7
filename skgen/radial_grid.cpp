#include "skgen/radial_grid.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mesochain::skgen {

LogGrid LogGrid::make(double rMin, double rMax, double h) {
  if (!(rMin > 0.0) || !(rMax > rMin) || !(h > 0.0)) {
    throw std::invalid_argument("LogGrid: need 0 < r_min < r_max and h > 0 (got r_min = " +
                                std::to_string(rMin) + ", r_max = " + std::to_string(rMax) +
                                ", h = " + std::to_string(h) + ")");
  }
  LogGrid g;
  g.x0 = std::log(rMin);
  g.h = h;
  const int n = static_cast<int>(std::ceil((std::log(rMax) - g.x0) / h)) + 1;
  if (n < 8) throw std::invalid_argument("LogGrid: fewer than 8 points");
  g.r.resize(n);
  for (int i = 0; i < n; ++i) g.r[i] = std::exp(g.x0 + i * h);
  return g;
}

double LogGrid::integrateDx(const std::vector<double>& f) const {
  const int n = size();
  double s = 0.5 * (f[0] + f[n - 1]);
  for (int i = 1; i < n - 1; ++i) s += f[i];
  return s * h;
}

std::vector<double> LogGrid::cumulativeDx(const std::vector<double>& f) const {
  const int n = size();
  std::vector<double> F(n, 0.0);
  for (int i = 0; i + 1 < n; ++i) {
    double seg;
    if (i >= 1 && i + 2 < n) {
      // ∫_{x_i}^{x_{i+1}} of the cubic through x_{i-1..i+2}.
      seg = h * (-f[i - 1] + 13.0 * f[i] + 13.0 * f[i + 1] - f[i + 2]) / 24.0;
    } else if (i == 0) {
      // cubic through x_0..x_3
      seg = h * (9.0 * f[0] + 19.0 * f[1] - 5.0 * f[2] + f[3]) / 24.0;
    } else {
      // last interval: cubic through x_{n-4..n-1}
      seg = h * (f[i - 2] - 5.0 * f[i - 1] + 19.0 * f[i] + 9.0 * f[i + 1]) / 24.0;
    }
    F[i + 1] = F[i] + seg;
  }
  return F;
}

std::vector<double> LogGrid::derivativeDx(const std::vector<double>& f) const {
  const int n = size();
  std::vector<double> d(n);
  for (int i = 0; i < n; ++i) {
    if (i >= 3 && i + 3 < n) {
      d[i] = (-f[i - 3] + 9.0 * f[i - 2] - 45.0 * f[i - 1] + 45.0 * f[i + 1] - 9.0 * f[i + 2] +
              f[i + 3]) / (60.0 * h);
    } else if (i >= 1 && i + 1 < n) {
      d[i] = (f[i + 1] - f[i - 1]) / (2.0 * h);
    } else if (i == 0) {
      d[i] = (-3.0 * f[0] + 4.0 * f[1] - f[2]) / (2.0 * h);
    } else {
      d[i] = (3.0 * f[i] - 4.0 * f[i - 1] + f[i - 2]) / (2.0 * h);
    }
  }
  return d;
}

namespace {
// 4-point Lagrange weights (and their derivatives) at offset t in [0,1) from node j = 1 of the
// stencil {-1, 0, 1, 2}.
void lagrange4(double t, double w[4], double dw[4]) {
  const double a = t + 1.0, b = t, c = t - 1.0, d = t - 2.0;
  w[0] = -b * c * d / 6.0;
  w[1] = a * c * d / 2.0;
  w[2] = -a * b * d / 2.0;
  w[3] = a * b * c / 6.0;
  dw[0] = -(c * d + b * d + b * c) / 6.0;
  dw[1] = (c * d + a * d + a * c) / 2.0;
  dw[2] = -(b * d + a * d + a * b) / 2.0;
  dw[3] = (b * c + a * c + a * b) / 6.0;
}
}  // namespace

void LogGrid::interpolateWithDerivative(const std::vector<double>& f, double radius,
                                        double& value, double& dvalue_dr) const {
  const int n = size();
  if (radius <= r[0]) {
    value = f[0];
    dvalue_dr = 0.0;
    return;
  }
  if (radius >= r[n - 1]) {
    value = 0.0;
    dvalue_dr = 0.0;
    return;
  }
  const double s = (std::log(radius) - x0) / h;
  int j = static_cast<int>(s);
  if (j < 1) j = 1;
  if (j > n - 3) j = n - 3;
  const double t = s - j;
  double w[4], dw[4];
  lagrange4(t, w, dw);
  value = 0.0;
  double dx = 0.0;
  for (int k = 0; k < 4; ++k) {
    value += w[k] * f[j - 1 + k];
    dx += dw[k] * f[j - 1 + k];
  }
  dvalue_dr = dx / (h * radius);
}

double LogGrid::interpolate(const std::vector<double>& f, double radius) const {
  double v, dv;
  interpolateWithDerivative(f, radius, v, dv);
  return v;
}

}  // namespace mesochain::skgen
