// Symmetry equivalences of the helical lattice sums: splitting independence, the C_Na subgroup
// against explicit rotated copies, a commensurate helix against its translational supercell,
// continuity at gamma = 0, and rings summed directly.
#include <gtest/gtest.h>

#include <cmath>

#include "cells.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "direct_sums.hpp"
#include "ewald/helical_lattice_sum.hpp"

using namespace mesochain;
using ewald::HelicalLatticeSum;
using ewald::Kernel;
using ewald::LatticeSumSettings;
using objective::GroupElement;
using objective::ObjectiveCell;
using objective::Symmetry;

using ewaldtest::phi;

namespace {

double scaleOf(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

}  // namespace

TEST(EwaldEquivalence, MatrixIndependentOfSplittingParameter) {
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    const auto cell = ewaldtest::sampleCell(Symmetry::screw(5.3, 0.7, 2));
    const Eigen::MatrixXd a = phi(k, cell, 1e-12, 0.25);
    const Eigen::MatrixXd b = phi(k, cell, 1e-12, 0.6);
    const Eigen::MatrixXd c = phi(k, cell, 1e-12, 1.4);
    const double s = scaleOf(a);
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-10 * s);
    EXPECT_LT((a - c).cwiseAbs().maxCoeff(), 1e-10 * s);
  }
}

TEST(EwaldEquivalence, RotationSubgroupEqualsExplicitCopies) {
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    const int na = 4;
    const auto cell = ewaldtest::sampleCell(Symmetry::screw(4.7, 0.45, na));
    std::vector<GroupElement> gs;
    for (int c = 0; c < na; ++c) gs.push_back({0, c});
    const auto big = ewaldtest::expanded(cell, gs, Symmetry::screw(4.7, 0.45, 1));
    const Eigen::MatrixXd small = phi(k, cell);
    const Eigen::MatrixXd ref = ewaldtest::folded(phi(k, big), cell.atomCount(), na);
    EXPECT_LT((small - ref).cwiseAbs().maxCoeff(), 1e-10 * scaleOf(small));
  }
}

TEST(EwaldEquivalence, CommensurateHelixEqualsTranslationalSupercell) {
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    // gamma * 5 = 2 pi * 2: five screw steps are a pure translation by 5 T.
    const double T = 3.2, gamma = 2 * units::kPi * 2 / 5;
    const auto cell = ewaldtest::sampleCell(Symmetry::screw(T, gamma, 1));
    std::vector<GroupElement> gs;
    for (long z = 0; z < 5; ++z) gs.push_back({z, 0});
    const auto big = ewaldtest::expanded(cell, gs, Symmetry::screw(5 * T, 0.0, 1));
    const Eigen::MatrixXd small = phi(k, cell);
    const Eigen::MatrixXd ref = ewaldtest::folded(phi(k, big), cell.atomCount(), 5);
    EXPECT_LT((small - ref).cwiseAbs().maxCoeff(), 1e-10 * scaleOf(small));
  }
}

TEST(EwaldEquivalence, ContinuousAtZeroTwist) {
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    const Eigen::MatrixXd a = phi(k, ewaldtest::sampleCell(Symmetry::screw(5.0, 0.0, 1)));
    const Eigen::MatrixXd b = phi(k, ewaldtest::sampleCell(Symmetry::screw(5.0, 1e-9, 1)));
    const Eigen::MatrixXd c = phi(k, ewaldtest::sampleCell(Symmetry::screw(5.0, -1e-9, 1)));
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-10 * scaleOf(a));
    EXPECT_LT((a - c).cwiseAbs().maxCoeff(), 1e-10 * scaleOf(a));
  }
}

TEST(EwaldEquivalence, RingIsTheFiniteClusterSum) {
  // A ring of N_a copies: E per cell equals the cluster energy of all copies divided by N_a.
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    const int na = 7;
    const auto cell = ewaldtest::sampleCell(Symmetry::ring(na));
    Eigen::VectorXd q = ewaldtest::sampleCharges();
    q(0) += 0.3;  // rings need no neutrality
    double cluster = 0;
    for (int a = 0; a < na; ++a)
      for (int b = 0; b < na; ++b)
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            if (a == b && i == j) continue;
            const Eigen::Vector3d xa = cell.symmetry.apply({0, a}, cell.positions.col(i));
            const Eigen::Vector3d xb = cell.symmetry.apply({0, b}, cell.positions.col(j));
            const double r = (xa - xb).norm();
            cluster += 0.5 * q(i) * q(j) * (k == Kernel::Coulomb ? 1 / r : std::pow(r, -6));
          }
    const double e = HelicalLatticeSum(k, {}).energy(cell, q);
    EXPECT_NEAR(e, cluster / na, 1e-12 * std::abs(cluster));
  }
}

TEST(EwaldErrors, NonNeutralCoulombCellIsAnInputError) {
  const auto cell = ewaldtest::sampleCell(Symmetry::screw(5.0, 0.3, 1));
  Eigen::VectorXd q = ewaldtest::sampleCharges();
  q(1) += 0.1;
  HelicalLatticeSum sum(Kernel::Coulomb, {});
  EXPECT_THROW(sum.energy(cell, q), InputError);
  EXPECT_THROW(sum.derivatives(cell, q * q.transpose()), InputError);
  try {
    sum.energy(cell, q);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("neutral"), std::string::npos) << e.what();
  }
}

TEST(EwaldErrors, ToleranceBeyondDoublePrecisionIsAnInputError) {
  LatticeSumSettings st;
  st.tolerance = 1e-15;
  EXPECT_THROW(HelicalLatticeSum(Kernel::Coulomb, st), InputError);
  st.tolerance = 1e-10;
  st.splitting = -1.0;
  const auto cell = ewaldtest::sampleCell(Symmetry::screw(5.0, 0.3, 1));
  EXPECT_THROW(HelicalLatticeSum(Kernel::Coulomb, st).matrix(cell), InputError);
}
