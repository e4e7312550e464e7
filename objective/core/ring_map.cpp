#include "objective/core/ring_map.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

using units::kPi;

namespace {
const char* kBendSource = "<bend>";
}

BendFrame bendFrame(const ObjectiveCell& straight, BendDirection direction) {
  BendFrame f;
  const int n = straight.atomCount();
  if (n == 0) return f;
  const Eigen::Matrix2Xd xy = straight.positions.topRows(2);
  f.centre = xy.rowwise().mean();
  const Eigen::Matrix2Xd c = xy.colwise() - f.centre;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(c * c.transpose() / n);
  // Eigenvalues ascending: column 0 is the short axis, column 1 the long axis.
  f.radial = eig.eigenvectors().col(direction == BendDirection::Soft ? 0 : 1).normalized();
  return f;
}

ObjectiveCell straightToRing(const ObjectiveCell& straight, const BendFrame& frame,
                             int rotationOrder) {
  const Symmetry& s = straight.symmetry;
  if (s.isRing() || s.rotationOrder() != 1 || std::abs(s.twist()) > 1e-12)
    throw InputError(kBendSource, "the straight cell",
                     fmt::format("translation {:.6g} Bohr, twist {:.6g} rad, rotation order {}",
                                 s.translation(), s.twist(), s.rotationOrder()),
                     "a translational cell (translation > 0, twist 0, rotation order 1), e.g. "
                     "[builder] cell = \"translational\"");
  if (rotationOrder < 2)
    throw InputError(kBendSource, "rotation order", std::to_string(rotationOrder),
                     "a ring of at least 2 cells");
  const double radius = rotationOrder * s.translation() / (2 * kPi);
  const Eigen::Vector2d er = frame.radial.normalized();
  const Eigen::Vector2d ea(-er.y(), er.x());  // e_z x e_r
  ObjectiveCell ring;
  ring.speciesNames = straight.speciesNames;
  ring.species = straight.species;
  ring.positions.resize(3, straight.atomCount());
  for (int a = 0; a < straight.atomCount(); ++a) {
    const Eigen::Vector3d p = straight.positions.col(a);
    const Eigen::Vector2d d = p.head<2>() - frame.centre;
    const double ur = d.dot(er), ua = d.dot(ea);
    if (!(radius + ur > 1.0))
      throw InputError(kBendSource, fmt::format("rotation order {}", rotationOrder),
                       fmt::format("a ring radius of {:.4f} Bohr, at which atom {} would sit at "
                                   "{:.4f} Bohr from the ring axis",
                                   radius, a + 1, radius + ur),
                       "a larger rotation order (a radius well beyond the cross-section)");
    const double theta = p.z() / radius;
    ring.positions.col(a) << (radius + ur) * std::cos(theta), (radius + ur) * std::sin(theta),
        -ua;
  }
  ring.symmetry = Symmetry::ring(rotationOrder);
  return ring;
}

ObjectiveCell ringToStraight(const ObjectiveCell& ring, double radius) {
  const int na = ring.symmetry.rotationOrder();
  const double sector = 2 * kPi / na;
  ObjectiveCell straight;
  straight.speciesNames = ring.speciesNames;
  straight.species = ring.species;
  straight.positions.resize(3, ring.atomCount());
  for (int a = 0; a < ring.atomCount(); ++a) {
    const Eigen::Vector3d p = ring.positions.col(a);
    // Angle measured from the middle of the sector, so that atoms a little outside [0, sector)
    // keep a continuous angle.
    const double mid = sector / 2;
    const double rel = std::atan2(p.y() * std::cos(mid) - p.x() * std::sin(mid),
                                  p.x() * std::cos(mid) + p.y() * std::sin(mid));
    const double theta = mid + rel;
    straight.positions.col(a) << std::hypot(p.x(), p.y()) - radius, -p.z(), radius * theta;
  }
  straight.symmetry = Symmetry::screw(sector * radius, 0.0, 1);
  return straight;
}

ObjectiveCell rebendSector(const ObjectiveCell& sector, double radiusFrom, double radiusTo,
                           int rotationOrderTo) {
  const int nFrom = sector.symmetry.rotationOrder();
  if (rotationOrderTo < 2 || !(radiusTo > 0))
    throw InputError(kBendSource, "rotation order", std::to_string(rotationOrderTo),
                     "a ring of at least 2 sectors");
  const double mid = kPi / nFrom;  // angles from the middle of the sector stay continuous
  const double scale = static_cast<double>(nFrom) / rotationOrderTo;
  ObjectiveCell out = sector;
  for (int a = 0; a < sector.atomCount(); ++a) {
    const Eigen::Vector3d p = sector.positions.col(a);
    const double rel = std::atan2(p.y() * std::cos(mid) - p.x() * std::sin(mid),
                                  p.x() * std::cos(mid) + p.y() * std::sin(mid));
    const double theta = (mid + rel) * scale;
    const double rho = std::hypot(p.x(), p.y()) - radiusFrom + radiusTo;
    if (!(rho > 1.0))
      throw InputError(kBendSource, fmt::format("rotation order {}", rotationOrderTo),
                       fmt::format("a middle radius of {:.4f} Bohr, at which atom {} would sit "
                                   "{:.4f} Bohr from the axis",
                                   radiusTo, a + 1, rho),
                       "a larger rotation order");
    out.positions.col(a) << rho * std::cos(theta), rho * std::sin(theta), p.z();
  }
  out.symmetry = Symmetry::screw(sector.symmetry.translation(), 0.0, rotationOrderTo);
  return out;
}

double meanRingRadius(const ObjectiveCell& ring) {
  if (ring.atomCount() == 0) return 0.0;
  return ring.positions.topRows(2).colwise().norm().mean();
}

}  // namespace mesochain::objective
