#include "ewald/helical_lattice_sum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "ewald/helical_reciprocal.hpp"
#include "objective/core/images.hpp"

namespace mesochain::ewald {

using objective::GroupElement;
using objective::ObjectiveCell;
using objective::Symmetry;
using units::kPi;

namespace {

constexpr const char* kSource = "<ewald>";
constexpr double kMinTolerance = 1e-13;
constexpr double kMaxTolerance = 1e-2;
constexpr long kMaxImagesPerPair = 50000000;

double fullKernel(Kernel k, double r) {
  return k == Kernel::Coulomb ? 1 / r : 1 / (r * r * r * r * r * r);
}
// d/dr of the full kernel.
double fullKernelDerivative(Kernel k, double r) {
  return k == Kernel::Coulomb ? -1 / (r * r) : -6 / (r * r * r * r * r * r * r);
}

// Short-range split kernel, eq. (E3): erfc(alpha r)/r, or Gamma(3, a) / (2 r^6), a = alpha^2 r^2.
double shortKernel(Kernel k, double alpha, double r) {
  if (k == Kernel::Coulomb) return std::erfc(alpha * r) / r;
  const double a = alpha * alpha * r * r;
  return std::exp(-a) * (1 + a + 0.5 * a * a) / std::pow(r, 6);
}
// Both at once (one erfc / exp): value K_s(r) and derivative dK_s/dr.
void shortKernelWithDerivative(Kernel k, double alpha, double r, double& value, double& derivative) {
  if (k == Kernel::Coulomb) {
    const double e = std::erfc(alpha * r);
    value = e / r;
    derivative = -value / r - 2 * alpha / std::sqrt(kPi) * std::exp(-alpha * alpha * r * r) / r;
    return;
  }
  const double a = alpha * alpha * r * r, ex = std::exp(-a);
  const double r2 = r * r, r5 = r2 * r2 * r;
  value = ex * (1 + a + 0.5 * a * a) / (r5 * r);
  derivative = -alpha * alpha * a * a * ex / r5 - 6 * value / r;
}
// The identity image's long-range part, int_0^{alpha^2} w(t) dt, eq. (E15).
double selfLongRange(Kernel k, double alpha) {
  return k == Kernel::Coulomb ? 2 * alpha / std::sqrt(kPi) : std::pow(alpha, 6) / 6;
}

double shortestDistance(const ObjectiveCell& cell) {
  const int n = cell.atomCount();
  double cutoff = 4.0;
  for (int attempt = 0; attempt < 12; ++attempt, cutoff *= 2) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j)
        objective::forEachImageNear(cell.symmetry, cell.positions.col(i), cell.positions.col(j),
                                    cutoff, [&](const GroupElement& g, const Eigen::Vector3d& y) {
                                      if (i == j && g.isIdentity()) return;
                                      best = std::min(best, (y - cell.positions.col(i)).norm());
                                    });
    if (std::isfinite(best)) return best;
    if (cell.symmetry.isRing() && cell.symmetry.rotationOrder() == 1 && n == 1) break;
  }
  return std::numeric_limits<double>::infinity();
}

