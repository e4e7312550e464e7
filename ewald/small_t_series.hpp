#pragma once
// The small-t part t in [0, t_c] of the Ewald splitting integral F_lk (docs/ewald.md, eqs.
// (E18)-(E20)), in closed form: B_l(t) = e^{-ta} I_l(tb) (a = rho_i^2 + rho_j^2,
// b = 2 rho_i rho_j) is an entire function of t, and with t_c (a + b) <= 1 its Taylor series
// converges fast without cancellation; each power t^n against omega(t) e^{-q^2/(4t)} dt/t
// integrates to t_c^(n+beta) E_{n+beta+1}(q^2 / (4 t_c)). Internal to ewald/.
#include <array>

#include "ewald/helical_lattice_sum.hpp"

namespace mesochain::ewald::detail {

// Integrals over t in [0, t_c] of omega(t) dt/t times B_l E_lk (f) and the radial, angular and q
// derivative integrands of eq. (E17) (same meaning as the quadrature accumulators).
struct SmallTIntegrals {
  double f = 0, fRhoI = 0, fRhoJ = 0, lOverRhoI = 0, lOverRhoJ = 0, fQ = 0;
};

class SmallTSeries {
 public:
  static constexpr int kMaxTerms = 24;  // Taylor terms n = 0..kMaxTerms-1 at most

  // tc (a + b) must be <= 1 (checked: NumericalError otherwise).
  SmallTSeries(Kernel kernel, double tc, double rhoI, double rhoJ);

  double cutoff() const { return tc_; }
  // Highest power kept; orders l > maxPower() vanish to below 1e-18 of B_0 on [0, t_c] (their
  // derivatives from order maxPower() + 1 on).
  int maxPower() const { return terms_ - 1; }
  // An upper bound of |F_lk| over all q on [0, t_c] without the q-dependence: c t_c^beta
  // times a closed-form bound of sum_n |P_n^(l)| (the q-dependent factor E_{n+beta+1}(x) <=
  // e^{-x} / max(l + beta, 1) for x >= 1 is applied by the caller).
  double magnitude(int l) const;
  // The same bound for the derivative integrands of order l (eq. (E17)), times a length
  // max(rho_i, rho_j) t_c: on the axis B_1 vanishes but its radial derivative does not.
  double derivativeMagnitude(int l) const;
  // F_lk on [0, t_c] for order l and wave number q. regularised: the Coulomb l = 0, q = 0 term,
  // with B_0 - 1 in place of B_0 (eq. (E14)).
  SmallTIntegrals integrals(int l, double q, bool regularised, bool withDerivatives);

 private:
  // Scaled Taylor coefficients P_n^(l) = p_n^(l) t_c^n of B_l(t) = sum_n p_n^(l) t^n (orders
  // l >= 0; I_{-l} = I_l), computed on first use.
  const std::array<double, kMaxTerms>& coefficients(int l);
  double coefficientBound(int l) const;  // >= sum_n |P_n^(l)|

  Kernel kernel_;
  double tc_, rhoI_, rhoJ_, beta_, prefactor_;
  int terms_ = 1;
  std::array<double, kMaxTerms> expSeries_{};  // (-a t_c)^m / m!
  double expAbsSum_ = 0;                        // sum_m |(-a t_c)^m / m!|
  std::array<std::array<double, kMaxTerms>, kMaxTerms + 2> p_{};  // orders 0..kMaxTerms+1
  std::array<bool, kMaxTerms + 2> have_{};
  std::array<double, kMaxTerms> zeros_{};
};

}  // namespace mesochain::ewald::detail
