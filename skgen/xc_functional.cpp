#include "skgen/xc_functional.hpp"

#include <xc.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "common/errors.hpp"

namespace mesochain::skgen {

XcKind parseXcKind(const std::string& name, const std::string& source) {
  if (name == "none") return XcKind::None;
  if (name == "lda" || name == "lda-pw92") return XcKind::LdaPw92;
  if (name == "lda-vwn") return XcKind::LdaVwn;
  if (name == "pbe") return XcKind::Pbe;
  throw InputError(source, "key functional", "'" + name + "'",
                   "one of none, lda (PW92), lda-vwn, pbe");
}

std::string xcName(XcKind kind) {
  switch (kind) {
    case XcKind::None: return "none";
    case XcKind::LdaPw92: return "lda";
    case XcKind::LdaVwn: return "lda-vwn";
    case XcKind::Pbe: return "pbe";
  }
  return "?";
}

struct XcFunctional::Impl {
  std::vector<xc_func_type> funcs;
  ~Impl() {
    for (auto& f : funcs) xc_func_end(&f);
  }
};

XcFunctional::XcFunctional(XcKind kind, bool polarised)
    : kind_(kind), polarised_(polarised), impl_(std::make_unique<Impl>()) {
  std::vector<int> ids;
  switch (kind) {
    case XcKind::None: break;
    case XcKind::LdaPw92: ids = {XC_LDA_X, XC_LDA_C_PW}; break;
    case XcKind::LdaVwn: ids = {XC_LDA_X, XC_LDA_C_VWN}; break;
    case XcKind::Pbe: ids = {XC_GGA_X_PBE, XC_GGA_C_PBE}; break;
  }
  for (int id : ids) {
    xc_func_type f;
    if (xc_func_init(&f, id, polarised ? XC_POLARIZED : XC_UNPOLARIZED) != 0) {
      throw std::runtime_error("libxc: functional " + std::to_string(id) + " not available");
    }
    impl_->funcs.push_back(f);
  }
}

XcFunctional::~XcFunctional() = default;

XcPointValues XcFunctional::evaluate(const std::vector<double>& rho,
                                     const std::vector<double>& sigma) const {
  const int ns = spins();
  const std::size_t np = rho.size() / ns;
  const std::size_t nsig = polarised_ ? 3 : 1;
  XcPointValues out;
  out.energy.assign(np, 0.0);
  out.vrho.assign(np * ns, 0.0);
  if (isGga()) out.vsigma.assign(np * nsig, 0.0);
  if (impl_->funcs.empty() || np == 0) return out;
  std::vector<double> zk(np), vrho(np * ns), vsigma(isGga() ? np * nsig : 0);
  for (const auto& f : impl_->funcs) {
    if (f.info->family == XC_FAMILY_LDA) {
      xc_lda_exc_vxc(&f, np, rho.data(), zk.data(), vrho.data());
    } else {
      xc_gga_exc_vxc(&f, np, rho.data(), sigma.data(), zk.data(), vrho.data(), vsigma.data());
      for (std::size_t i = 0; i < vsigma.size(); ++i) out.vsigma[i] += vsigma[i];
    }
    for (std::size_t p = 0; p < np; ++p) {
      double n = 0.0;
      for (int s = 0; s < ns; ++s) n += rho[p * ns + s];
      out.energy[p] += zk[p] * n;
    }
    for (std::size_t i = 0; i < vrho.size(); ++i) out.vrho[i] += vrho[i];
  }
  return out;
}

std::vector<std::vector<double>> XcFunctional::radialPotential(
    const LogGrid& grid, const std::vector<std::vector<double>>& n, double& energy) const {
  const int ns = spins();
  const int np = grid.size();
  std::vector<std::vector<double>> v(ns, std::vector<double>(np, 0.0));
  energy = 0.0;
  if (kind_ == XcKind::None) return v;

  std::vector<double> rho(static_cast<std::size_t>(np) * ns);
  for (int p = 0; p < np; ++p)
    for (int s = 0; s < ns; ++s) rho[p * ns + s] = std::max(n[s][p], 0.0);

  // dn_s/dr = (dn_s/dx) / r
  std::vector<std::vector<double>> dn(ns);
  std::vector<double> sigma;
  if (isGga()) {
    for (int s = 0; s < ns; ++s) {
      dn[s] = grid.derivativeDx(n[s]);
      for (int p = 0; p < np; ++p) dn[s][p] /= grid.r[p];
    }
    if (ns == 1) {
      sigma.resize(np);
      for (int p = 0; p < np; ++p) sigma[p] = dn[0][p] * dn[0][p];
    } else {
      sigma.resize(3 * static_cast<std::size_t>(np));
      for (int p = 0; p < np; ++p) {
        sigma[3 * p] = dn[0][p] * dn[0][p];
        sigma[3 * p + 1] = dn[0][p] * dn[1][p];
        sigma[3 * p + 2] = dn[1][p] * dn[1][p];
      }
    }
  }
  const XcPointValues val = evaluate(rho, sigma);

  std::vector<double> f(np);
  for (int p = 0; p < np; ++p) f[p] = val.energy[p] * grid.r[p] * grid.r[p] * grid.r[p];
  energy = 4.0 * std::numbers::pi * grid.integrateDx(f);

  for (int s = 0; s < ns; ++s)
    for (int p = 0; p < np; ++p) v[s][p] = val.vrho[p * ns + s];
  if (!isGga()) return v;

  // Divergence term: (1/r²) d/dr (r² A) = (1/r³) d/dx (r² A), A the radial flux.
  for (int s = 0; s < ns; ++s) {
    std::vector<double> flux(np);
    for (int p = 0; p < np; ++p) {
      double a;
      if (ns == 1) {
        a = 2.0 * val.vsigma[p] * dn[0][p];
      } else {
        const int t = 1 - s;
        const double vss = val.vsigma[3 * p + (s == 0 ? 0 : 2)];
        const double vud = val.vsigma[3 * p + 1];
        a = 2.0 * vss * dn[s][p] + vud * dn[t][p];
      }
      flux[p] = grid.r[p] * grid.r[p] * a;
    }
    const std::vector<double> dflux = grid.derivativeDx(flux);
    for (int p = 0; p < np; ++p) {
      v[s][p] -= dflux[p] / (grid.r[p] * grid.r[p] * grid.r[p]);
    }
  }
  return v;
}

}  // namespace mesochain::skgen