// Modelled cost of one pair (in instructions, calibrated with callgrind on carbon tubes) at
// splitting parameter alpha, docs/ewald.md section "Splitting parameter": real-space images
// (~110 each, ~80 per screw power), the closed-form small-t series (~8000 per pair, ~1500 per
// (l, k) term) and, when alpha^2 > t_c, the quadrature nodes above t_c (a Bessel sequence of
// ~l_A + 50 orders at ~15 each, ~60 per (l, k) term).
double modelledPairCost(double alpha, double tol, double T, int na, double rho) {
  const double L = std::log(1 / tol) + 3;
  const double rc = std::sqrt(L) / alpha;
  const double zetas = 2 * rc / T + 1;
  double perZeta = na;
  if (na > 8) perZeta = std::min<double>(na, na * std::min(1.0, rc / (kPi * rho)) + 3);
  const double real = zetas * (80 + 110 * perZeta);
  const double spread = 4 * rho * rho;
  const double tc = std::min(alpha * alpha, 1 / spread);
  int lB = 0;  // B_l ~ (t_c b / 2)^l / l!: orders above tol
  for (double m = 1; lB < 24 && m > tol; m *= tc * spread / 4 / ++lB) {
  }
  const double series = 8000 + 1500 * (lB / na + 1) * (2 * std::sqrt(tc * L) * T / kPi + 1);
  double quad = 0;
  if (alpha * alpha > tc) {
    const double panels = std::ceil(std::log(alpha * alpha / tc));
    const double lA = 2 * alpha * rho * std::sqrt(L);
    quad = 12 * panels * (15 * (lA + 50) + 60 * (lA / na + 1) * (2 * alpha * std::sqrt(L) * T / kPi + 1));
  }
  return real + series + quad;
}

struct Resolved {
  LatticeSumPlan plan;
  detail::ReciprocalSetup setup;
  std::vector<std::array<double, 2>> rotations;  // cos, sin of 2 pi c / N_a
};

// Real-space images g x_j within r_c of x_i, eq. (E4) (the same set as
// objective::forEachImageNear), passed as f(g, y, cos, sin of the rotation angle of g): one
// sincos per screw power zeta, composed with the table of the
// C_Na rotations; for N_a > 8 only the rotations whose in-plane angle can bring the image within
// r_c (|phi_i - phi_j - zeta gamma - 2 pi c / N_a| <= theta, cos theta = (rho_i^2 + rho_j^2 -
// r_c^2 + dz^2) / (2 rho_i rho_j)), padded by one on each side; every image is still tested.
template <class F>
void forEachRealSpaceImage(const Symmetry& sym, const std::vector<std::array<double, 2>>& rot,
                           const Eigen::Vector3d& xi, const Eigen::Vector3d& xj, double rc, F&& f) {
  const double T = sym.translation(), gamma = sym.twist();
  const int na = sym.rotationOrder();
  const double rc2 = rc * rc;
  const long zmin = static_cast<long>(std::ceil((xi.z() - xj.z() - rc) / T));
  const long zmax = static_cast<long>(std::floor((xi.z() - xj.z() + rc) / T));
  const double ri = std::hypot(xi.x(), xi.y()), rj = std::hypot(xj.x(), xj.y());
  const double phiI = std::atan2(xi.y(), xi.x()), phiJ = std::atan2(xj.y(), xj.x());
  for (long zeta = zmin; zeta <= zmax; ++zeta) {
    const double z = xj.z() + static_cast<double>(zeta) * T;
    const double dz = z - xi.z();
    const double inPlane2 = rc2 - dz * dz;
    if (inPlane2 <= (ri - rj) * (ri - rj)) continue;
    const double a0 = static_cast<double>(zeta) * gamma;
    const double cz = std::cos(a0), sz = std::sin(a0);
    const double bx = cz * xj.x() - sz * xj.y(), by = sz * xj.x() + cz * xj.y();
    long cLo = 0, cHi = na - 1;
    if (na > 8 && ri * rj > 0) {
      const double cosTheta = (ri * ri + rj * rj - inPlane2) / (2 * ri * rj);
      if (cosTheta > -1) {
        const double theta = std::acos(std::min(cosTheta, 1.0));
        const double perStep = na / (2 * kPi);
        const double center = std::remainder(phiI - phiJ - a0, 2 * kPi) * perStep;
        const long lo = static_cast<long>(std::floor(center - theta * perStep)) - 1;
        const long hi = static_cast<long>(std::ceil(center + theta * perStep)) + 1;
        if (hi - lo + 1 < na) cLo = lo, cHi = hi;
      }
    }
    for (long cc = cLo; cc <= cHi; ++cc) {
      const int c = static_cast<int>(((cc % na) + na) % na);
      const Eigen::Vector3d y(rot[c][0] * bx - rot[c][1] * by, rot[c][1] * bx + rot[c][0] * by, z);
      if ((y - xi).squaredNorm() < rc2)
        f(GroupElement{zeta, c}, y, cz * rot[c][0] - sz * rot[c][1], sz * rot[c][0] + cz * rot[c][1]);
    }
  }
}

