#pragma once
// Helical k-points: Bloch functions of the objective group carry a helical wave number kappa
// (phase per screw step, kappa in (-pi, pi]) and an angular quantum number mu = 0..N_a-1
// (phase 2*pi*mu/N_a per elementary rotation). The phase of group element g(zeta, c) is
//   theta_g = kappa*zeta + 2*pi*mu*c/N_a.
// kappa lies on a midpoint grid of N_kappa points; time reversal pairs (kappa, mu) with
// (-kappa, -mu) and their Hamiltonians are complex conjugates, so only kappa >= 0 is kept
// (kappa = 0 once, kappa > 0 with weight doubled). Weights sum to 1: energies are per cell.
//
// A closed ring has no kappa; mu runs over 0..N_a-1 (exact) or over a sampled subset.
#include <string>
#include <vector>

#include "objective/core/symmetry.hpp"

namespace mesochain::objective {

struct HelicalKPoint {
  double kappa = 0.0;  // rad per screw step
  int mu = 0;          // angular quantum number, 0..N_a-1
  double weight = 0.0; // sums to 1 over the reduced grid
  // True when every Bloch phase exp(i theta_g) of this point is real (+-1): the Hamiltonian is
  // then real symmetric.
  bool realPhases = false;
  // Position of mu in the angular set (0..angularCount()-1); with sampled mu, the points of even
  // and of odd index form two interleaved half grids whose disagreement estimates the error.
  int angularIndex = 0;
};

struct AngularSampling {
  // 0 = all N_a quantum numbers (exact); M > 0 = M evenly spread samples of mu.
  int samples = 0;
};

class HelicalKGrid {
 public:
  HelicalKGrid() = default;
  // nKappa >= 1 points on the midpoint grid for a screw; ignored (must be 1) for a ring.
  HelicalKGrid(const Symmetry& symmetry, int nKappa, AngularSampling angular = {});

  const std::vector<HelicalKPoint>& points() const { return points_; }
  int kappaCount() const { return nKappa_; }
  int angularCount() const { return nMu_; }
  // True when mu is sampled rather than summed exactly over 0..N_a-1.
  bool angularSampled() const { return sampled_; }
  // Phase angle theta_g for point k and group element g.
  double phase(const HelicalKPoint& k, const GroupElement& g) const;

 private:
  int rotationOrder_ = 1;
  int nKappa_ = 1;
  int nMu_ = 1;
  bool sampled_ = false;
  std::vector<HelicalKPoint> points_;
};

}  // namespace mesochain::objective
