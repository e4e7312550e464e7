#pragma once
// Fermi-Dirac filling of the levels of all k-points with one common Fermi level, and the
// electronic entropy of the Mermin free energy (Mermin, Phys. Rev. 137, A1441 (1965)):
//   f_nk = 2 / (1 + exp((e_nk - mu)/kT)),  sum_k w_k sum_n f_nk = N_el,
//   -TS = kT sum_k w_k sum_n 2 [f ln f + (1-f) ln(1-f)]  (f per spin orbital).
#include <vector>

#include <Eigen/Dense>

namespace mesochain::dftb {

struct Filling {
  double fermiLevel = 0.0;      // Hartree
  double entropyTerm = 0.0;     // T*S in Hartree per cell (>= 0)
  double bandEnergy = 0.0;      // sum_k w_k sum_n f_nk e_nk
  double highestOccupied = 0.0; // highest level below the Fermi level (Hartree)
  double lowestUnoccupied = 0.0;// lowest level above the Fermi level (Hartree)
  std::vector<Eigen::VectorXd> occupations;  // per k-point, 0..2 per level
};

// levels[k]: the eigenvalues of k-point k (any order); weights sum to 1; kT > 0 in Hartree.
// Throws NumericalError when the electrons do not fit in the levels. When the electron count is
// met over a whole interval (a gap at low temperature), the Fermi level is its midpoint.
Filling fillFermiDirac(const std::vector<Eigen::VectorXd>& levels,
                       const std::vector<double>& weights, double electrons, double kT);

// 2 / (1 + exp(x)) and the entropy density ln(1+e^x) - (1-f) x, stable for any x.
double fermiOccupation(double x);
double fermiEntropy(double x);

}  // namespace mesochain::dftb