// Splitting parameter from a cost model (real-space images vs. reciprocal terms) unless given,
// then every truncation from the tolerance (docs/ewald.md section "Truncations").
Resolved resolve(Kernel kernel, const LatticeSumSettings& st, const ObjectiveCell& cell) {
  const double tol = st.tolerance;
  if (!(tol >= kMinTolerance && tol <= kMaxTolerance))
    throw InputError(kSource, "ewald tolerance", std::to_string(tol),
                     "a relative tolerance between 1e-13 and 1e-2 (tighter cannot be met in "
                     "double precision)");
  if (st.splitting && !(std::isfinite(*st.splitting) && *st.splitting > 0))
    throw InputError(kSource, "ewald splitting", std::to_string(*st.splitting),
                     "a positive splitting parameter (1/Bohr)");
  Resolved r;
  for (int c = 0; c < cell.symmetry.rotationOrder(); ++c) {
    const double a = 2 * kPi * c / cell.symmetry.rotationOrder();
    r.rotations.push_back({std::cos(a), std::sin(a)});
  }
  LatticeSumPlan& p = r.plan;
  p.shortestDistance = shortestDistance(cell);
  const double dmin = std::isfinite(p.shortestDistance) ? p.shortestDistance : 1.0;
  // Per element tol K(d_min) / N_o: the energy sums N_o^2 elements but grows like N_o K(d_min).
  p.elementTolerance = tol * fullKernel(kernel, dmin) / std::max(1, cell.atomCount());
  const Symmetry& sym = cell.symmetry;
  if (sym.isRing()) return r;
  const double T = sym.translation();
  const int na = sym.rotationOrder();
  double rhoMax = 1.0;
  for (int i = 0; i < cell.atomCount(); ++i)
    rhoMax = std::max(rhoMax, std::hypot(cell.positions(0, i), cell.positions(1, i)));
  if (st.splitting) {
    p.splitting = *st.splitting;
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (double a = std::min(1e-3, 1 / T); a < 5.0; a *= 1.04) {
      const double c = modelledPairCost(a, tol, T, na, rhoMax);
      if (c < best) best = c, p.splitting = a;
    }
  }
  const double alpha = p.splitting;
  // Real-space cutoff: the short kernel times the number of images per unit length beyond it.
  double rc = 1.0;
  auto tail = [&](double x) {
    return shortKernel(kernel, alpha, x) * na * (2 + 1 / (alpha * alpha * x * T));
  };
  while (tail(rc) > 0.05 * p.elementTolerance) rc *= 1.05;
  p.realSpaceCutoff = rc;
  if (na * (2 * rc / T + 1) > kMaxImagesPerPair)
    throw NumericalError("helical Ewald: more than " + std::to_string(kMaxImagesPerPair) +
                         " real-space images per pair (choose a larger splitting parameter)");
  r.setup.kernel = kernel;
  r.setup.alpha = alpha;
  r.setup.translation = T;
  r.setup.twist = sym.twist();
  r.setup.rotationOrder = na;
  // Half of the element budget goes to the reciprocal part.
  r.setup.elementTolerance = 0.5 * p.elementTolerance;
  return r;
}

struct Site {
  double rho, phi;
};
Site site(const Eigen::Vector3d& x) { return {std::hypot(x.x(), x.y()), std::atan2(x.y(), x.x())}; }

// Visits the pair (i, j): f(value, contribution callback data). Shared by matrix and derivatives.
struct PairResult {
  double value = 0;
  Eigen::Vector3d gradI = Eigen::Vector3d::Zero(), gradJ = Eigen::Vector3d::Zero();
  double dT = 0, dGamma = 0;
};

