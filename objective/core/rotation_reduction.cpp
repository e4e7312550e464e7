#include "objective/core/rotation_reduction.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

using units::kPi;

namespace {

long reductionModulo(long a, long n) { return ((a % n) + n) % n; }

struct RotatedImage {
  int atom = -1;
  GroupElement g;  // position(x) = g * position(atom) within the tolerance
};

// The cell atom of element `species` and the element g of the cell's group with g * atom = x,
// within tol; nothing when there is none. zeta is fixed by z (the screw translation), c by the
// azimuth after the screw's twist; the distance check decides.
std::optional<RotatedImage> findRotatedImage(const ObjectiveCell& cell, const Eigen::Vector3d& x, int species,
                               double tol) {
  const Symmetry& s = cell.symmetry;
  const double phiX = std::atan2(x.y(), x.x());
  for (int b = 0; b < cell.atomCount(); ++b) {
    if (cell.species[b] != species) continue;
    const Eigen::Vector3d p = cell.positions.col(b);
    GroupElement g;
    if (!s.isRing()) g.zeta = std::lround((x.z() - p.z()) / s.translation());
    const double phiB = std::atan2(p.y(), p.x()) + static_cast<double>(g.zeta) * s.twist();
    const long c = std::lround((phiX - phiB) * s.rotationOrder() / (2.0 * kPi));
    g.c = static_cast<int>(reductionModulo(c, s.rotationOrder()));
    if ((s.apply(g, p) - x).norm() <= tol) return RotatedImage{b, g};
  }
  return std::nullopt;
}

// The orbits of the rotation R by 2 pi / (N_a m), or nothing when R is not a symmetry or an
// orbit has fewer than m distinct atoms (an atom fixed by a non-identity element).
std::optional<RotationReduction> rotationOrbits(const ObjectiveCell& cell, int m, double tol) {
  const int n = cell.atomCount();
  const int na = cell.symmetry.rotationOrder();
  const double step = 2.0 * kPi / (static_cast<double>(na) * m);
  // R is a symmetry of the structure iff it maps every cell atom onto the structure (R commutes
  // with every element of G).
  const Eigen::Matrix3d r = rotationZ(step);
  for (int a = 0; a < n; ++a)
    if (!findRotatedImage(cell, r * cell.positions.col(a), cell.species[a], tol)) return std::nullopt;
  RotationReduction out;
  out.extraOrder = m;
  out.orbit.assign(n, -1);
  out.element.assign(n, GroupElement{});
  const long naPrime = static_cast<long>(na) * m;
  for (int a = 0; a < n; ++a) {
    if (out.orbit[a] >= 0) continue;
    const int orbit = static_cast<int>(out.representatives.size());
    out.representatives.push_back(a);
    for (int j = 0; j < m; ++j) {
      const auto image = findRotatedImage(cell, rotationZ(j * step) * cell.positions.col(a), cell.species[a], tol);
      if (!image || out.orbit[image->atom] >= 0) return std::nullopt;
      // R^j a = g b with g = S^zeta C_{N_a}^c = S^zeta C'^{c m}, so b = S^-zeta C'^{j - c m} a.
      out.orbit[image->atom] = orbit;
      out.element[image->atom] =
          GroupElement{-image->g.zeta, static_cast<int>(reductionModulo(j - static_cast<long>(image->g.c) * m, naPrime))};
    }
  }
  return out;
}

}  // namespace

RotationReduction findExtraRotation(const ObjectiveCell& cell, double toleranceBohr) {
  if (!std::isfinite(toleranceBohr) || !(toleranceBohr > 0.0) || toleranceBohr > kMaximumReductionToleranceBohr)
    throw InputError("<command line>", "option --tolerance-bohr", std::to_string(toleranceBohr),
                     "a tolerance > 0 and at most " + std::to_string(kMaximumReductionToleranceBohr) + " Bohr");
  const int n = cell.atomCount();
  for (int m = n; m >= 2; --m) {
    if (n % m != 0) continue;
    if (auto r = rotationOrbits(cell, m, toleranceBohr)) return *r;
  }
  RotationReduction none;
  for (int a = 0; a < n; ++a) none.representatives.push_back(a);
  none.orbit = none.representatives;
  none.element.assign(n, GroupElement{});
  return none;
}

ObjectiveCell reducedCell(const ObjectiveCell& cell, const RotationReduction& reduction) {
  const Symmetry& s = cell.symmetry;
  const int order = s.rotationOrder() * reduction.extraOrder;
  ObjectiveCell out;
  out.symmetry = s.isRing() ? Symmetry::ring(order) : Symmetry::screw(s.translation(), s.twist(), order);
  out.speciesNames = cell.speciesNames;
  out.positions.resize(3, static_cast<Eigen::Index>(reduction.representatives.size()));
  for (size_t i = 0; i < reduction.representatives.size(); ++i) {
    const int a = reduction.representatives[i];
    out.species.push_back(cell.species[a]);
    out.positions.col(static_cast<Eigen::Index>(i)) = cell.positions.col(a);
  }
  return out;
}

Eigen::Matrix3Xd mapToOriginalAtoms(const ObjectiveCell& reduced, const RotationReduction& reduction,
                                    const Eigen::Matrix3Xd& reducedForces) {
  const auto n = static_cast<Eigen::Index>(reduction.orbit.size());
  Eigen::Matrix3Xd out(3, n);
  for (Eigen::Index a = 0; a < n; ++a)
    out.col(a) = reduced.symmetry.rotation(reduction.element[a]) * reducedForces.col(reduction.orbit[a]);
  return out;
}

}  // namespace mesochain::objective
