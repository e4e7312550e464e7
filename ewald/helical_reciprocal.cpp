#include "ewald/helical_reciprocal.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "ewald/scaled_bessel.hpp"
#include "ewald/small_t_series.hpp"

namespace mesochain::ewald::detail {

using units::kPi;

namespace {

constexpr double kEulerGamma = 0.57721566490153286061;
constexpr int kQuadratureOrder = 12;   // Gauss-Legendre nodes per panel
constexpr int kMaxOrder = 200000;      // largest angular order we accept before giving up
constexpr long kMaxTermsPerNode = 20000000;

// Kernel weight omega(t) of the u-integral, eq. (E11): Coulomb 1, 1/r^6 (sqrt(pi)/2) t^(5/2).
double omega(Kernel kernel, double t) {
  return kernel == Kernel::Coulomb ? 1.0 : 0.5 * std::sqrt(kPi) * t * t * std::sqrt(t);
}

struct Accumulator {
  double f = 0, fRhoI = 0, fRhoJ = 0, lOverRhoI = 0, lOverRhoJ = 0, fQ = 0;
};

struct OrderBlock {
  long kLow = 0;
  std::vector<Accumulator> acc;  // index k - kLow
};

}  // namespace

void gaussLegendre(int order, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.resize(order);
  weights.resize(order);
  for (int i = 0; i < order; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (order + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int n = 2; n <= order; ++n) {
        const double p2 = ((2.0 * n - 1) * x * p1 - (n - 1.0) * p0) / n;
        p0 = p1;
        p1 = p2;
      }
      dp = order * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[i] = x;
    weights[i] = 2.0 / ((1 - x * x) * dp * dp);
  }
}

PairLongRange longRangePair(const ReciprocalSetup& s, double rhoI, double rhoJ, double dphi,
                            double dz, bool withDerivatives) {
  const bool coulomb = s.kernel == Kernel::Coulomb;
  const int na = s.rotationOrder;
  const double T = s.translation, gamma = s.twist, alpha2 = s.alpha * s.alpha;
  const double pref = na / T;  // eq. (E8)
  const double drho2 = (rhoI - rhoJ) * (rhoI - rhoJ);
  const double eps = s.elementTolerance;

  // Split of the u-integral at t_c = min(alpha^2, 1 / (rho_i + rho_j)^2), eq. (E18): below t_c
  // the Taylor series of B_l in t integrates in closed form (small_t_series.hpp); above it, up to
  // alpha^2, composite Gauss-Legendre in u = ln(t / alpha^2).
  const double spread = (rhoI + rhoJ) * (rhoI + rhoJ);
  const double tc = spread * alpha2 > 1 ? 1 / spread : alpha2;
  const double uMin = std::log(tc / alpha2);
  const int panels = uMin < 0 ? std::max(1, static_cast<int>(std::ceil(-uMin / s.panelWidth - 1e-9))) : 0;
  const double h = panels > 0 ? -uMin / panels : 0.0;

  static thread_local std::vector<double> glx, glw;
  if (glx.empty()) gaussLegendre(kQuadratureOrder, glx, glw);

  // Smallest per-term threshold (at t = alpha^2) fixes the k range kept per order.
  const double uRange = std::max(-uMin, 1.0);
  auto threshold = [&](double t) { return 0.02 * eps / (2 * pref * omega(s.kernel, t) * uRange); };
  const double deltaMin = threshold(alpha2);
  double qMaxAll = 2 * s.alpha * std::sqrt(std::max(std::log(1 / deltaMin), 1.0));

  // Orders and axial ranges of the small-t part, eq. (E20): order l is bounded by
  // A_l = c t_c^beta sum_n |P_n^(l)| / max(l + beta, 1) times sum_k e^{-x_k}, x = q^2 / (4 t_c),
  // which is at most 1 + sqrt(4 pi t_c) / dq; wave numbers with x > X_l leave out at most
  // 2 A_l e^{-X_l} (1 + sqrt(t_c / X_l) / dq).
  SmallTSeries series(s.kernel, tc, rhoI, rhoJ);
  const double beta = coulomb ? 0.0 : 2.5;
  const double dq = 2 * kPi / T;
  const double deltaB = 0.02 * eps / (2 * pref * (series.maxPower() + 2));
  const double kSum = 1 + std::sqrt(4 * kPi * tc) / dq;
  struct SeriesOrder {
    int m;
    double xMax;
  };
  static thread_local std::vector<SeriesOrder> seriesOrders;
  seriesOrders.clear();
  for (int m = 0; m * na <= series.maxPower() + (withDerivatives ? 1 : 0); ++m) {
    const int l = m * na;
    // With derivatives, measured like the quadrature part in units of 1/alpha.
    const double A = std::max(series.magnitude(l),
                              withDerivatives ? series.derivativeMagnitude(l) / s.alpha : 0.0) /
                     std::max(l + beta, 1.0);
    if (m > 0 && A * kSum < deltaB) break;
    double X = 1;
    for (int it = 0; it < 3; ++it)
      X = std::max(1.0, std::log(std::max(2 * A * (1 + std::sqrt(tc / X) / dq) / deltaB, 1.0)));
    seriesOrders.push_back({m, X});
    qMaxAll = std::max(qMaxAll, 2 * std::sqrt(tc * X));
  }

  static thread_local std::vector<OrderBlock> blocks;
  static thread_local std::vector<double> ie;
  size_t blocksUsed = 0;
  auto block = [&](int m) -> OrderBlock& {
    while (blocksUsed <= static_cast<size_t>(m)) {
      if (blocks.size() <= blocksUsed) blocks.emplace_back();
      OrderBlock& b = blocks[blocksUsed];
      const double lg = static_cast<double>(blocksUsed) * na * gamma;
      b.kLow = static_cast<long>(std::floor((-T * qMaxAll - lg) / (2 * kPi)));
      const long kHigh = static_cast<long>(std::ceil((T * qMaxAll - lg) / (2 * kPi)));
      b.acc.assign(static_cast<size_t>(kHigh - b.kLow + 1), Accumulator{});
      ++blocksUsed;
    }
    return blocks[m];
  };
  block(0);

  PairLongRange out;
  for (int p = 0; p < panels; ++p) {
    const double u0 = uMin + p * h;
    for (int n = 0; n < kQuadratureOrder; ++n) {
      const double u = u0 + 0.5 * h * (glx[n] + 1);
      const double t = alpha2 * std::exp(u);
      const double w = 0.5 * h * glw[n] * omega(s.kernel, t);
      const double delta = threshold(t);
      const double g = std::exp(-t * drho2);
      const double x = 2 * t * rhoI * rhoJ;
      ++out.nodes;
      if (g < delta && !coulomb) continue;
      // Orders with g Ie_l(x) >= delta; Ie_l ~ exp(-l^2 / 2x) for l << x, faster beyond.
      const double lb = std::log(std::max(g / delta, 1.0));
      int lEst = static_cast<int>(std::ceil(std::sqrt(2 * x * lb) + lb + 2));
      for (;;) {
        if (lEst > kMaxOrder)
          throw NumericalError("helical Ewald: more than " + std::to_string(kMaxOrder) +
                               " angular orders needed (radius too large for the tolerance)");
        scaledBesselISequence(x, lEst + 2, ie);
        if (g * ie[lEst] < delta || x == 0) break;
        lEst *= 2;
      }
      const double q4t = 1 / (4 * t);
      for (int m = 0;; ++m) {
        const int l = m * na;
        if (l > lEst + 1) break;
        const double b = g * ie[l];
        // With derivatives, order l also enters through Ie_{l-1} (eq. (E17)): on the axis B_1 = 0
        // but its radial derivative is not. Measured in units of 1/alpha.
        const double mag =
            withDerivatives && l > 0
                ? std::max(b, g * ie[l - 1] * t * std::max(rhoI, rhoJ) / s.alpha)
                : b;
        if (mag < delta && !(coulomb && l == 0)) break;  // Ie_l decreases with l
        out.maxOrder = std::max(out.maxOrder, l);
        const double lgam = l * gamma;
        const double qc = mag > delta ? 2 * std::sqrt(t * std::log(mag / delta)) : 0.0;
        long kLo = static_cast<long>(std::ceil((-T * qc - lgam) / (2 * kPi)));
        long kHi = static_cast<long>(std::floor((T * qc - lgam) / (2 * kPi)));
        if (coulomb && l == 0) kLo = std::min(kLo, 0L), kHi = std::max(kHi, 0L);
        OrderBlock& blk = block(m);
        kLo = std::max(kLo, blk.kLow);
        kHi = std::min(kHi, blk.kLow + static_cast<long>(blk.acc.size()) - 1);
        if (kHi - kLo > kMaxTermsPerNode)
          throw NumericalError("helical Ewald: too many axial wave numbers per order");
        // Radial factors, eq. (E9) and its derivatives (E17).
        const double iem = l == 0 ? ie[1] : ie[l - 1], iep = ie[l + 1];
        const double bRi = g * (-2 * t * rhoI * ie[l] + t * rhoJ * (iem + iep));
        const double bRj = g * (-2 * t * rhoJ * ie[l] + t * rhoI * (iem + iep));
        const double lRi = l == 0 ? 0.0 : g * t * rhoJ * (iem - iep);
        const double lRj = l == 0 ? 0.0 : g * t * rhoI * (iem - iep);
        for (long k = kLo; k <= kHi; ++k) {
          const double q = (lgam + 2 * kPi * k) / T;
          const double e = std::exp(-q * q * q4t);
          Accumulator& a = blk.acc[static_cast<size_t>(k - blk.kLow)];
          // Coulomb l = 0, q = 0: the neutralised integrand B_0 - 1, eq. (E14).
          a.f += w * ((coulomb && l == 0 && k == 0) ? b - 1 : b * e);
          ++out.terms;
          if (withDerivatives) {
            a.fRhoI += w * bRi * e;
            a.fRhoJ += w * bRj * e;
            a.lOverRhoI += w * lRi * e;
            a.lOverRhoJ += w * lRj * e;
            a.fQ += w * b * e * (-q * 2 * q4t);
          }
        }
      }
    }
  }

  // Small-t part in closed form, eqs. (E19)-(E20).
  for (const SeriesOrder& so : seriesOrders) {
    const int l = so.m * na;
    const double lgam = l * gamma;
    const double qc = 2 * std::sqrt(tc * so.xMax);
    long kLo = static_cast<long>(std::ceil((-T * qc - lgam) / (2 * kPi)));
    long kHi = static_cast<long>(std::floor((T * qc - lgam) / (2 * kPi)));
    if (coulomb && l == 0) kLo = std::min(kLo, 0L), kHi = std::max(kHi, 0L);
    OrderBlock& blk = block(so.m);
    kLo = std::max(kLo, blk.kLow);
    kHi = std::min(kHi, blk.kLow + static_cast<long>(blk.acc.size()) - 1);
    if (kHi - kLo > kMaxTermsPerNode)
      throw NumericalError("helical Ewald: too many axial wave numbers per order");
    out.maxOrder = std::max(out.maxOrder, l);
    for (long k = kLo; k <= kHi; ++k) {
      const double q = (lgam + 2 * kPi * k) / T;
      const SmallTIntegrals in = series.integrals(l, q, coulomb && l == 0 && k == 0, withDerivatives);
      Accumulator& a = blk.acc[static_cast<size_t>(k - blk.kLow)];
      a.f += in.f;
      a.fRhoI += in.fRhoI;
      a.fRhoJ += in.fRhoJ;
      a.lOverRhoI += in.lOverRhoI;
      a.lOverRhoJ += in.lOverRhoJ;
      a.fQ += in.fQ;
      ++out.terms;
    }
  }
  if (coulomb) {
    // The convention constant 2 ln(alpha) + gamma_E of eq. (E14): a remote line is -2 lambda ln(rho).
    blocks[0].acc[static_cast<size_t>(-blocks[0].kLow)].f += 2 * std::log(s.alpha) + kEulerGamma;
  }

  // Assemble, eq. (E12): sum over l >= 0 (factor 2 for l > 0 covers -l, -k) and all k.
  for (size_t m = 0; m < blocksUsed; ++m) {
    const OrderBlock& blk = blocks[m];
    const int l = static_cast<int>(m) * na;
    const double mult = pref * (l == 0 ? 1.0 : 2.0);
    for (size_t ik = 0; ik < blk.acc.size(); ++ik) {
      const Accumulator& a = blk.acc[ik];
      if (a.f == 0 && a.fRhoI == 0 && a.fRhoJ == 0) continue;
      const long k = blk.kLow + static_cast<long>(ik);
      const double q = (l * gamma + 2 * kPi * k) / T;
      const double theta = l * dphi - q * dz;
      const double c = std::cos(theta), sn = std::sin(theta);
      out.value += mult * c * a.f;
      if (!withDerivatives) continue;
      out.dRhoI += mult * c * a.fRhoI;
      out.dRhoJ += mult * c * a.fRhoJ;
      out.gradPhiI += -mult * sn * a.lOverRhoI;
      out.gradPhiJ += mult * sn * a.lOverRhoJ;
      out.dDz += mult * q * sn * a.f;
      out.dTranslation += -mult * c * a.f / T + mult * (-sn * dz * q / T * a.f - c * a.fQ * q / T);
      out.dTwist += mult * (sn * dz * l / T * a.f + c * a.fQ * l / T);
    }
  }
  for (size_t m = 0; m < blocksUsed; ++m)
    std::fill(blocks[m].acc.begin(), blocks[m].acc.end(), Accumulator{});
  return out;
}

}  // namespace mesochain::ewald::detail
