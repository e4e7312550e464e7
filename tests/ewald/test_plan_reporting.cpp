// matrix() and derivatives() report the plan they truncated by (optional `used` argument): the
// same as a separate plan(cell), while the sums themselves are unchanged by asking for it.
#include <gtest/gtest.h>

#include <string>

#include "cells.hpp"
#include "ewald/helical_lattice_sum.hpp"

using namespace mesochain;
using ewald::HelicalLatticeSum;
using ewald::Kernel;
using ewald::LatticeSumPlan;
using ewald::LatticeSumSettings;
using objective::Symmetry;

namespace {

void expectSamePlan(const LatticeSumPlan& a, const LatticeSumPlan& b, const std::string& where) {
  EXPECT_EQ(a.splitting, b.splitting) << where;
  EXPECT_EQ(a.realSpaceCutoff, b.realSpaceCutoff) << where;
  EXPECT_EQ(a.elementTolerance, b.elementTolerance) << where;
  EXPECT_EQ(a.shortestDistance, b.shortestDistance) << where;
  EXPECT_EQ(a.maxAngularOrder, b.maxAngularOrder) << where;
  EXPECT_EQ(a.reciprocalTerms, b.reciprocalTerms) << where;
  EXPECT_EQ(a.quadratureNodes, b.quadratureNodes) << where;
}

}  // namespace

TEST(LatticeSumPlanReporting, MatrixAndDerivativesReportThePlanOfPlan) {
  const Symmetry symmetries[] = {Symmetry::screw(4.6, 0.52, 5), Symmetry::screw(9.0, 0.0, 1),
                                 Symmetry::ring(40)};
  int index = 0;
  for (const Symmetry& s : symmetries) {
    const auto cell = ewaldtest::sampleCell(s);
    const int n = cell.atomCount();
    for (Kernel k : {Kernel::Coulomb, Kernel::InverseSixth}) {
      for (double tol : {1e-6, 1e-10}) {
        const std::string where = "cell " + std::to_string(index) + " kernel " +
                                  std::to_string(static_cast<int>(k)) + " tol " + std::to_string(tol);
        LatticeSumSettings st;
        st.tolerance = tol;
        const HelicalLatticeSum sum(k, st);
        const LatticeSumPlan expected = sum.plan(cell);
        if (!s.isRing()) {
          // Not an empty plan: the comparison below could fail.
          EXPECT_GT(expected.splitting, 0) << where;
          EXPECT_GT(expected.reciprocalTerms, 0) << where;
        }
        LatticeSumPlan fromMatrix;
        const Eigen::MatrixXd m = sum.matrix(cell, &fromMatrix);
        expectSamePlan(fromMatrix, expected, where + " matrix");
        EXPECT_EQ((m - sum.matrix(cell)).cwiseAbs().maxCoeff(), 0.0) << where;

        // Neutral weights q q^T (Coulomb needs them), |q| |q|^T for r^-6.
        Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(n, -0.3, 0.5);
        q.array() -= q.mean();
        const Eigen::MatrixXd w = k == Kernel::Coulomb ? Eigen::MatrixXd(q * q.transpose())
                                                       : Eigen::MatrixXd(q.cwiseAbs() * q.cwiseAbs().transpose());
        LatticeSumPlan fromDerivatives;
        const auto d = sum.derivatives(cell, w, &fromDerivatives);
        expectSamePlan(fromDerivatives, expected, where + " derivatives");
        const auto plain = sum.derivatives(cell, w);
        EXPECT_EQ(d.energy, plain.energy) << where;
        EXPECT_EQ((d.gradient - plain.gradient).cwiseAbs().maxCoeff(), 0.0) << where;
        EXPECT_EQ(d.dTranslation, plain.dTranslation) << where;
        EXPECT_EQ(d.dTwist, plain.dTwist) << where;
      }
    }
    ++index;
  }
}
