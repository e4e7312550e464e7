#pragma once
// One bound state of the radial Schrödinger equation
//   −½ u'' + [ l(l+1)/(2r²) + v(r) ] u = ε u,   u(0) = 0, u(r_max) = 0,
// on a logarithmic grid. With r = e^x and u = r^{1/2} φ the equation becomes
//   φ''(x) = [ (l+½)² + 2 r² (v − ε) ] φ(x),
// which is integrated with Numerov's method (O(h⁴)): outward from r_min (φ ~ r^{l+½}(1 − Z r/(l+1)))
// to the outermost classical turning point, inward from r_max (φ = 0); the eigenvalue with
// n − l − 1 nodes is bracketed by the node count of the outward solution and the sign of the
// derivative mismatch, and found by bisection refined with the Illinois false-position rule. The
// result is the exact eigenvalue of the Numerov discretisation.
#include <vector>

#include "skgen/radial_grid.hpp"

namespace mesochain::skgen {

struct RadialState {
  double energy = 0.0;
  std::vector<double> u;  // u(r) = r R(r), normalised: ∫ u² dr = 1, positive at small r
};

// v: the full potential on the grid (nuclear + screening + confinement), excluding the
// centrifugal term; z: nuclear charge for the r → 0 start; guess: an eigenvalue estimate (NaN for
// none). Throws NumericalError when no state with the requested node count is found.
RadialState solveRadial(const LogGrid& grid, const std::vector<double>& v, double z, int n,
                        int l, double guess);

}  // namespace mesochain::skgen
