#include "dftb/repulsive.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "dftb/pair_potential_term.hpp"
#include "dftb/term_registry.hpp"

namespace mesochain::dftb {

SplineRepulsive::SplineRepulsive(SplineRepulsiveData data) : data_(std::move(data)) {}

void SplineRepulsive::evaluate(double r, double& value, double& derivative) const {
  value = 0.0;
  derivative = 0.0;
  const auto& d = data_;
  if (d.start.empty() || r >= d.cutoff()) return;
  if (r < d.start.front()) {
    // Exponential head exp(-a1 r + a2) + a3.
    const double e = std::exp(-d.expHead[0] * r + d.expHead[1]);
    value = e + d.expHead[2];
    derivative = -d.expHead[0] * e;
    return;
  }
  // Last interval whose start is <= r.
  const auto it = std::upper_bound(d.start.begin(), d.start.end(), r);
  const std::size_t i = static_cast<std::size_t>(it - d.start.begin()) - 1;
  const double x = r - d.start[i];
  const std::array<double, 6>& c = d.coeffs[i];
  // Horner for sum c_k x^k and its derivative (c4 = c5 = 0 for the cubic intervals).
  double v = c[5];
  double dv = 0.0;
  for (int k = 4; k >= 0; --k) {
    dv = dv * x + v;
    v = v * x + c[static_cast<std::size_t>(k)];
  }
  value = v;
  derivative = dv;
}

void PolynomialRepulsive::evaluate(double r, double& value, double& derivative) const {
  value = 0.0;
  derivative = 0.0;
  if (r >= data_.cutoff) return;
  // V = sum_{i=2..9} c_i x^i with x = rcut - r; dV/dr = -dV/dx.
  const double x = data_.cutoff - r;
  double p = 0.0;   // sum c_i x^(i-2)
  double dp = 0.0;  // d/dx of p
  for (int i = 9; i >= 2; --i) {
    dp = dp * x + p;
    p = p * x + data_.c[static_cast<std::size_t>(i - 2)];
  }
  value = p * x * x;
  derivative = -(dp * x * x + 2.0 * p * x);
}

// The repulsive term: the tables' pair potentials summed over the image pairs (always built).
namespace {
struct TableRepulsive {
  std::shared_ptr<const ParameterSet> params;
  double cutoff() const { return params->repulsiveCutoff(); }
  void operator()(int si, int sj, double r, double& v, double& dv) const {
    params->repulsive(si, sj).evaluate(r, v, dv);
  }
};
}  // namespace

MESOCHAIN_DFTB_TERM(TermRegistration{
    "repulsive", 200, "pair repulsive potentials of the Slater-Koster tables", false,
    [](const CalculatorSettings&) { return true; },
    [](const TermBuild& b) -> std::unique_ptr<EnergyTerm> {
      return std::make_unique<PairTerm<TableRepulsive>>("repulsive", TableRepulsive{b.params});
    },
    nullptr})

}  // namespace mesochain::dftb
