#pragma once
// Generalised exponential integrals E_nu(x) = int_1^inf e^{-x v} v^{-nu} dv for a run of orders
// nu = nu0, nu0 + 1, ..., the closed form of the small-t part of the Ewald splitting integral
// (docs/ewald.md, eq. (E19)).
//
// x <= 1: the power series at the lowest order >= 1 (digamma form for integer orders), then the
// recurrence E_{nu+1} = (e^{-x} - x E_nu) / nu upwards (stable: x / nu <= 1). x > 1: the
// continued fraction at the order nearest x, the recurrence downwards below it (stable for
// nu < x) and upwards above it (stable for nu > x).
#include <vector>

namespace mesochain::ewald {

// out[i] = E_{nu0 + i}(x), i = 0..count-1; nu0 >= 0, x >= 0 finite. At x = 0, E_nu(0) = 1/(nu-1)
// for nu > 1 and +inf otherwise. Throws NumericalError if the continued fraction fails.
void exponentialIntegralSequence(double nu0, double x, int count, std::vector<double>& out);

}  // namespace mesochain::ewald
