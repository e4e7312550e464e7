#include "skgen/two_centre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mesochain::skgen {

void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;  // Legendre recurrence
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0;
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-15) break;
    }
    x[i] = -z;
    x[n - 1 - i] = z;
    w[i] = w[n - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

namespace {

constexpr double kPi = std::numbers::pi;

// Angular-radial value g(ρ, z) of an orbital (the φ factor 1 or cos φ left out) and its ρ, z
// derivatives, at local coordinates relative to the orbital's atom.
struct OrbitalValue {
  double g = 0.0, gr = 0.0, gz = 0.0;
  double t = 0.0;  // Slater back-end: (−½∇² φ) with the same angular factor as g
};

OrbitalValue evalOrbital(const TwoCentreOrbital& o, int m, double rho, double z) {
  const double r = std::sqrt(rho * rho + z * z);
  double R, dR, tR = 0.0;
  if (!o.slater.empty()) {
    const SlaterValue sv = evaluateSlater(o.slater, o.l, r);
    R = sv.R;
    dR = sv.dR;
    tR = sv.t;
  } else {
    o.grid.interpolateWithDerivative(o.radial, r, R, dR);
  }
  OrbitalValue v;
  if (o.l == 0) {
    const double c = 1.0 / std::sqrt(4.0 * kPi);
    v.g = c * R;
    v.t = c * tR;
    v.gr = c * dR * rho / r;
    v.gz = c * dR * z / r;
  } else if (o.l == 1) {
    const double c = std::sqrt(3.0 / (4.0 * kPi));
    const double P = R / r, dP = dR / r - R / (r * r);
    if (m == 0) {
      v.t = c * tR * z / r;
      v.g = c * P * z;
      v.gr = c * dP * rho * z / r;
      v.gz = c * (dP * z * z / r + P);
    } else {
      v.t = c * tR * rho / r;
      v.g = c * P * rho;
      v.gr = c * (dP * rho * rho / r + P);
      v.gz = c * dP * rho * z / r;
    }
  } else {
    throw std::invalid_argument("two-centre integrals: only s and p orbitals so far");
  }
  return v;
}

}  // namespace

std::vector<SkIntegral> twoCentreIntegrals(const std::vector<TwoCentreOrbital>& orbA,
                                           const std::vector<TwoCentreOrbital>& orbB,
                                           const TwoCentreAtom* atomA, const TwoCentreAtom* atomB,
                                           const XcFunctional* xc, double d,
                                           const TwoCentreQuadrature& q) {
  if (!(d > 0.0)) throw std::invalid_argument("two-centre integrals need a distance d > 0");
  const bool withH = atomA && atomB;
  std::vector<SkIntegral> out;
  for (int a = 0; a < static_cast<int>(orbA.size()); ++a)
    for (int b = 0; b < static_cast<int>(orbB.size()); ++b)
      for (int m = 0; m <= std::min(orbA[a].l, orbB[b].l); ++m) {
        SkIntegral s;
        s.la = orbA[a].l;
        s.lb = orbB[b].l;
        s.m = m;
        s.a = a;
        s.b = b;
        out.push_back(s);
      }

  std::vector<double> te, we, tx, wx;
  gaussLegendre(q.nEta, te, we);
  gaussLegendre(q.nXi, tx, wx);
  const double c = q.clustering;
  const double alpha = std::log(1.0 + q.rMax / c);
  const int np = q.nEta * q.nXi;

  // Points: position (ρ, z) and weight (d/2)³ (ξ² − η²) dξ dη.
  std::vector<double> prho(np), pz(np), pw(np);
  int p = 0;
  for (int i = 0; i < q.nXi; ++i) {
    const double t = 0.5 * (tx[i] + 1.0);
    const double lam = c * (std::exp(alpha * t) - 1.0);  // (d/2)(ξ − 1)
    const double dlam = c * alpha * std::exp(alpha * t) * 0.5 * wx[i];
    const double xi = 1.0 + 2.0 * lam / d;
    const double dxi = 2.0 * dlam / d;
    for (int j = 0; j < q.nEta; ++j, ++p) {
      const double eta = te[j];
      prho[p] = 0.5 * d * std::sqrt(std::max(0.0, (xi * xi - 1.0) * (1.0 - eta * eta)));
      pz[p] = 0.5 * d * (xi * eta + 1.0);  // A at 0, B at d: z = d/2 (ξη + 1)
      pw[p] = std::pow(0.5 * d, 3) * (xi * xi - eta * eta) * dxi * we[j];
    }
  }

  // Potential of the superposition at every point.
  std::vector<double> vloc(np, 0.0), vrho, vsig, nr(np), nz(np);
  const bool potentialSum = withH && q.superposition == Superposition::Potential;
  if (potentialSum && (atomA->xc.size() != atomA->density.size() || atomB->xc.size() != atomB->density.size()))
    throw std::invalid_argument("potential superposition: an atom without its xc potential");
  if (withH) {
    std::vector<double> rhoTot(np), sigma;
    for (int k = 0; k < np; ++k) {
      const double rA = std::sqrt(prho[k] * prho[k] + pz[k] * pz[k]);
      const double zB = pz[k] - d;
      const double rB = std::sqrt(prho[k] * prho[k] + zB * zB);
      double nA, dnA, nB, dnB;
      atomA->grid.interpolateWithDerivative(atomA->density, rA, nA, dnA);
      atomB->grid.interpolateWithDerivative(atomB->density, rB, nB, dnB);
      vloc[k] = -atomA->z / rA + atomA->grid.interpolate(atomA->hartree, rA) - atomB->z / rB +
                atomB->grid.interpolate(atomB->hartree, rB);
      if (potentialSum)
        vloc[k] += atomA->grid.interpolate(atomA->xc, rA) + atomB->grid.interpolate(atomB->xc, rB);
      rhoTot[k] = std::max(0.0, nA + nB);
      nr[k] = dnA * prho[k] / rA + dnB * prho[k] / rB;
      nz[k] = dnA * pz[k] / rA + dnB * zB / rB;
    }
    if (xc && xc->kind() != XcKind::None && !potentialSum) {
      if (xc->polarised()) throw std::invalid_argument("two-centre xc: spin-unpolarised only");
      if (xc->isGga()) {
        sigma.resize(np);
        for (int k = 0; k < np; ++k) sigma[k] = nr[k] * nr[k] + nz[k] * nz[k];
      }
      const XcPointValues val = xc->evaluate(rhoTot, sigma);
      vrho = val.vrho;
      vsig = val.vsigma;
    }
  }

  for (SkIntegral& I : out) {
    const TwoCentreOrbital& oa = orbA[I.a];
    const TwoCentreOrbital& ob = orbB[I.b];
    const double phiFactor = I.m == 0 ? 2.0 * kPi : kPi;
    double S = 0.0, H = 0.0;
    for (int k = 0; k < np; ++k) {
      const double zB = pz[k] - d;
      const OrbitalValue va = evalOrbital(oa, I.m, prho[k], pz[k]);
      const OrbitalValue vb = evalOrbital(ob, I.m, prho[k], zB);
      const double prod = va.g * vb.g;
      S += pw[k] * prod;
      if (withH) {
        const double rB = std::sqrt(prho[k] * prho[k] + zB * zB);
        double v = vloc[k];
        if (!vrho.empty()) v += vrho[k];
        double term = v * prod;
        if (ob.slater.empty())
          term += (ob.energy - ob.grid.interpolate(ob.potential, rB)) * prod;  // T φ_b = (ε − v) φ_b
        else
          term += va.g * vb.t;
        if (!vsig.empty()) {
          const double gr = va.gr * vb.g + va.g * vb.gr;
          const double gz = va.gz * vb.g + va.g * vb.gz;
          term += 2.0 * vsig[k] * (nr[k] * gr + nz[k] * gz);
        }
        H += pw[k] * term;
      }
    }
    I.s = phiFactor * S;
    I.h = phiFactor * H;
  }
  return out;
}

}  // namespace mesochain::skgen
