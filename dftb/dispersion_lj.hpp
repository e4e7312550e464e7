#pragma once
// Lennard-Jones dispersion kernel in the form DFTB+ uses for its UFF dispersion
// (L. Zhechkov, T. Heine, S. Patchkovskii, G. Seifert, H. A. Duarte, J. Chem. Theory Comput. 1,
// 841 (2005); DFTB+ src/dftbp/dftb/dispuff.F90):
//   r >= r_s:  V(r) = eps [ (r0/r)^12 - 2 (r0/r)^6 ]      (minimum -eps at r = r0)
//   r <  r_s:  V(r) = U0 - U5 r^5 - U10 r^10
// with r_s = 2^(-1/6) r0, the distance where the Lennard-Jones term crosses zero. U0, U5, U10
// make value, first and second derivative continuous at r_s. Solving those three conditions
// (V(r_s) = 0, r_s V'(r_s) = -24 eps, r_s^2 V''(r_s) = 456 eps) gives
//   U0 = 396/25 eps,  U5 = 2^(5/6) 672/25 eps / r0^5,  U10 = -2^(2/3) 552/25 eps / r0^10,
// the constants of the paper and of DFTB+ (checked in tests/dftb/test_dispersion_lj.cpp).
// Beyond `cutoff` the kernel is zero (plain truncation; value and derivative jump there).
#include "dftb/parameters.hpp"

namespace mesochain::dftb {

class UffLennardJones final : public RadialPotential {
 public:
  // epsilon: well depth (Hartree); r0: distance of the minimum (Bohr); cutoff (Bohr).
  UffLennardJones(double epsilon, double r0, double cutoff);

  // Carbon: eps = 0.069 kcal/mol, r0 = 3.80 Angstrom (the project's default; note that the UFF
  // values DFTB+ takes by default for C are D = 0.105 kcal/mol, x = 3.851 Angstrom, Rappe et
  // al., J. Am. Chem. Soc. 114, 10024 (1992)). cutoff in Bohr.
  static UffLennardJones carbonDefaults(double cutoff = kDefaultCutoffBohr);
  static constexpr double kDefaultCutoffBohr = 25.0;

  double cutoff() const override { return cutoff_; }
  void evaluate(double r, double& value, double& derivative) const override;

  double epsilon() const { return eps_; }
  double r0() const { return r0_; }
  double switchRadius() const { return rs_; }
  double u0() const { return u0_; }
  double u5() const { return u5_; }
  double u10() const { return u10_; }

 private:
  double eps_, r0_, cutoff_, rs_;
  double u0_, u5_, u10_;
};

}  // namespace mesochain::dftb