PairResult pairSum(Kernel kernel, const Resolved& r, const ObjectiveCell& cell, int i, int j,
                   bool withDerivatives) {
  const Symmetry& sym = cell.symmetry;
  const Eigen::Vector3d xi = cell.positions.col(i), xj = cell.positions.col(j);
  PairResult out;
  if (sym.isRing()) {
    // A closed ring is finite: the direct sum over C_Na, eq. (E16).
    for (int c = 0; c < sym.rotationOrder(); ++c) {
      const GroupElement g{0, c};
      if (i == j && g.isIdentity()) continue;
      const Eigen::Vector3d d = sym.apply(g, xj) - xi;
      const double dist = d.norm();
      out.value += fullKernel(kernel, dist);
      if (withDerivatives) {
        const Eigen::Vector3d u = fullKernelDerivative(kernel, dist) / dist * d;
        out.gradI -= u;
        out.gradJ += sym.rotation(g).transpose() * u;
      }
    }
    return out;
  }
  const double alpha = r.plan.splitting;
  // Real-space part, eq. (E4).
  forEachRealSpaceImage(
      sym, r.rotations, xi, xj, r.plan.realSpaceCutoff,
      [&](const GroupElement& g, const Eigen::Vector3d& y, double ca, double sa) {
        if (i == j && g.isIdentity()) return;
        const Eigen::Vector3d d = y - xi;
        const double dist = d.norm();
        if (!withDerivatives) {
          out.value += shortKernel(kernel, alpha, dist);
          return;
        }
        double value, derivative;
        shortKernelWithDerivative(kernel, alpha, dist, value, derivative);
        out.value += value;
        const Eigen::Vector3d u = derivative / dist * d;
        const double zeta = static_cast<double>(g.zeta);
        out.gradI -= u;
        // R(angle)^T u, and d(g x_j)/d gamma = zeta R'(angle) x_j = zeta (-y_y, y_x, 0).
        out.gradJ += Eigen::Vector3d(ca * u.x() + sa * u.y(), -sa * u.x() + ca * u.y(), u.z());
        out.dT += u.z() * zeta;
        out.dGamma += (u.y() * y.x() - u.x() * y.y()) * zeta;
      });
  // Long-range part, eq. (E12).
  const Site si = site(xi), sj = site(xj);
  const detail::PairLongRange lr =
      detail::longRangePair(r.setup, si.rho, sj.rho, si.phi - sj.phi, xi.z() - xj.z(), withDerivatives);
  out.value += lr.value;
  if (i == j) out.value -= selfLongRange(kernel, alpha);
  if (withDerivatives) {
    auto cyl = [](const Site& s, double dRho, double gradPhi, double dz) {
      const double c = std::cos(s.phi), sn = std::sin(s.phi);
      return Eigen::Vector3d(c * dRho - sn * gradPhi, sn * dRho + c * gradPhi, dz);
    };
    out.gradI += cyl(si, lr.dRhoI, lr.gradPhiI, lr.dDz);
    out.gradJ += cyl(sj, lr.dRhoJ, lr.gradPhiJ, -lr.dDz);
    out.dT += lr.dTranslation;
    out.dGamma += lr.dTwist;
  }
  return out;
}

}  // namespace

HelicalLatticeSum::HelicalLatticeSum(Kernel kernel, LatticeSumSettings settings)
    : kernel_(kernel), settings_(std::move(settings)) {
  const double tol = settings_.tolerance;
  if (!(tol >= kMinTolerance && tol <= kMaxTolerance))
    throw InputError(kSource, "ewald tolerance", std::to_string(tol),
                     "a relative tolerance between 1e-13 and 1e-2 (tighter cannot be met in "
                     "double precision)");
}

