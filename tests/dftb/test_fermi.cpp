#include <cmath>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "dftb/fermi.hpp"

using namespace mesochain;
using namespace mesochain::dftb;

namespace {
double count(const Filling& f, const std::vector<double>& w) {
  double n = 0;
  for (size_t k = 0; k < w.size(); ++k) n += w[k] * f.occupations[k].sum();
  return n;
}
}  // namespace

TEST(Fermi, InsulatorFermiLevelMidGap) {
  std::vector<Eigen::VectorXd> levels{Eigen::Vector4d(-1.0, -0.5, 0.3, 0.9),
                                      Eigen::Vector4d(-0.9, -0.4, 0.2, 1.0)};
  std::vector<double> w{0.5, 0.5};
  const double kT = 1e-4;
  const Filling f = fillFermiDirac(levels, w, 4.0, kT);
  // N(mu) = N_el holds to double precision over most of the gap: the Fermi level is mid-gap.
  EXPECT_NEAR(f.fermiLevel, 0.5 * (-0.4 + 0.2), 1e-15);
  EXPECT_NEAR(count(f, w), 4.0, 1e-12);
  EXPECT_NEAR(f.highestOccupied, -0.4, 0);
  EXPECT_NEAR(f.lowestUnoccupied, 0.2, 0);
  EXPECT_NEAR(f.bandEnergy, 2 * 0.5 * (-1.0 - 0.5 - 0.9 - 0.4), 1e-12);
  EXPECT_LT(f.entropyTerm, 1e-12);
}

TEST(Fermi, DegenerateLevelsShareOccupationEqually) {
  // Three degenerate levels holding 2 electrons: each gets 2/3, at any low temperature.
  std::vector<Eigen::VectorXd> levels{Eigen::Vector4d(-1.0, 0.0, 0.0, 0.0)};
  std::vector<double> w{1.0};
  for (double kT : {1e-3, 1e-6, 1e-9}) {
    const Filling f = fillFermiDirac(levels, w, 4.0, kT);
    EXPECT_NEAR(f.occupations[0][1], 2.0 / 3.0, 1e-9);
    EXPECT_NEAR(f.occupations[0][3], 2.0 / 3.0, 1e-9);
    EXPECT_TRUE(std::isfinite(f.entropyTerm));
    // TS of three levels at occupation 1/3 per spin orbital: 2*3*kT*H(1/3).
    const double h = -(1.0 / 3 * std::log(1.0 / 3) + 2.0 / 3 * std::log(2.0 / 3));
    EXPECT_NEAR(f.entropyTerm, 6 * kT * h, 1e-9 * kT);
  }
}

TEST(Fermi, EntropyMatchesDefinition) {
  for (double x : {-30.0, -2.0, -0.1, 0.0, 0.7, 5.0, 40.0}) {
    const double f = 0.5 * fermiOccupation(x);
    const double direct = -(f * std::log(f) + (1 - f) * std::log1p(-f));
    EXPECT_NEAR(fermiEntropy(x), direct, 1e-12 * std::max(1.0, direct)) << x;
  }
  EXPECT_EQ(fermiOccupation(1e6), 0.0);
  EXPECT_EQ(fermiOccupation(-1e6), 2.0);
  EXPECT_EQ(fermiEntropy(1e6), 0.0);
  EXPECT_EQ(fermiEntropy(-1e6), 0.0);
}

TEST(Fermi, MerminFreeEnergyIsStationaryInOccupations) {
  // dF/de_n = f_n for fixed electron number (envelope theorem): check by finite differences.
  std::vector<Eigen::VectorXd> levels{Eigen::Vector3d(-0.3, -0.25, -0.2),
                                      Eigen::Vector3d(-0.28, -0.22, 0.1)};
  std::vector<double> w{0.25, 0.75};
  const double kT = 0.01, ne = 3.1;
  const Filling f0 = fillFermiDirac(levels, w, ne, kT);
  const double h = 1e-6;
  auto freeEnergy = [&](double de) {
    auto l = levels;
    l[1][1] += de;
    const Filling f = fillFermiDirac(l, w, ne, kT);
    return f.bandEnergy - f.entropyTerm;
  };
  const double fd = (freeEnergy(h) - freeEnergy(-h)) / (2 * h);
  EXPECT_NEAR(fd, w[1] * f0.occupations[1][1], 1e-8);
}

TEST(Fermi, RefusesImpossibleFilling) {
  std::vector<Eigen::VectorXd> levels{Eigen::Vector2d(-1.0, 1.0)};
  EXPECT_THROW(fillFermiDirac(levels, {1.0}, 5.0, 0.01), NumericalError);
  EXPECT_THROW(fillFermiDirac(levels, {1.0}, 2.0, 0.0), NumericalError);
}
