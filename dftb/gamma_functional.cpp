#include "dftb/gamma_functional.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "dftb/image_pair_sum.hpp"

namespace mesochain::dftb {

namespace {
// exp(-ta r) [A - B/r] with A = tb^4 ta / (2 (ta^2 - tb^2)^2), B = (tb^6 - 3 tb^4 ta^2) /
// (ta^2 - tb^2)^3 (Elstner et al. 1998, appendix), and its r derivative.
void unequalPart(double r, double ta, double tb, double& v, double& dv) {
  const double d = ta * ta - tb * tb;
  const double tb4 = std::pow(tb, 4);
  const double a = tb4 * ta / (2 * d * d);
  const double b = (tb4 * tb * tb - 3 * tb4 * ta * ta) / (d * d * d);
  const double e = std::exp(-ta * r);
  v = e * (a - b / r);
  dv = e * (-ta * (a - b / r) + b / (r * r));
}
}  // namespace

void gammaShortRange(double r, double ua, double ub, double& value, double& derivative) {
  const double ta = 3.2 * ua, tb = 3.2 * ub;
  if (std::abs(ta - tb) < 1e-3 * std::max(ta, tb)) {
    const double t = 0.5 * (ta + tb);
    const double e = std::exp(-t * r);
    const double poly = 1.0 / r + 11.0 * t / 16 + 3.0 * t * t * r / 16 + t * t * t * r * r / 48;
    const double dpoly = -1.0 / (r * r) + 3.0 * t * t / 16 + t * t * t * r / 24;
    value = e * poly;
    derivative = e * (dpoly - t * poly);
    return;
  }
  double v1, d1, v2, d2;
  unequalPart(r, ta, tb, v1, d1);
  unequalPart(r, tb, ta, v2, d2);
  value = v1 + v2;
  derivative = d1 + d2;
}

double gammaValue(double r, double ua, double ub) {
  double s, ds;
  gammaShortRange(r, ua, ub, s, ds);
  return 1.0 / r - s;
}

double shortRangeCutoff(double uMin, double tolerance) {
  if (!(uMin > 0) || !(tolerance > 0))
    throw InputError("the calculator settings", "scc.ewald_tolerance with the tables' Hubbard U",
                     "U = " + std::to_string(uMin) + ", tolerance = " + std::to_string(tolerance),
                     "positive values");
  // S is bounded by exp(-tau r) times a polynomial that is largest for equal tau at the
  // smaller U; walk out until r^2 |S| < tolerance (r^2: the number of images in a shell grows
  // at most like r^2 for a cell of any shape, which bounds the neglected tail).
  double r = 1.0;
  for (;; r += 0.25) {
    double s, ds;
    gammaShortRange(r, uMin, uMin, s, ds);
    if (r * r * std::abs(s) < tolerance) return r;
  }
}

ShortRangeGammaSum::ShortRangeGammaSum(std::vector<double> hubbard, double tolerance)
    : hubbard_(std::move(hubbard)) {
  double uMin = std::numeric_limits<double>::infinity();
  for (double u : hubbard_) uMin = std::min(uMin, u);
  cutoff_ = shortRangeCutoff(uMin, tolerance);
}

Eigen::MatrixXd ShortRangeGammaSum::matrix(const objective::ObjectiveCell& cell) const {
  const objective::ImageList images(cell, cutoff_);
  return imagePairMatrix(cell, images, [&](int i, int j, double r, double& v, double& dv) {
    gammaShortRange(r, hubbard_[cell.species[i]], hubbard_[cell.species[j]], v, dv);
  });
}

LatticeSumDerivatives ShortRangeGammaSum::derivatives(const objective::ObjectiveCell& cell,
                                                      const Eigen::MatrixXd& weights) const {
  const objective::ImageList images(cell, cutoff_);
  return imagePairDerivatives(cell, images, weights,
                              [&](int i, int j, double r, double& v, double& dv) {
                                gammaShortRange(r, hubbard_[cell.species[i]],
                                                hubbard_[cell.species[j]], v, dv);
                              });
}

}  // namespace mesochain::dftb
