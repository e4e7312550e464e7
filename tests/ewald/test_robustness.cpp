// Hard cells for the helical Ewald sums: thousands of rotations C_Na, a twist far below any
// resolution, atoms exactly on the screw axis, very long (sparse) and very short (dense) screw
// translations — all against direct sums or exact equivalences — and limits that throw instead
// of truncating silently.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cells.hpp"
#include "common/errors.hpp"
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

double maxRelative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& ref) {
  return (a - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff();
}

// Coulomb energy of the sample charges: Ewald at 1e-12 against the extrapolated direct sum.
void expectCoulombMatchesDirect(const ObjectiveCell& cell, long n0, double rel = 1e-10) {
  const Eigen::VectorXd q = ewaldtest::sampleCharges().head(cell.atomCount()) -
                            Eigen::VectorXd::Constant(cell.atomCount(),
                                                      ewaldtest::sampleCharges().head(cell.atomCount()).mean());
  const double reference = ewaldtest::extrapolatedCoulombEnergy(cell, q, n0);
  const double e = 0.5 * q.dot(phi(Kernel::Coulomb, cell) * q);
  EXPECT_NEAR(e, reference, rel * std::abs(reference)) << "reference " << reference;
}

// 1/r^6 matrix at 1e-12 against the plain direct sum over |zeta| <= zmax. Elements are promised
// to tol K(d_min) / N_o (the scale of the largest element), not relative to themselves: in the
// dense cell they span 8 decades.
void expectInverseSixthMatchesDirect(const ObjectiveCell& cell, long zmax) {
  const Eigen::MatrixXd ref = ewaldtest::windowedSum(cell, 6, zmax, false);
  const Eigen::MatrixXd m = phi(Kernel::InverseSixth, cell);
  EXPECT_LT(maxRelative(m, ref), 1e-10);
}

// Three sites near radius rho on a cell with N_a rotations (spacing 2 pi rho / N_a ~ 0.94 Bohr
// for rho = 300, N_a = 2000).
ObjectiveCell wideRing(int na, double rho) {
  ObjectiveCell c;
  c.symmetry = Symmetry::screw(4.0, 0.0123, na);
  const double step = 2 * M_PI / na;
  c.addAtom("C", {rho, 0.0, 0.0});
  c.addAtom("C", {(rho + 0.6) * std::cos(0.37 * step), (rho + 0.6) * std::sin(0.37 * step), 1.3});
  c.addAtom("H", {(rho - 0.8) * std::cos(0.71 * step), (rho - 0.8) * std::sin(0.71 * step), -1.1});
  return c;
}

}  // namespace

TEST(EwaldRobustness, ThousandsOfRotationsEqualHalfAsManyWithExplicitCopies) {
  // C_2000 against C_1000 carrying each site twice (rotated by 2 pi / 2000): different angular
  // orders (multiples of 2000 vs 1000) and different real-space windows, the same lattice sum.
  const ObjectiveCell cell = wideRing(2000, 300.0);
  const ObjectiveCell big = ewaldtest::expanded(cell, {GroupElement{0, 0}, GroupElement{0, 1}},
                                                Symmetry::screw(4.0, 0.0123, 1000));
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    const Eigen::MatrixXd small = phi(k, cell);
    const Eigen::MatrixXd ref = ewaldtest::folded(phi(k, big), cell.atomCount(), 2);
    EXPECT_LT(maxRelative(small, ref), 1e-10) << (k == Kernel::Coulomb ? "1/r" : "1/r^6");
  }
}

TEST(EwaldRobustness, ThousandsOfRotationsMatchDirectSum) {
  // 1/r^6: the tail beyond |zeta| = 150 (600 Bohr) is < N_a / (5 T (600)^5) ~ 1e-12 absolute.
  expectInverseSixthMatchesDirect(wideRing(2000, 300.0), 150);
  // 1/r with fewer rotations (the direct sum visits every rotation of every screw power; its
  // extrapolation needs n0 = 200 here: 100 is off by 1.4e-10).
  expectCoulombMatchesDirect(wideRing(120, 18.0), 200);
}

TEST(EwaldRobustness, TinyTwistMatchesDirectSum) {
  for (double gamma : {1e-12, 3e-8})
    for (int na : {1, 3}) {
      const auto cell = ewaldtest::sampleCell(Symmetry::screw(5.1, gamma, na));
      expectCoulombMatchesDirect(cell, 200);
      expectInverseSixthMatchesDirect(cell, 20000);
    }
}

TEST(EwaldRobustness, SitesOnTheAxisMatchDirectSumAndFiniteDifferences) {
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(4.4, 0.5, 1);
  cell.addAtom("C", {0.0, 0.0, 0.0});
  cell.addAtom("C", {0.0, 0.0, 1.7});
  cell.addAtom("H", {2.2, 0.9, 0.6});
  expectCoulombMatchesDirect(cell, 200);
  expectInverseSixthMatchesDirect(cell, 20000);
  // Gradients: moving an axis site off the axis (B_1 and its radial derivative, eq. (E17)).
  const Eigen::Vector3d q(0.5, -0.8, 0.3);
  for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
    LatticeSumSettings st;
    st.tolerance = 1e-13;
    st.splitting = 0.4;
    const HelicalLatticeSum sum(k, st);
    const Eigen::MatrixXd w = k == Kernel::Coulomb ? Eigen::MatrixXd(q * q.transpose())
                                                   : Eigen::MatrixXd::Constant(3, 3, 20.0);
    auto energy = [&](const ObjectiveCell& c) { return 0.5 * w.cwiseProduct(sum.matrix(c)).sum(); };
    const auto d = sum.derivatives(cell, w);
    const double h = 1e-4, scale = d.gradient.cwiseAbs().maxCoeff();
    for (int i = 0; i < 2; ++i)
      for (int a = 0; a < 3; ++a) {
        ObjectiveCell p = cell, m = cell;
        p.positions(a, i) += h;
        m.positions(a, i) -= h;
        EXPECT_NEAR(d.gradient(a, i), (energy(p) - energy(m)) / (2 * h), 1e-7 * scale)
            << "site " << i << " axis " << a;
      }
  }
}

