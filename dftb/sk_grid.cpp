#include "dftb/sk_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "common/errors.hpp"

namespace mesochain::dftb {

namespace {

constexpr int kN = SkGrid::kPoints;

// Lagrange weights for nodes 0..kN-1 at the local coordinate t: w[j] = L_j(t), dw[j] = L_j'(t)
// and (if d2w) d2w[j] = L_j''(t), with L_j(t) = prod_{m != j} (t - m) / (j - m).
// Products of the differences are formed directly (no division by t - m), so the weights are
// exact at the nodes and smooth everywhere.
void lagrangeWeights(double t, std::array<double, kN>& w, std::array<double, kN>& dw,
                     std::array<double, kN>* d2w) {
  std::array<double, kN> a{};
  for (int m = 0; m < kN; ++m) a[m] = t - m;
  for (int j = 0; j < kN; ++j) {
    double denom = 1.0;
    for (int m = 0; m < kN; ++m) {
      if (m != j) denom *= static_cast<double>(j - m);
    }
    double value = 1.0;
    for (int m = 0; m < kN; ++m) {
      if (m != j) value *= a[m];
    }
    double first = 0.0;
    double second = 0.0;
    for (int m = 0; m < kN; ++m) {
      if (m == j) continue;
      double pm = 1.0;  // prod over n != j, m
      for (int n = 0; n < kN; ++n) {
        if (n != j && n != m) pm *= a[n];
      }
      first += pm;
      if (d2w) {
        for (int n = 0; n < kN; ++n) {
          if (n == j || n == m) continue;
          double pmn = 1.0;
          for (int k = 0; k < kN; ++k) {
            if (k != j && k != m && k != n) pmn *= a[k];
          }
          second += pmn;
        }
      }
    }
    w[j] = value / denom;
    dw[j] = first / denom;
    if (d2w) (*d2w)[j] = second / denom;
  }
}

}  // namespace

SkGrid::SkGrid(double spacing, Eigen::MatrixXd table, const std::string& source)
    : h_(spacing), table_(std::move(table)) {
  if (!(h_ > 0.0)) {
    throw InputError(source, "", "grid spacing " + std::to_string(h_), "a positive grid spacing");
  }
  if (table_.rows() < kPoints + 1) {
    throw InputError(source, "", std::to_string(table_.rows()) + " integral rows",
                     "at least " + std::to_string(kPoints + 1) + " rows for the " +
                         std::to_string(kPoints) + "-point interpolation");
  }
  if (!table_.allFinite()) {
    throw InputError(source, "", "a non-finite integral", "finite integrals");
  }
  const int n = rows();
  lastR_ = n * h_;
  cutoff_ = lastR_ + kTailLength;
  // Value, first and second derivative at r_N of the polynomial through the last 8 rows
  // (local coordinate t = r/h - (N - 7), so r_N is t = 7).
  std::array<double, kN> w{}, dw{}, d2w{};
  lagrangeWeights(static_cast<double>(kN - 1), w, dw, &d2w);
  tail_.resize(3, table_.cols());
  const double len = kTailLength;
  for (int c = 0; c < columns(); ++c) {
    double y = 0.0, y1 = 0.0, y2 = 0.0;
    for (int j = 0; j < kN; ++j) {
      const double v = table_(n - kN + j, c);
      y += w[j] * v;
      y1 += dw[j] * v / h_;
      y2 += d2w[j] * v / (h_ * h_);
    }
    const double a = y, b = -len * y1, cc = len * len * y2;
    tail_(0, c) = 10.0 * a - 4.0 * b + 0.5 * cc;
    tail_(1, c) = -15.0 * a + 7.0 * b - cc;
    tail_(2, c) = 6.0 * a - 3.0 * b + 0.5 * cc;
  }
}

void SkGrid::evaluate(double r, double* value, double* derivative) const {
  const int nc = columns();
  if (!(r < cutoff_)) {
    std::fill(value, value + nc, 0.0);
    std::fill(derivative, derivative + nc, 0.0);
    return;
  }
  const int n = rows();
  if (r >= lastR_) {
    // Quintic tail in s = (cutoff - r) / L; d/dr = -(1/L) d/ds.
    const double s = (cutoff_ - r) / kTailLength;
    for (int c = 0; c < nc; ++c) {
      const double d = tail_(0, c), e = tail_(1, c), f = tail_(2, c);
      value[c] = s * s * s * (d + s * (e + s * f));
      derivative[c] = -(s * s * (3.0 * d + s * (4.0 * e + s * 5.0 * f))) / kTailLength;
    }
    return;
  }
  // floor(r/h) is the 1-based row at or below r; the stencil has 4 rows up to it and 4 above.
  const double x = r / h_;
  const int below = static_cast<int>(std::floor(x));
  const int last = std::max(std::min(n, below + kPointsRight), kPoints);  // 1-based last row
  const int first = last - kPoints + 1;                                    // 1-based
  std::array<double, kN> w{}, dw{};
  lagrangeWeights(x - first, w, dw, nullptr);
  for (int c = 0; c < nc; ++c) {
    double v = 0.0, dv = 0.0;
    for (int j = 0; j < kN; ++j) {
      const double y = table_(first - 1 + j, c);
      v += w[j] * y;
      dv += dw[j] * y;
    }
    value[c] = v;
    derivative[c] = dv / h_;
  }
}

}  // namespace mesochain::dftb
