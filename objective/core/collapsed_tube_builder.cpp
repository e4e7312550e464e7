#include "objective/core/collapsed_tube_builder.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"

namespace mesochain::objective {

using units::kBohrInAngstrom;
using units::kPi;

DogBoneContour::DogBoneContour(double halfGap, double bulbRadius, double transitionRadius,
                               double perimeter)
    : h_(halfGap), rb_(bulbRadius), rt_(transitionRadius), perimeter_(perimeter) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(h_) || !positive(rt_) || !positive(perimeter_))
    throw InputError(kBuilderSource, "collapsed tube",
                     fmt::format("half gap {:.4g}, transition radius {:.4g}, perimeter {:.4g} Bohr",
                                 h_, rt_, perimeter_),
                     "positive, finite lengths");
  if (!(rb_ > h_) || !std::isfinite(rb_))
    throw InputError(kBuilderSource, "bulb_radius", fmt::format("{:.4f} Å", rb_ * kBohrInAngstrom),
                     fmt::format("a bulb radius larger than half the face separation ({:.4f} Å)",
                                 h_ * kBohrInAngstrom));
  // Tangency of the transition circle (centre (x_t, h + r_t)) and the bulb (centre (x_c, 0)).
  const double dx = std::sqrt((rb_ + rt_) * (rb_ + rt_) - (h_ + rt_) * (h_ + rt_));
  theta_ = std::atan2(-(h_ + rt_), dx);
  alpha_ = theta_ + kPi / 2;
  xt_ = (perimeter_ - 4 * rt_ * alpha_ - 4 * rb_ * (kPi + theta_)) / 4;
  if (!(xt_ >= 0.0))
    throw InputError(kBuilderSource, "collapsed tube",
                     fmt::format("a wall of perimeter {:.4f} Å, too short for bulbs of radius "
                                 "{:.4f} Å and transitions of radius {:.4f} Å",
                                 perimeter_ * kBohrInAngstrom, rb_ * kBohrInAngstrom,
                                 rt_ * kBohrInAngstrom),
                     "a larger tube or smaller bulb_radius / transition_radius");
  xc_ = xt_ + dx;
}

Eigen::Vector2d DogBoneContour::point(double s) const {
  s = std::fmod(s, perimeter_);
  if (s < 0) s += perimeter_;
  // The contour is symmetric under a rotation by pi: the second half is the first rotated.
  if (s >= perimeter_ / 2) return -point(s - perimeter_ / 2);
  if (s < xt_) return {s, h_};  // upper face, right half
  s -= xt_;
  const double arcT = rt_ * alpha_;
  if (s < arcT) {  // upper-right transition, counter-clockwise about (x_t, h + r_t)
    const double a = -kPi / 2 + s / rt_;
    return {xt_ + rt_ * std::cos(a), h_ + rt_ + rt_ * std::sin(a)};
  }
  s -= arcT;
  const double arcB = 2 * rb_ * (kPi + theta_);
  if (s < arcB) {  // bulb, clockwise about (x_c, 0) from the angle theta + pi
    const double a = theta_ + kPi - s / rb_;
    return {xc_ + rb_ * std::cos(a), rb_ * std::sin(a)};
  }
  s -= arcB;
  if (s < arcT) {  // lower-right transition, counter-clockwise about (x_t, -h - r_t)
    const double a = -theta_ + s / rt_;
    return {xt_ + rt_ * std::cos(a), -h_ - rt_ + rt_ * std::sin(a)};
  }
  s -= arcT;
  return {xt_ - s, -h_};  // lower face, right half, towards x = 0
}

ObjectiveCell buildCollapsedTube(const std::vector<std::pair<int, int>>& walls, double bondLength,
                                 const CollapseShape& shape) {
  if (!(shape.interlayer > 0.0) || !std::isfinite(shape.interlayer))
    throw InputError(kBuilderSource, "interlayer", fmt::format("{}", shape.interlayer),
                     "a positive interlayer distance");
  const ObjectiveCell round = buildMultiWallTranslational(walls, bondLength);
  const int nWalls = static_cast<int>(walls.size());
  // Walls sorted by radius: the k-th from the inside gets the k-th parallel contour.
  std::vector<std::pair<double, int>> order;
  for (int w = 0; w < nWalls; ++w)
    order.emplace_back(NanotubeRollUp(walls[w].first, walls[w].second, bondLength).radius(), w);
  std::sort(order.begin(), order.end());
  const double d = shape.interlayer;
  ObjectiveCell out;
  out.symmetry = round.symmetry;
  int atom = 0;
  for (int w = 0; w < nWalls; ++w) {
    const NanotubeRollUp tube(walls[w].first, walls[w].second, bondLength);
    const long count = tube.translationalAtomCount();
    const int k = static_cast<int>(
        std::find_if(order.begin(), order.end(), [&](const auto& p) { return p.second == w; }) -
        order.begin());
    const double radius = tube.radius();
    const DogBoneContour contour(d / 2 + k * d, shape.bulbRadius + k * d,
                                 shape.transitionRadius + (nWalls - 1 - k) * d,
                                 2 * kPi * radius);
    for (long a = 0; a < count; ++a, ++atom) {
      const Eigen::Vector3d x = round.positions.col(atom);
      // Arc length against the contour's direction: keeps the handedness of chiral walls.
      const double s = -radius * std::atan2(x.y(), x.x());
      const Eigen::Vector2d p = contour.point(s);
      out.addAtom(round.speciesOf(atom), {p.x(), p.y(), x.z()});
    }
  }
  return out;
}

CollapsedDimensions measureCollapsed(const ObjectiveCell& cell, double interlayer) {
  const int n = cell.atomCount();
  if (n < 4) throw InputError("<cell>", "measureCollapsed", fmt::format("{} atoms", n),
                              "a flattened cell of at least 4 atoms");
  const Eigen::Matrix2Xd xy = cell.positions.topRows(2);
  const Eigen::Vector2d centre = xy.rowwise().mean();
  const Eigen::Matrix2Xd c = xy.colwise() - centre;
  const Eigen::Matrix2d cov = c * c.transpose() / n;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  CollapsedDimensions out;
  out.longAxis = eig.eigenvectors().col(1);  // largest eigenvalue last
  const Eigen::Vector2d shortAxis = eig.eigenvectors().col(0);
  const Eigen::VectorXd u = (out.longAxis.transpose() * c).transpose();
  const Eigen::VectorXd v = (shortAxis.transpose() * c).transpose();
  const double extent = u.maxCoeff() - u.minCoeff();
  std::vector<double> central;
  for (int a = 0; a < n; ++a)
    if (std::abs(u[a]) < extent / 4) central.push_back(v[a]);
  if (central.size() < 2)
    throw InputError("<cell>", "measureCollapsed", "no atoms in the central half of the width",
                     "a flattened cell");
  const double top = *std::max_element(central.begin(), central.end());
  const double bottom = *std::min_element(central.begin(), central.end());
  double upper = 0, lower = 0;
  int nu = 0, nl = 0;
  for (double x : central) {
    if (x > top - 0.5) upper += x, ++nu;
    if (x < bottom + 0.5) lower += x, ++nl;
  }
  out.faceSeparation = upper / nu - lower / nl;
  out.thickness = out.faceSeparation + interlayer;
  out.width = extent + interlayer;
  return out;
}

}  // namespace mesochain::objective
