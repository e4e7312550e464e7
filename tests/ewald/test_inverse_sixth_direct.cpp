// Helical Ewald sum for 1/r^6 against direct sums over the screw (which converge like N^-5).
#include <gtest/gtest.h>

#include "cells.hpp"
#include "direct_sums.hpp"
#include "ewald/helical_lattice_sum.hpp"

using namespace mesochain;

TEST(EwaldInverseSixth, MatchesDirectSum) {
  for (const auto& s : {objective::Symmetry::screw(5.3, 0.7, 1), objective::Symmetry::screw(4.1, 0.31, 3),
                        objective::Symmetry::screw(6.0, 0.0, 1), objective::Symmetry::screw(0.9, 1.1, 2)}) {
    const auto cell = ewaldtest::sampleCell(s);
    // Tail beyond N cells: < 2 N_a N_o^2 / (5 N^5 T^6), negligible at N = 20000.
    const Eigen::MatrixXd ref = ewaldtest::windowedSum(cell, 6, 20000, false);
    ewald::LatticeSumSettings st;
    st.tolerance = 1e-12;
    const Eigen::MatrixXd m = ewald::HelicalLatticeSum(ewald::Kernel::InverseSixth, st).matrix(cell);
    for (int i = 0; i < cell.atomCount(); ++i)
      for (int j = 0; j < cell.atomCount(); ++j)
        EXPECT_NEAR(m(i, j), ref(i, j), 1e-10 * std::abs(ref(i, j))) << i << " " << j;
  }
}
