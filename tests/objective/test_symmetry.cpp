#include <cmath>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/images.hpp"
#include "objective/core/kgrid.hpp"
#include "objective/core/symmetry.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using units::kPi;

TEST(Symmetry, GroupElementsCompose) {
  const Symmetry s = Symmetry::screw(2.0, 0.3, 4);
  const Eigen::Vector3d x(1.2, -0.4, 0.7);
  // S^2 C^3 applied in one step equals S applied twice after C applied three times.
  Eigen::Vector3d y = x;
  for (int k = 0; k < 3; ++k) y = s.apply({0, 1}, y);
  for (int k = 0; k < 2; ++k) y = s.apply({1, 0}, y);
  EXPECT_LT((y - s.apply({2, 3}, x)).norm(), 1e-13);
  // Rotation preserves the distance to the axis; the screw shifts z by zeta*T.
  const Eigen::Vector3d z = s.apply({-3, 2}, x);
  EXPECT_NEAR(std::hypot(z.x(), z.y()), std::hypot(x.x(), x.y()), 1e-13);
  EXPECT_NEAR(z.z(), x.z() - 6.0, 1e-13);
}

TEST(Symmetry, RingRequiresCommensurateTwist) {
  EXPECT_NO_THROW(Symmetry::fromParameters(0.0, 2 * kPi / 10 * 3, 10));
  EXPECT_THROW(Symmetry::fromParameters(0.0, 0.1, 10), InputError);
  EXPECT_THROW(Symmetry::fromParameters(1.0, 0.1, 0), InputError);
  EXPECT_THROW(Symmetry::fromParameters(-1.0, 0.1, 1), InputError);
  EXPECT_THROW(Symmetry::fromParameters(NAN, 0.1, 1), InputError);
}

TEST(ImageList, ContainsEveryPairBothWays) {
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(2.5, 0.4, 3);
  cell.addAtom("C", {3.0, 0.0, 0.0});
  cell.addAtom("C", {2.0, 1.5, 1.0});
  const ImageList list(cell, 9.0);
  // Brute force over a generous range of group elements.
  int count = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (long zeta = -20; zeta <= 20; ++zeta)
        for (int c = 0; c < 3; ++c) {
          if (i == j && zeta == 0 && c == 0) continue;
          const Eigen::Vector3d y = cell.symmetry.apply({zeta, c}, cell.positions.col(j));
          if ((y - cell.positions.col(i)).norm() < 9.0) ++count;
        }
  EXPECT_EQ(count, static_cast<int>(list.pairs().size()));
  EXPECT_GT(count, 10);
}

TEST(ImageList, RingOfThousandsEnumeratesOnlyNeighbours) {
  ObjectiveCell cell;
  const int na = 5000;
  const double radius = na * 2.5 / (2 * kPi);
  cell.symmetry = Symmetry::ring(na);
  cell.addAtom("C", {radius, 0.0, 0.0});
  const ImageList list(cell, 6.0);
  EXPECT_EQ(list.pairs().size(), 4u);  // two neighbours on each side, 2.5 Bohr apart
}

TEST(CellValidation, RejectsCloseImages) {
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(0.5, 0.0, 1);
  cell.addAtom("C", {1.0, 0.0, 0.0});
  EXPECT_THROW(cell.validate("test", 0.5 / units::kBohrInAngstrom * 1.2), InputError);
  ObjectiveCell onAxis;
  onAxis.symmetry = Symmetry::screw(3.0, 0.5, 2);
  onAxis.addAtom("C", {0.0, 0.0, 0.0});  // coincides with its own C_2 image
  EXPECT_THROW(onAxis.validate("test", 0.9), InputError);
}

TEST(HelicalKGrid, WeightsSumToOneAndReduceByTimeReversal) {
  for (int nk : {1, 2, 7, 8}) {
    const HelicalKGrid grid(Symmetry::screw(2.0, 0.3, 3), nk);
    double w = 0;
    for (const auto& p : grid.points()) {
      w += p.weight;
      EXPECT_GE(p.kappa, 0.0);
    }
    EXPECT_NEAR(w, 1.0, 1e-14);
    EXPECT_EQ(static_cast<int>(grid.points().size()), 3 * ((nk + 1) / 2));
  }
  const HelicalKGrid ring(Symmetry::ring(10), 1);
  double w = 0;
  for (const auto& p : ring.points()) w += p.weight;
  EXPECT_NEAR(w, 1.0, 1e-14);
  EXPECT_EQ(ring.points().size(), 6u);
}
