// Derivatives of E = 1/2 sum_ij w_ij Phi_ij against central finite differences: positions
// (including a site on the axis), translation T and twist gamma, both kernels.
#include <gtest/gtest.h>

#include <cmath>

#include "cells.hpp"
#include "ewald/helical_lattice_sum.hpp"

using namespace mesochain;
using ewald::HelicalLatticeSum;
using ewald::Kernel;
using objective::ObjectiveCell;
using objective::Symmetry;

namespace {

Eigen::MatrixXd weightsFor(Kernel k) {
  const Eigen::VectorXd q = ewaldtest::sampleCharges();
  if (k == Kernel::Coulomb) return q * q.transpose();
  Eigen::MatrixXd c6(4, 4);  // symmetric, dispersion-like positive coefficients
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) c6(i, j) = 10.0 + 3.0 * (i + j) + (i == j ? 2.0 : 0.0);
  return c6;
}

double energy(const HelicalLatticeSum& s, const ObjectiveCell& c, const Eigen::MatrixXd& w) {
  return 0.5 * (w.cwiseProduct(s.matrix(c))).sum();
}

void checkGradients(Kernel k, const Symmetry& sym) {
  ewald::LatticeSumSettings st;
  st.tolerance = 1e-13;
  st.splitting = 0.45;  // fixed: the finite differences must not change the truncations' alpha
  const HelicalLatticeSum sum(k, st);
  const ObjectiveCell cell = ewaldtest::sampleCell(sym);
  const Eigen::MatrixXd w = weightsFor(k);
  const auto d = sum.derivatives(cell, w);
  EXPECT_NEAR(d.energy, energy(sum, cell, w), 1e-11 * std::abs(d.energy));
  const double h = 1e-4;
  double scale = d.gradient.cwiseAbs().maxCoeff();
  for (int i = 0; i < cell.atomCount(); ++i)
    for (int a = 0; a < 3; ++a) {
      ObjectiveCell p = cell, m = cell;
      p.positions(a, i) += h;
      m.positions(a, i) -= h;
      const double fd = (energy(sum, p, w) - energy(sum, m, w)) / (2 * h);
      EXPECT_NEAR(d.gradient(a, i), fd, 1e-7 * scale) << "atom " << i << " axis " << a;
    }
  ObjectiveCell tp = cell, tm = cell;
  tp.symmetry = sym.withTranslation(sym.translation() + h);
  tm.symmetry = sym.withTranslation(sym.translation() - h);
  const double fdT = (energy(sum, tp, w) - energy(sum, tm, w)) / (2 * h);
  EXPECT_NEAR(d.dTranslation, fdT, 1e-7 * std::max(scale, std::abs(fdT)));
  ObjectiveCell gp = cell, gm = cell;
  gp.symmetry = sym.withTwist(sym.twist() + h);
  gm.symmetry = sym.withTwist(sym.twist() - h);
  const double fdG = (energy(sum, gp, w) - energy(sum, gm, w)) / (2 * h);
  EXPECT_NEAR(d.dTwist, fdG, 1e-7 * std::max(scale, std::abs(fdG)));
}

}  // namespace

TEST(EwaldGradients, CoulombScrewMatchesFiniteDifferences) {
  checkGradients(Kernel::Coulomb, Symmetry::screw(5.3, 0.7, 1));  // one site on the axis
  checkGradients(Kernel::Coulomb, Symmetry::screw(4.1, 0.31, 3));
}

TEST(EwaldGradients, CoulombZeroTwistMatchesFiniteDifferences) {
  checkGradients(Kernel::Coulomb, Symmetry::screw(6.0, 0.0, 1));
}

TEST(EwaldGradients, InverseSixthMatchesFiniteDifferences) {
  checkGradients(Kernel::InverseSixth, Symmetry::screw(5.3, 0.7, 1));
  checkGradients(Kernel::InverseSixth, Symmetry::screw(4.1, 0.31, 3));
}

TEST(EwaldGradients, RingMatchesFiniteDifferences) {
  ewald::LatticeSumSettings st;
  const HelicalLatticeSum sum(Kernel::Coulomb, st);
  const ObjectiveCell cell = ewaldtest::sampleCell(Symmetry::ring(5));
  const Eigen::VectorXd q = ewaldtest::sampleCharges();
  const Eigen::MatrixXd w = q * q.transpose();
  const auto d = sum.derivatives(cell, w);
  const double h = 1e-5;
  for (int i = 0; i < cell.atomCount(); ++i)
    for (int a = 0; a < 3; ++a) {
      ObjectiveCell p = cell, m = cell;
      p.positions(a, i) += h;
      m.positions(a, i) -= h;
      const double fd = (energy(sum, p, w) - energy(sum, m, w)) / (2 * h);
      EXPECT_NEAR(d.gradient(a, i), fd, 1e-8);
    }
}
