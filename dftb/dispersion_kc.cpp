#include "dftb/dispersion_kc.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "dftb/image_pair_sum.hpp"
#include "dftb/term_registry.hpp"
#include "objective/core/images.hpp"

namespace mesochain::dftb {

namespace {

constexpr double kMeV = 1e-3 * units::kEvInHartree;
constexpr double kA = units::kAngstromInBohr;

KolmogorovCrespiParameters fromMetalUnits(std::string name, double z0, double c0, double c2,
                                          double c4, double c, double delta, double lambda,
                                          double a, double taperStart, double cutoff) {
  KolmogorovCrespiParameters p;
  p.name = std::move(name);
  p.z0 = z0 * kA;
  p.c0 = c0 * kMeV;
  p.c2 = c2 * kMeV;
  p.c4 = c4 * kMeV;
  p.c = c * kMeV;
  p.delta = delta * kA;
  p.lambda = lambda / kA;
  p.a = a * kMeV;
  p.taperStart = taperStart * kA;
  p.cutoff = cutoff * kA;
  return p;
}

}  // namespace

KolmogorovCrespiParameters KolmogorovCrespiParameters::kc2005() {
  return fromMetalUnits("kc2005", 3.34, 15.71, 12.29, 4.933, 3.030, 0.578, 3.629, 10.238, 20.0,
                        25.0);
}

KolmogorovCrespiParameters KolmogorovCrespiParameters::ouyang2018() {
  return fromMetalUnits("ouyang2018", 3.416084, 20.021583, 10.9055107, 4.2756354, 1.0010836e-2,
                        0.8447122, 2.9360584, 14.3132588, 0.0, 16.0);
}

KolmogorovCrespiParameters KolmogorovCrespiParameters::byName(const std::string& name,
                                                              const std::string& source,
                                                              const std::string& key) {
  if (name == "kc2005") return kc2005();
  if (name == "ouyang2018") return ouyang2018();
  throw InputError(source, key, "\"" + name + "\"", "\"kc2005\" or \"ouyang2018\"");
}

void validate(const KolmogorovCrespiSettings& s) {
  const std::string src = "the calculator settings";
  const KolmogorovCrespiParameters p =
      KolmogorovCrespiParameters::byName(s.parameters, src, "kc.parameters");
  requireFinite(s.cutoff, src, "kc.cutoff_bohr");
  requireFinite(s.taperStart, src, "kc.taper_start_bohr");
  requireFinite(s.bondCutoff, src, "kc.bond_cutoff_bohr");
  if (!(s.cutoff >= 0.0))
    throw InputError(src, "kc.cutoff_bohr", std::to_string(s.cutoff), "> 0 (0: the set's)");
  if (!(s.bondCutoff > 0.0))
    throw InputError(src, "kc.bond_cutoff_bohr", std::to_string(s.bondCutoff),
                     "a positive distance");
  const double rc = s.cutoff > 0.0 ? s.cutoff : p.cutoff;
  const double ron = s.taperStart >= 0.0 ? s.taperStart : p.taperStart;
  if (!(ron < rc))
    throw InputError(src, "kc.taper_start_bohr", fmt::format("{} >= cutoff {}", ron, rc),
                     "a taper start below the cutoff");
  if (!(rc > 2.0 * p.z0))
    throw InputError(src, "kc.cutoff_bohr", fmt::format("{} Bohr", rc),
                     fmt::format("a cutoff beyond 2 z0 = {:.4g} Bohr", 2.0 * p.z0));
}

KolmogorovCrespiParameters resolvedParameters(const KolmogorovCrespiSettings& s) {
  KolmogorovCrespiParameters p =
      KolmogorovCrespiParameters::byName(s.parameters, "the calculator settings", "kc.parameters");
  if (s.cutoff > 0.0) p.cutoff = s.cutoff;
  if (s.taperStart >= 0.0) p.taperStart = s.taperStart;
  return p;
}

void kcTaper(double r, double taperStart, double cutoff, double& value, double& derivative) {
  value = 1.0;
  derivative = 0.0;
  if (r <= taperStart) return;
  if (r >= cutoff) {
    value = 0.0;
    return;
  }
  // The taper of Ouyang et al. 2018 (and of Leven et al., J. Chem. Theory Comput. 12, 2896 (2016)):
  // Tap(x) = 20 x^7 - 70 x^6 + 84 x^5 - 35 x^4 + 1, dTap/dx = 140 x^3 (x - 1)^3.
  const double w = cutoff - taperStart;
  const double x = (r - taperStart) / w;
  const double x2 = x * x, x3 = x2 * x, x4 = x2 * x2;
  value = ((((20.0 * x - 70.0) * x + 84.0) * x - 35.0) * x4) + 1.0;
  const double xm1 = x - 1.0;
  derivative = 140.0 * x3 * xm1 * xm1 * xm1 / w;
}

KcPair kcPair(const KolmogorovCrespiParameters& p, const Eigen::Vector3d& d,
              const Eigen::Vector3d& ni, const Eigen::Vector3d& nj) {
  // The pair energy of Kolmogorov & Crespi 2005 (header) and its derivatives.
  const double r2 = d.squaredNorm(), r = std::sqrt(r2);
  const double inv2 = 1.0 / (p.delta * p.delta);
  const double ai = ni.dot(d), aj = nj.dot(d);
  const double si = (r2 - ai * ai) * inv2, sj = (r2 - aj * aj) * inv2;  // (rho/delta)^2
  auto f = [&](double s, double& df) {
    const double e = std::exp(-s);
    const double poly = p.c0 + (p.c2 + p.c4 * s) * s;
    df = e * (p.c2 + 2.0 * p.c4 * s - poly);  // d f / d s
    return e * poly;
  };
  double dfi = 0, dfj = 0;
  const double fi = f(si, dfi), fj = f(sj, dfj);
  const double ex = std::exp(-p.lambda * (r - p.z0));
  const double x6 = std::pow(p.z0 * p.z0 / r2, 3);
  KcPair out;
  out.v = ex * (p.c + fi + fj) - p.a * x6;
  // d/dd: e^{-lambda (r - z0)} -> -lambda e d/r; (z0/r)^6 -> -6 (z0/r)^6 d / r^2;
  // s_i -> 2 (d - a_i n_i) / delta^2.
  out.dd = (-p.lambda * ex * (p.c + fi + fj) / r + 6.0 * p.a * x6 / r2) * d +
           (2.0 * inv2 * ex) * (dfi * (d - ai * ni) + dfj * (d - aj * nj));
  out.dni = (-2.0 * inv2 * ex * dfi * ai) * d;
  out.dnj = (-2.0 * inv2 * ex * dfj * aj) * d;
  return out;
}

namespace {

using objective::GroupElement;
using objective::ImageList;
using objective::ImagePair;
using objective::ObjectiveCell;
using objective::Symmetry;

struct Bond {
  int j;
  GroupElement g;
  Eigen::Vector3d d;
};

// An image site: cell atom `atom` under g.
struct Site {
  int atom;
  GroupElement g;
  friend bool operator==(const Site&, const Site&) = default;
};

GroupElement compose(const Symmetry& s, const GroupElement& a, const GroupElement& b) {
  return {a.zeta + b.zeta, (a.c + b.c) % s.rotationOrder()};
}

// The sites within kExcludedBondDistance bonds of cell atom `root` (itself left out), by a
// breadth-first search over the bonds of every cell atom moved by the group element of the
// site they leave from.
std::vector<Site> sitesWithinBonds(const Symmetry& s, const std::vector<std::vector<Bond>>& bonds,
                                   int root) {
  std::vector<Site> seen{{root, {}}};
  std::vector<Site> frontier = seen;
  for (int depth = 0; depth < kExcludedBondDistance; ++depth) {
    std::vector<Site> next;
    for (const Site& site : frontier)
      for (const Bond& b : bonds[static_cast<std::size_t>(site.atom)]) {
        const Site to{b.j, compose(s, site.g, b.g)};
        if (std::find(seen.begin(), seen.end(), to) != seen.end()) continue;
        seen.push_back(to);
        next.push_back(to);
      }
    frontier = std::move(next);
  }
  seen.erase(seen.begin());
  return seen;
}

}  // namespace

KolmogorovCrespiTerm::KolmogorovCrespiTerm(KolmogorovCrespiParameters parameters,
                                           double bondCutoff)
    : p_(std::move(parameters)), bondCutoff_(bondCutoff) {}

void KolmogorovCrespiTerm::evaluate(const ObjectiveCell& cell, const EvaluationRequest& request,
                                    TermOutput& out) const {
  const Symmetry& sym = cell.symmetry;
  const int n = cell.atomCount();
  const bool gradient = request.gradient, screw = request.strain && !sym.isRing();
  // Bond graph and normals.
  std::vector<std::vector<Bond>> bonds(static_cast<std::size_t>(n));
  const ImageList bondPairs(cell, bondCutoff_);
  for (const ImagePair& b : bondPairs.pairs())
    bonds[static_cast<std::size_t>(b.i)].push_back({b.j, b.g, b.d});
  Eigen::Matrix3Xd normal(3, n), rawNormal(3, n);
  for (int i = 0; i < n; ++i) {
    const auto& b = bonds[static_cast<std::size_t>(i)];
    if (b.size() != 3)
      throw InputError("<kolmogorov_crespi>", fmt::format("atom {}", i + 1),
                       fmt::format("{} bonded neighbours within {:.4g} Å", b.size(),
                                   bondCutoff_ * units::kBohrInAngstrom),
                       "exactly 3 (sp2 carbon: the local normal is that of the plane through "
                       "the three neighbours)");
    rawNormal.col(i) = (b[1].d - b[0].d).cross(b[2].d - b[0].d);
    normal.col(i) = rawNormal.col(i).normalized();
  }
  std::vector<std::vector<Site>> excluded(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) excluded[static_cast<std::size_t>(i)] = sitesWithinBonds(sym, bonds, i);
  const double excludedReach = kExcludedBondDistance * bondCutoff_;

  // Pair sum.
  ImagePairSum s;
  if (gradient) s.gradient = Eigen::Matrix3Xd::Zero(3, n);
  Eigen::Matrix3Xd dNormal = Eigen::Matrix3Xd::Zero(3, n);  // dE/dn_i
  const ImageList images(cell, p_.cutoff);
  for (const ImagePair& q : images.pairs()) {
    if (q.r < excludedReach) {
      const auto& ex = excluded[static_cast<std::size_t>(q.i)];
      if (std::find(ex.begin(), ex.end(), Site{q.j, q.g}) != ex.end()) continue;
    }
    double tap = 0, dtap = 0;
    kcTaper(q.r, p_.taperStart, p_.cutoff, tap, dtap);
    if (tap == 0.0) continue;
    const Eigen::Matrix3d rot = sym.rotation(q.g);
    const Eigen::Vector3d m = rot * normal.col(q.j);
    const KcPair v = kcPair(p_, q.d, normal.col(q.i), m);
    s.energy += 0.5 * tap * v.v;
    if (!gradient && !screw) continue;
    // 1/2 Tap V: d/dd, d/dn_i, d/dm.
    const Eigen::Vector3d fd = 0.5 * (dtap * v.v / q.r * q.d + tap * v.dd);
    const Eigen::Vector3d fm = 0.5 * tap * v.dnj;
    dNormal.col(q.i) += 0.5 * tap * v.dni;
    dNormal.col(q.j) += rot.transpose() * fm;  // m = R(g) n_j
    if (gradient) s.gradient.col(q.i) -= fd;
    addImagePointDerivative(cell, q.j, q.g, fd, gradient, screw, s);
    if (screw)  // dm/dgamma = zeta R'(phi_g) n_j
      s.dTwist += fm.dot(static_cast<double>(q.g.zeta) *
                         objective::rotationZDerivative(sym.angle(q.g)) * normal.col(q.j));
  }
  // Normals: n = N/|N|, N = (y2 - y1) x (y3 - y1), y_k = g_k(x_{j_k}) the bonded images.
  if (gradient || screw)
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d nn = normal.col(i);
      const Eigen::Vector3d dN =
          (dNormal.col(i) - nn * nn.dot(dNormal.col(i))) / rawNormal.col(i).norm();
      const auto& b = bonds[static_cast<std::size_t>(i)];
      const Eigen::Vector3d e1 = b[1].d - b[0].d, e2 = b[2].d - b[0].d;
      const Eigen::Vector3d f1 = e2.cross(dN), f2 = dN.cross(e1);  // dE/dy2, dE/dy3
      const Eigen::Vector3d f0 = -f1 - f2;                          // dE/dy1
      addImagePointDerivative(cell, b[0].j, b[0].g, f0, gradient, screw, s);
      addImagePointDerivative(cell, b[1].j, b[1].g, f1, gradient, screw, s);
      addImagePointDerivative(cell, b[2].j, b[2].g, f2, gradient, screw, s);
    }
  out.energies.add(name(), EnergyKind::Energy, s.energy, "Kolmogorov-Crespi");
  if (gradient) out.gradient = std::move(s.gradient);
  out.dEdTranslation = s.dTranslation;
  out.dEdTwist = s.dTwist;
}

MESOCHAIN_DFTB_TERM(TermRegistration{
    "kolmogorov_crespi", 300,
    "Kolmogorov-Crespi registry-dependent interlayer potential (pairs more than 3 bonds apart)",
    false, [](const CalculatorSettings& s) { return s.kc.enabled; },
    [](const TermBuild& b) -> std::unique_ptr<EnergyTerm> {
      const KolmogorovCrespiSettings& k = b.settings.kc;
      validate(k);
      return std::make_unique<KolmogorovCrespiTerm>(resolvedParameters(k), k.bondCutoff);
    },
    nullptr})

}  // namespace mesochain::dftb
