#pragma once
// The long-range 1/r part of the SCC gamma on an objective cell:
//   Phi_ij = sum_g 1/|x_i - g(x_j)|   (identity excluded for i == j),
// with E = 1/2 sum_ij q_i q_j Phi_ij per cell for a neutral cell. An interface with two
// implementations: a direct sum for closed rings (T = 0, molecules are ring(1)), and the helical
// Ewald sum of ewald/ for screw cells once it is available. makeCoulombLatticeSum() is the one
// place that chooses (the swap to the Ewald sum is a one-line change there).
#include <memory>

#include <Eigen/Dense>

#include "dftb/image_pair_sum.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::dftb {

// Energy and derivatives of a weighted lattice sum 1/2 sum_ij w_ij Phi_ij.
using LatticeSumDerivatives = ImagePairSum;

class CoulombLatticeSum {
 public:
  virtual ~CoulombLatticeSum() = default;
  virtual Eigen::MatrixXd matrix(const objective::ObjectiveCell& cell) const = 0;  // N_o x N_o
  virtual LatticeSumDerivatives derivatives(const objective::ObjectiveCell& cell,
                                            const Eigen::MatrixXd& weights) const = 0;
};

// The helical Ewald sum of ewald/ (screw cells, C_Na, and rings by direct sum) behind this
// interface; tolerance as ewald::LatticeSumSettings (relative to 1/d_min, in [1e-13, 1e-2]).
class HelicalEwaldCoulombSum : public CoulombLatticeSum {
 public:
  explicit HelicalEwaldCoulombSum(double tolerance);
  ~HelicalEwaldCoulombSum() override;
  Eigen::MatrixXd matrix(const objective::ObjectiveCell& cell) const override;
  LatticeSumDerivatives derivatives(const objective::ObjectiveCell& cell,
                                    const Eigen::MatrixXd& weights) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Direct sum over the N_a images of a closed ring; a screw cell is an InputError. An
// independent reference for the Ewald path in the tests.
class DirectRingCoulombSum : public CoulombLatticeSum {
 public:
  Eigen::MatrixXd matrix(const objective::ObjectiveCell& cell) const override;
  LatticeSumDerivatives derivatives(const objective::ObjectiveCell& cell,
                                    const Eigen::MatrixXd& weights) const override;
};

// The Coulomb sum used by SCC; tolerance: requested accuracy of the Ewald sum (screw cells).
std::unique_ptr<CoulombLatticeSum> makeCoulombLatticeSum(double tolerance);

}  // namespace mesochain::dftb
