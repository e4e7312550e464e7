#pragma once
// Collapsed (flattened) single- and multi-walled nanotubes as translational objective cells.
//
// Starting shape: an analytic "dog-bone" cross-section (the shape seen in relaxed collapsed
// tubes, e.g. Chopra et al., Nature 377, 135 (1995); Gao, Cagin & Goddard, Nanotechnology 9,
// 184 (1998)). In the x-y plane, for the innermost wall:
//   - two flat faces y = +-h (h = interlayer / 2) for |x| <= x_t,
//   - at each end a concave transition arc of radius r_t, tangent to the face at x = +-x_t,
//   - a convex bulb of radius r_b centred on the x axis at x = +-x_c, tangent to both transition
//     arcs. Tangency of the two circles gives (x_c - x_t)^2 + (h + r_t)^2 = (r_b + r_t)^2.
// With theta = atan2(-(h + r_t), x_c - x_t) (in (-pi/2, 0)), each transition arc turns by
// alpha = theta + pi/2 and each bulb by 2 (pi + theta); the perimeter is
//   P = 4 x_t + 4 r_t alpha + 4 r_b (pi + theta),
// and x_t follows from P = 2 pi R (the perimeter, and hence every bond, of the round tube is
// preserved). Wall k = 0, 1, ... (inside out) is the parallel curve at distance k * interlayer:
// faces at +-(h + k d), bulbs of radius r_b + k d, transition arcs of radius
// r_t,outer + (W - 1 - k) d, where r_t,outer is the transition radius of the outermost wall
// (a parallel curve shrinks concave arcs). x_t of each wall again follows from its perimeter.
//
// Atoms: each atom of the round tube's translational cell keeps z and moves to the point of
// the contour at the same arc length s = R phi, measured from the middle of the upper face
// (x = 0, y = +h) in the direction of increasing phi. Symmetry: gamma = 0, N_a = 1, the
// translational period of the tube. Everything in Bohr.
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "objective/core/cell.hpp"

namespace mesochain::objective {

struct CollapseShape {
  double interlayer = 0.0;         // Bohr: distance between the flat faces of the inner wall
  double bulbRadius = 0.0;         // Bohr: bulb radius of the innermost wall (> interlayer / 2)
  double transitionRadius = 0.0;   // Bohr: concave transition radius of the outermost wall (> 0)
};

// The closed dog-bone contour of one wall, parametrised by arc length.
class DogBoneContour {
 public:
  // Throws InputError (source "<builder>") when the perimeter is too short for the shape
  // (negative flat length) or a radius is not positive.
  DogBoneContour(double halfGap, double bulbRadius, double transitionRadius, double perimeter);
  double perimeter() const { return perimeter_; }
  double flatHalfLength() const { return xt_; }
  double bulbCentre() const { return xc_; }
  // The point at arc length s (any real s; periodic in the perimeter), starting at (0, +h) and
  // running towards +x along the upper face.
  Eigen::Vector2d point(double s) const;

 private:
  double h_, rb_, rt_, perimeter_;
  double xt_ = 0, xc_ = 0, theta_ = 0, alpha_ = 0;
};

// Collapses the translational cell of concentric walls (e.g. {{30,30}} or {{30,30},{35,35}},
// listed inside out, sharing one period) onto nested dog-bone contours.
ObjectiveCell buildCollapsedTube(const std::vector<std::pair<int, int>>& walls, double bondLength,
                                 const CollapseShape& shape);

// Measured dimensions of a flattened cell (from its atoms, in Bohr).
struct CollapsedDimensions {
  double faceSeparation = 0.0;  // between the outermost flat faces (atom centres)
  double thickness = 0.0;       // faceSeparation + one interlayer (van der Waals thickness)
  double width = 0.0;           // atom-centre extent along the long axis + one interlayer
  Eigen::Vector2d longAxis = Eigen::Vector2d::UnitX();  // unit vector in the x-y plane
};

// Principal axes of the x-y positions give the long (width) and short (thickness) directions.
// The faces are the atoms of the central half of the width (|u| < width/4 about the centroid):
// the upper face is the mean v of those within 0.5 Bohr of their largest v, the lower face
// likewise; faceSeparation = upper - lower. `interlayer` (Bohr) is added once to the
// separation and to the extent (half a layer on each side).
CollapsedDimensions measureCollapsed(const ObjectiveCell& cell, double interlayer);

}  // namespace mesochain::objective
