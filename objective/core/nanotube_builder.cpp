#include "objective/core/nanotube_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

using units::kPi;

namespace {

// Extended Euclid: returns g = gcd(a, b) >= 0 and x, y with a x + b y = g.
long extendedGcd(long a, long b, long& x, long& y) {
  if (b == 0) {
    x = (a >= 0) ? 1 : -1;
    y = 0;
    return std::abs(a);
  }
  long x1 = 0, y1 = 0;
  const long g = extendedGcd(b, a % b, x1, y1);
  x = y1;
  y = x1 - (a / b) * y1;
  return g;
}

double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace

NanotubeRollUp::NanotubeRollUp(int n, int m, double bondLength) : n_(n), m_(m), bond_(bondLength) {
  if (n < 1 || m < 0)
    throw InputError(kBuilderSource, "nanotube indices", fmt::format("({}, {})", n, m),
                     "integers n >= 1 and m >= 0 (m > n gives the mirror image of (m, n))");
  if (!std::isfinite(bondLength) || !(bondLength > 0.0))
    throw InputError(kBuilderSource, "bond_length", fmt::format("{}", bondLength),
                     "a positive, finite bond length");
  gcd_ = std::gcd(n, m);
  lengthSquared_ = static_cast<long>(n) * n + static_cast<long>(n) * m + static_cast<long>(m) * m;
  const double a = std::sqrt(3.0) * bondLength;
  a1_ = a * Eigen::Vector2d(std::sqrt(3.0) / 2.0, 0.5);
  a2_ = a * Eigen::Vector2d(std::sqrt(3.0) / 2.0, -0.5);
  ch_ = n * a1_ + m * a2_;
  // Screw vector H = p a1 + q a2 with m p - n q = N_a: from m x + n y = N_a, p = x, q = -y.
  long x = 0, y = 0;
  extendedGcd(m, n, x, y);
  const long p = x, q = -y;
  // H . C_h / a^2 = K / 2 with K = p (2n + m) + q (2m + n); gamma = 2 pi K / (2 L). Adding
  // C_h/N_a to H adds M = 2 L / N_a to K (one elementary rotation): reduce K into (-M/2, M/2].
  const long mm = 2 * lengthSquared_ / gcd_;
  long k = (p * (2L * n + m) + q * (2L * m + n)) % mm;
  if (k < 0) k += mm;
  if (2 * k > mm) k -= mm;
  reducedTwistNumerator_ = k;
}

double NanotubeRollUp::radius() const { return ch_.norm() / (2.0 * kPi); }

std::pair<long, long> NanotubeRollUp::translationalVector() const {
  const long dr = std::gcd(2L * m_ + n_, 2L * n_ + m_);
  return {(2L * m_ + n_) / dr, -(2L * n_ + m_) / dr};
}

double NanotubeRollUp::translationalPeriod() const {
  const auto [t1, t2] = translationalVector();
  return (static_cast<double>(t1) * a1_ + static_cast<double>(t2) * a2_).norm();
}

long NanotubeRollUp::translationalAtomCount() const {
  const long dr = std::gcd(2L * m_ + n_, 2L * n_ + m_);
  return 4 * lengthSquared_ / dr;
}

double NanotubeRollUp::screwTranslation() const {
  // |C_h x H| = N_a * (area of the graphene cell) for every solution H.
  const double cellArea = std::abs(cross2(a1_, a2_));
  return gcd_ * cellArea / ch_.norm();
}

double NanotubeRollUp::screwTwist() const {
  return kPi * static_cast<double>(reducedTwistNumerator_) / static_cast<double>(lengthSquared_);
}

Eigen::Vector3d NanotubeRollUp::roll(const Eigen::Vector2d& r) const {
  const double c2 = ch_.squaredNorm();
  const double phi = 2.0 * kPi * r.dot(ch_) / c2;
  const double rad = radius();
  return {rad * std::cos(phi), rad * std::sin(phi), cross2(ch_, r) / ch_.norm()};
}

Eigen::Vector2d NanotubeRollUp::unrollToSheetFrame(const Eigen::Vector3d& x) const {
  return {radius() * std::atan2(x.y(), x.x()), x.z()};
}

ObjectiveCell buildNanotubeHelical(int n, int m, double bondLength) {
  const NanotubeRollUp tube(n, m, bondLength);
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(tube.screwTranslation(), tube.screwTwist(), tube.rotationOrder());
  cell.addAtom("C", tube.roll(Eigen::Vector2d::Zero()));
  cell.addAtom("C", tube.roll((tube.a1() + tube.a2()) / 3.0));
  return cell;
}

ObjectiveCell buildNanotubeTranslational(int n, int m, double bondLength, bool useRotation) {
  return buildNanotubeSector(n, m, bondLength, useRotation ? std::gcd(n, m) : 1);
}

ObjectiveCell buildNanotubeSector(int n, int m, double bondLength, int order) {
  const NanotubeRollUp tube(n, m, bondLength);
  if (order < 1 || tube.rotationOrder() % order != 0)
    throw InputError(kBuilderSource, fmt::format("rotation order of the ({}, {}) sector", n, m), std::to_string(order),
                     fmt::format("a divisor of gcd(n, m) = {} (the rotation by 2 pi / order maps the wall onto "
                                 "itself only then)",
                                 tube.rotationOrder()));
  const auto [t1, t2] = tube.translationalVector();
  const long L = static_cast<long>(n) * n + static_cast<long>(n) * m + static_cast<long>(m) * m;
  const long dr = std::gcd(2L * m + n, 2L * n + m);
  const long na = order;
  // Checked before any atom is placed (a (10000, 9999) cell has 1.2e9 atoms).
  const long atoms = tube.translationalAtomCount() / na;
  if (atoms > kMaxBuiltAtoms)
    throw InputError(kBuilderSource, "nanotube indices",
                     fmt::format("({}, {}): a translational cell of {} atoms (about {:.3g} GB of "
                                 "positions alone)",
                                 n, m, atoms, 24e-9 * static_cast<double>(atoms)),
                     fmt::format("at most {} atoms per cell (a DFTB Hamiltonian of that many "
                                 "atoms already needs {:.3g} TB); use the helical cell",
                                 kMaxBuiltAtoms, 16e-12 * 16.0 * kMaxBuiltAtoms * kMaxBuiltAtoms));
  // Exact membership test: a sheet point has fractional coordinates (U, V) / (6 L) along
  // (C_h, T_vec); U = 3 [i (2n+m) + j (2m+n)] (+ 3 (n+m) for the second atom),
  // V = 3 (m i - n j) d_R (+ (m - n) d_R for the second atom). Keep 0 <= U N_a, V < 6 L.
  const long den = 6 * L;
  const long imin = std::min({0L, static_cast<long>(n), t1, n + t1}) - 1;
  const long imax = std::max({0L, static_cast<long>(n), t1, n + t1}) + 1;
  const long jmin = std::min({0L, static_cast<long>(m), t2, m + t2}) - 1;
  const long jmax = std::max({0L, static_cast<long>(m), t2, m + t2}) + 1;
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(tube.translationalPeriod(), 0.0, static_cast<int>(na));
  const Eigen::Vector2d basis[2] = {Eigen::Vector2d::Zero(), (tube.a1() + tube.a2()) / 3.0};
  for (long i = imin; i <= imax; ++i)
    for (long j = jmin; j <= jmax; ++j)
      for (int b = 0; b < 2; ++b) {
        const long u = 3 * (i * (2L * n + m) + j * (2L * m + n)) + (b ? 3L * (n + m) : 0L);
        const long v = 3 * (m * i - n * j) * dr + (b ? (m - n) * dr : 0L);
        if (u < 0 || u * na >= den || v < 0 || v >= den) continue;
        const Eigen::Vector2d r =
            static_cast<double>(i) * tube.a1() + static_cast<double>(j) * tube.a2() + basis[b];
        cell.addAtom("C", tube.roll(r));
      }
  if (cell.atomCount() != tube.translationalAtomCount() / na)
    throw std::logic_error(
        fmt::format("nanotube ({}, {}): {} atoms in the translational cell, "
                    "expected {}",
                    n, m, cell.atomCount(), tube.translationalAtomCount() / na));
  return cell;
}

ObjectiveCell buildMultiWallTranslational(const std::vector<std::pair<int, int>>& walls,
                                          double bondLength) {
  return buildMultiWallSector(walls, bondLength, 1);
}

ObjectiveCell buildMultiWallSector(const std::vector<std::pair<int, int>>& walls, double bondLength,
                                   int order) {
  if (order < 1)
    throw InputError(kBuilderSource, "rotation order", std::to_string(order),
                     "an integer >= 1 that divides gcd(n, m) of every wall");
  if (walls.empty())
    throw InputError(kBuilderSource, "walls", "an empty list", "at least one (n, m) wall");
  const NanotubeRollUp first(walls.front().first, walls.front().second, bondLength);
  const double period = first.translationalPeriod();
  std::vector<double> radii;
  ObjectiveCell out;
  out.symmetry = Symmetry::screw(period, 0.0, order);
  long atoms = 0;
  for (const auto& [n, m] : walls) atoms += NanotubeRollUp(n, m, bondLength).translationalAtomCount() / std::max(order, 1);
  if (atoms > kMaxBuiltAtoms)
    throw InputError(kBuilderSource, "walls", fmt::format("{} atoms in one cell", atoms),
                     fmt::format("at most {} atoms per cell (fewer or smaller walls, or a higher rotation order)",
                                 kMaxBuiltAtoms));
  for (const auto& [n, m] : walls) {
    const NanotubeRollUp tube(n, m, bondLength);
    if (std::abs(tube.translationalPeriod() - period) > 1e-9 * period)
      throw InputError(
          kBuilderSource, fmt::format("wall ({}, {})", n, m),
          fmt::format("a translational period of {:.6f} Å, incommensurate with {:.6f} Å of "
                      "wall ({}, {})",
                      tube.translationalPeriod() * units::kBohrInAngstrom,
                      period * units::kBohrInAngstrom, walls.front().first, walls.front().second),
          "walls that share one translational period (e.g. armchair inside armchair)");
    for (double r : radii)
      if (std::abs(r - tube.radius()) < units::kAngstromInBohr)
        throw InputError(kBuilderSource, fmt::format("wall ({}, {})", n, m),
                         fmt::format("a radius of {:.4f} Å, within 1 Å of another wall",
                                     tube.radius() * units::kBohrInAngstrom),
                         "distinct, concentric walls");
    radii.push_back(tube.radius());
    const ObjectiveCell wall = buildNanotubeSector(n, m, bondLength, order);
    for (int a = 0; a < wall.atomCount(); ++a) out.addAtom("C", wall.positions.col(a));
  }
  return out;
}

}  // namespace mesochain::objective
