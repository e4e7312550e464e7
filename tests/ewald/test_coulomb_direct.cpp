// Helical Ewald sum for 1/r against brute-force sums over the screw (windowed, extrapolated).
#include <gtest/gtest.h>

#include <cmath>

#include "cells.hpp"
#include "direct_sums.hpp"
#include "ewald/helical_lattice_sum.hpp"

using namespace mesochain;
using ewald::HelicalLatticeSum;
using ewald::Kernel;
using ewald::LatticeSumSettings;

namespace {

double ewaldEnergy(const objective::ObjectiveCell& cell, const Eigen::VectorXd& q, double tol,
                   std::optional<double> alpha = std::nullopt) {
  LatticeSumSettings st;
  st.tolerance = tol;
  st.splitting = alpha;
  return HelicalLatticeSum(Kernel::Coulomb, st).energy(cell, q);
}

void expectMatchesDirect(const objective::Symmetry& s) {
  const auto cell = ewaldtest::sampleCell(s);
  const Eigen::VectorXd q = ewaldtest::sampleCharges();
  const double reference = ewaldtest::extrapolatedCoulombEnergy(cell, q, 200);
  const double e = ewaldEnergy(cell, q, 1e-12);
  EXPECT_NEAR(e, reference, 1e-10 * std::abs(reference)) << "reference " << reference;
}

}  // namespace

TEST(EwaldCoulomb, ScrewMatchesExtrapolatedDirectSum) {
  expectMatchesDirect(objective::Symmetry::screw(5.3, 0.7, 1));
}

TEST(EwaldCoulomb, ScrewWithRotationSubgroupMatchesDirectSum) {
  expectMatchesDirect(objective::Symmetry::screw(4.1, 0.31, 3));
}

TEST(EwaldCoulomb, PlainOneDimensionalLimitMatchesDirectSum) {
  expectMatchesDirect(objective::Symmetry::screw(6.0, 0.0, 1));
}

TEST(EwaldCoulomb, ExtrapolatedReferenceIsConverged) {
  // The reference itself: two window lengths agree far below the 1e-10 asked of the Ewald sum.
  const auto cell = ewaldtest::sampleCell(objective::Symmetry::screw(5.3, 0.7, 1));
  const Eigen::VectorXd q = ewaldtest::sampleCharges();
  const double a = ewaldtest::extrapolatedCoulombEnergy(cell, q, 200);
  const double b = ewaldtest::extrapolatedCoulombEnergy(cell, q, 400);
  const double plain = 0.5 * q.dot(ewaldtest::windowedSum(cell, 1, 200, false) * q);
  std::printf("extrapolated %.15g %.15g plain N=200 %.15g\n", a, b, plain);
  EXPECT_NEAR(a, b, 1e-12 * std::abs(a));
  EXPECT_GT(std::abs(plain - a), 1e-8 * std::abs(a));  // the plain sum is not good enough
}