TEST(EwaldRobustness, SparseAndDenseScrewsMatchDirectSum) {
  // Long T: images far apart along the axis (few real-space images, many axial wave numbers).
  for (int na : {1, 2}) {
    const auto sparse = ewaldtest::sampleCell(Symmetry::screw(150.0, 0.4, na));
    expectCoulombMatchesDirect(sparse, 200);
    expectInverseSixthMatchesDirect(sparse, 2000);
  }
  // Short T: hundreds of screw images per unit length (T far below the bond length).
  const auto dense = ewaldtest::sampleCell(Symmetry::screw(0.35, 0.9, 1));
  expectCoulombMatchesDirect(dense, 400);
  expectInverseSixthMatchesDirect(dense, 200000);
}

TEST(EwaldRobustness, LimitsThrowInsteadOfTruncating) {
  const auto cell = ewaldtest::sampleCell(Symmetry::screw(5.0, 0.3, 1));
  // A splitting parameter so small that the real-space sum would need > 5e7 images per pair.
  try {
    phi(Kernel::Coulomb, cell, 1e-10, 1e-8);
    ADD_FAILURE() << "no error for 1e-8 / Bohr";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("real-space images"), std::string::npos) << e.what();
  }
  // A radius so large for the given splitting parameter that the angular orders exceed the limit.
  ObjectiveCell wide;
  wide.symmetry = Symmetry::screw(5.0, 0.3, 1);
  wide.addAtom("C", {4e4, 0.0, 0.0});
  wide.addAtom("C", {-4e4, 1.0, 0.0});
  try {
    phi(Kernel::InverseSixth, wide, 1e-10, 3.0);
    ADD_FAILURE() << "no error for radius 4e4 Bohr at alpha = 3";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("angular orders"), std::string::npos) << e.what();
  }
}

TEST(EwaldRobustness, RandomCellsMeetTheRequestedTolerance) {
  // 200 random cells (T 0.3..200 Bohr, N_a in {1, 2, 5, 12, 100}, sites at random radii, some on
  // the axis, some with |gamma| ~ 1e-9) against the same sum at 1e-13 with a different
  // splitting parameter. Energies must meet the tolerance; matrix elements their budget
  // tol K(d_min) / N_o, or for very dense Coulomb cells (elements ~ 2 N_a / T ln rho ~ 1e3)
  // the double-precision floor of the largest element.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const int orders[] = {1, 2, 5, 12, 100};
  for (int trial = 0; trial < 200; ++trial) {
    const int na = orders[trial % 5];
    const double T = std::exp(std::log(0.3) + u(rng) * std::log(200 / 0.3));
    const double gamma = (u(rng) - 0.5) * 6.3 * (trial % 7 == 0 ? 1e-9 : 1);
    ObjectiveCell c;
    c.symmetry = Symmetry::screw(T, gamma, na);
    const double rmax = na >= 12 ? 15 + na * 0.15 : 8;
    for (int i = 0; i < 4; ++i) {
      const double r = (i == 0 && na == 1 && trial % 3 == 0) ? 0.0 : 0.5 + u(rng) * rmax;
      const double p = u(rng) * 2 * M_PI;
      c.addAtom("C", {r * std::cos(p), r * std::sin(p), u(rng) * T});
    }
    const Eigen::VectorXd q = ewaldtest::sampleCharges();
    for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
      const bool coulomb = k == Kernel::Coulomb;
      const auto plan = HelicalLatticeSum(k, {1e-13, {}}).plan(c);
      const Eigen::MatrixXd ref = phi(k, c, 1e-13, 1.7 * plan.splitting);
      const Eigen::VectorXd w = coulomb ? q : Eigen::VectorXd(q.cwiseAbs());
      const double eRef = 0.5 * w.dot(ref * w);
      const double kMin = coulomb ? 1 / plan.shortestDistance : std::pow(plan.shortestDistance, -6);
      for (double tol : {1e-4, 1e-8, 1e-12}) {
        const Eigen::MatrixXd m = phi(k, c, tol);
        const std::string where = "trial " + std::to_string(trial) + " N_a " + std::to_string(na) +
                                  " T " + std::to_string(T) + " tol " + std::to_string(tol);
        EXPECT_LT(std::abs(0.5 * w.dot(m * w) - eRef), tol * std::abs(eRef)) << where;
        const double budget = std::max(tol * kMin / 4, 4e-15 * ref.cwiseAbs().maxCoeff());
        EXPECT_LT((m - ref).cwiseAbs().maxCoeff(), budget) << where;
      }
    }
  }
}
