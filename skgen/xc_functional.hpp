#pragma once
// Exchange-correlation through libxc: the pointwise kernel (energy density and the partial
// derivatives ∂e/∂n_s, ∂e/∂σ) and the radial Kohn-Sham potential of a spherical density.
//
// Functionals: "none" (no exchange-correlation, hydrogen-like tests), "lda" (Slater exchange +
// Perdew-Wang 92 correlation), "lda-vwn" (Slater + Vosko-Wilk-Nusair 5, the functional of the
// NIST atomic reference data), "pbe" (Perdew-Burke-Ernzerhof exchange + correlation).
#include <memory>
#include <string>
#include <vector>

#include "skgen/radial_grid.hpp"

namespace mesochain::skgen {

enum class XcKind { None, LdaPw92, LdaVwn, Pbe };

// "none", "lda", "lda-vwn", "pbe"; throws InputError naming `source` for anything else.
XcKind parseXcKind(const std::string& name, const std::string& source);
std::string xcName(XcKind kind);

// Pointwise values at np points. Layouts follow libxc: rho[np*nspin], sigma[np*(1 or 3)]
// (σ_uu, σ_ud, σ_dd when polarised), vrho like rho, vsigma like sigma. `energy` is the energy
// per volume e(r) = ε_xc n (not per particle).
struct XcPointValues {
  std::vector<double> energy, vrho, vsigma;
};

class XcFunctional {
 public:
  XcFunctional(XcKind kind, bool polarised);
  ~XcFunctional();
  XcFunctional(const XcFunctional&) = delete;
  XcFunctional& operator=(const XcFunctional&) = delete;

  XcKind kind() const { return kind_; }
  bool isGga() const { return kind_ == XcKind::Pbe; }
  bool polarised() const { return polarised_; }
  int spins() const { return polarised_ ? 2 : 1; }

  // sigma may be empty for LDA.
  XcPointValues evaluate(const std::vector<double>& rho, const std::vector<double>& sigma) const;

  // Spherical densities n_s(r) on `grid` (one vector per spin; unpolarised: the total).
  // Returns the potentials v_s(r) including the GGA divergence term
  //   v_s = ∂e/∂n_s − (1/r²) d/dr ( r² Σ_t c_st ∂e/∂σ_st dn_t/dr ),  c_ss = 2, c_ud = 1,
  // and the exchange-correlation energy ∫ e d³r in `energy`.
  std::vector<std::vector<double>> radialPotential(const LogGrid& grid,
                                                   const std::vector<std::vector<double>>& n,
                                                   double& energy) const;

 private:
  struct Impl;
  XcKind kind_;
  bool polarised_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mesochain::skgen