namespace {
// The plan as reported: the truncations of `r` plus the reciprocal truncation of the widest pair
// (largest radii), which costs one long-range pair sum.
LatticeSumPlan reportedPlan(const Resolved& r, const ObjectiveCell& cell) {
  LatticeSumPlan p = r.plan;
  if (cell.symmetry.isRing() || cell.atomCount() == 0) return p;
  int far = 0;
  for (int i = 0; i < cell.atomCount(); ++i)
    if (cell.positions.col(i).head<2>().norm() > cell.positions.col(far).head<2>().norm()) far = i;
  const Site s = site(cell.positions.col(far));
  const auto lr = detail::longRangePair(r.setup, s.rho, s.rho, 0, 0, false);
  p.maxAngularOrder = lr.maxOrder;
  p.reciprocalTerms = lr.terms;
  p.quadratureNodes = lr.nodes;
  return p;
}
}  // namespace

LatticeSumPlan HelicalLatticeSum::plan(const ObjectiveCell& cell) const {
  return reportedPlan(resolve(kernel_, settings_, cell), cell);
}

Eigen::MatrixXd HelicalLatticeSum::matrix(const ObjectiveCell& cell, LatticeSumPlan* used) const {
  const int n = cell.atomCount();
  const Resolved r = resolve(kernel_, settings_, cell);
  if (used) *used = reportedPlan(r, cell);
  Eigen::MatrixXd phi(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) phi(i, j) = phi(j, i) = pairSum(kernel_, r, cell, i, j, false).value;
  return phi;
}

HelicalLatticeSum::Derivatives HelicalLatticeSum::derivatives(const ObjectiveCell& cell,
                                                              const Eigen::MatrixXd& w,
                                                              LatticeSumPlan* used) const {
  const int n = cell.atomCount();
  if (w.rows() != n || w.cols() != n)
    throw InputError(kSource, "weights", std::to_string(w.rows()) + " x " + std::to_string(w.cols()),
                     "an N_o x N_o matrix, N_o = " + std::to_string(n));
  if (kernel_ == Kernel::Coulomb && !cell.symmetry.isRing()) {
    const double total = w.sum(), scale = w.cwiseAbs().sum();
    if (std::abs(total) > 1e-10 * std::max(scale, 1e-300))
      throw InputError(kSource, "charges", "a cell of net weight " + std::to_string(total),
                       "a neutral cell (sum of charges 0): the Coulomb sum over a screw diverges "
                       "otherwise");
  }
  const Resolved r = resolve(kernel_, settings_, cell);
  if (used) *used = reportedPlan(r, cell);
  Derivatives d;
  d.gradient = Eigen::Matrix3Xd::Zero(3, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      const double wij = (i == j ? 0.5 : 1.0) * 0.5 * (w(i, j) + w(j, i));
      if (wij == 0) continue;
      const PairResult p = pairSum(kernel_, r, cell, i, j, true);
      d.energy += wij * p.value;
      d.gradient.col(i) += wij * p.gradI;
      d.gradient.col(j) += wij * p.gradJ;
      d.dTranslation += wij * p.dT;
      d.dTwist += wij * p.dGamma;
    }
  return d;
}

double HelicalLatticeSum::energy(const ObjectiveCell& cell, const Eigen::VectorXd& q) const {
  if (q.size() != cell.atomCount())
    throw InputError(kSource, "charges", std::to_string(q.size()) + " values",
                     std::to_string(cell.atomCount()) + " (one per cell atom)");
  if (kernel_ == Kernel::Coulomb && !cell.symmetry.isRing() &&
      std::abs(q.sum()) > 1e-10 * std::max(q.cwiseAbs().sum(), 1e-300))
    throw InputError(kSource, "charges", "net charge " + std::to_string(q.sum()) + " per cell",
                     "a neutral cell (sum of charges 0): the Coulomb sum over a screw diverges "
                     "otherwise");
  return 0.5 * q.dot(matrix(cell) * q);
}

}  // namespace mesochain::ewald
