// ParameterSet::load: species data, pairs, cutoffs and errors.
#include <cmath>

#include <gtest/gtest.h>

#include "dftb/parameters.hpp"
#include "skf_test_util.hpp"

using namespace mesochain::dftb;
using namespace skftest;

namespace {

std::map<std::string, std::string> pbcFiles(const std::vector<std::string>& species) {
  std::map<std::string, std::string> f;
  for (const auto& a : species) {
    for (const auto& b : species) f[a + "-" + b] = pbc(a + "-" + b + ".skf");
  }
  return f;
}

}  // namespace

TEST(ParameterSet, CarbonOnly) {
  const ParameterSet p = ParameterSet::load({"C"}, pbcFiles({"C"}), "test");
  ASSERT_EQ(p.speciesCount(), 1);
  const SpeciesData& c = p.species(0);
  EXPECT_EQ(c.name, "C");
  EXPECT_EQ(c.maxAngularMomentum, 1);
  EXPECT_EQ(c.orbitalCount, 4);
  EXPECT_EQ(c.onsiteS, -0.50489172);
  EXPECT_EQ(c.onsiteP, -0.19435511);
  EXPECT_EQ(c.hubbardU, 0.364302);
  EXPECT_EQ(c.valenceElectrons, 4.0);
  EXPECT_EQ(c.mass, 12.01);
  EXPECT_NEAR(p.integralCutoff(), 519 * 0.02 + 1.0, 1e-12);
  EXPECT_EQ(p.repulsiveCutoff(), 3.83847);
  double v = 0, d = 0;
  p.repulsive(0, 0).evaluate(1.0, v, d);
  EXPECT_NEAR(v, 13.0459761, 1e-12);  // spline (first interval), not the polynomial
}

TEST(ParameterSet, CarbonAndHydrogen) {
  const ParameterSet p = ParameterSet::load({"C", "H"}, pbcFiles({"C", "H"}), "test");
  ASSERT_EQ(p.speciesCount(), 2);
  const SpeciesData& h = p.species(1);
  EXPECT_EQ(h.maxAngularMomentum, 0);
  EXPECT_EQ(h.orbitalCount, 1);
  EXPECT_EQ(h.valenceElectrons, 1.0);
  EXPECT_EQ(h.onsiteS, -0.23860040);
  EXPECT_EQ(h.hubbardU, 0.4195);
  EXPECT_EQ(h.mass, 1.008);
  // C-C and C-H tables end at 10.38 Bohr, H-H (500 declared) at 9.98.
  EXPECT_NEAR(p.integralCutoff(), 11.38, 1e-12);
  EXPECT_NEAR(p.integrals(1, 1).cutoff(), 10.98, 1e-12);
  EXPECT_EQ(p.repulsiveCutoff(), 3.83847);
  EXPECT_EQ(p.repulsive(0, 1).cutoff(), 3.39);
  EXPECT_EQ(p.repulsive(1, 1).cutoff(), 2.08);
  // (C, H) at d and (H, C) at -d are transposes; the C-H block has only its s column.
  const Eigen::Vector3d dvec(1.1, -0.9, 1.3);
  OrbitalBlock hch, sch, hhc, shc;
  p.integrals(0, 1).blocks(dvec, hch, sch);
  p.integrals(1, 0).blocks(-dvec, hhc, shc);
  EXPECT_LT((sch - shc.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((hch - hhc.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_GT(sch.col(0).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_EQ(sch.rightCols<3>().cwiseAbs().maxCoeff(), 0.0);
}

TEST(ParameterSet, MissingPairNamesThePair) {
  auto files = pbcFiles({"C", "H"});
  files.erase("H-C");
  const std::string msg = inputErrorOf([&] { ParameterSet::load({"C", "H"}, files, "cell.toml"); });
  EXPECT_NE(msg.find("H-C"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cell.toml"), std::string::npos) << msg;
}

TEST(ParameterSet, MissingFileNamesTheFile) {
  auto files = pbcFiles({"C"});
  files["C-C"] = "/nonexistent/C-C.skf";
  const std::string msg = inputErrorOf([&] { ParameterSet::load({"C"}, files, "cell.toml"); });
  EXPECT_NE(msg.find("/nonexistent/C-C.skf"), std::string::npos) << msg;
}

TEST(ParameterSet, DShellsAreRefused) {
  const auto dir = scratchDir();
  // Synthetic homonuclear table of a species with one d electron (fd = 1).
  const std::string path = writeFile(
      dir, "X-X.skf",
      syntheticTable(true, 20, "-0.1 -0.2 -0.5 0.0 0.3 0.3 0.3 1.0 2.0 2.0",
                     [](int i, int c) { return std::exp(-0.1 * i) * (c + 1) * 0.01; }));
  const std::string msg =
      inputErrorOf([&] { ParameterSet::load({"X"}, {{"X-X", path}}, "test"); });
  EXPECT_NE(msg.find("d shells not supported yet"), std::string::npos) << msg;
  // The same table without the d electron loads, and so does carbon; an override of 2 does not.
  const std::string ok = writeFile(
      dir, "Y-Y.skf",
      syntheticTable(true, 20, "-0.1 -0.2 -0.5 0.0 0.3 0.3 0.3 0.0 2.0 2.0",
                     [](int i, int c) { return std::exp(-0.1 * i) * (c + 1) * 0.01; }));
  EXPECT_EQ(ParameterSet::load({"Y"}, {{"Y-Y", ok}}, "test").species(0).orbitalCount, 4);
  const std::string msg2 =
      inputErrorOf([&] { ParameterSet::load({"C"}, pbcFiles({"C"}), "test", {{"C", 2}}); });
  EXPECT_NE(msg2.find("d shells not supported yet"), std::string::npos) << msg2;
}

TEST(ParameterSet, AngularMomentumOverride) {
  const ParameterSet p = ParameterSet::load({"C"}, pbcFiles({"C"}), "test", {{"C", 0}});
  EXPECT_EQ(p.species(0).orbitalCount, 1);
  EXPECT_EQ(p.species(0).valenceElectrons, 2.0);  // as DFTB+: only the shells in use count
  OrbitalBlock h, s;
  p.integrals(0, 0).blocks(Eigen::Vector3d(0, 0, 2.7), h, s);
  EXPECT_EQ(h.bottomRows<3>().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(ParameterSet::load({"C"}, pbcFiles({"C"}), "test", {{"N", 1}}),
               mesochain::InputError);
}

TEST(ParameterSet, PolynomialRepulsiveOnRequestAndMissingSpline) {
  const ParameterSet p = ParameterSet::load({"C"}, pbcFiles({"C"}), "test", {}, {"C-C"});
  double v = 0, d = 0;
  p.repulsive(0, 0).evaluate(2.5, v, d);
  const double c[8] = {0.0180339, 0.0947251, -0.128899, -0.116864, 0.301533, -0.172412, 0.032959, 0};
  double want = 0;
  for (int i = 2; i <= 9; ++i) want += c[i - 2] * std::pow(3.83847 - 2.5, i);
  EXPECT_NEAR(v, want, 1e-13);
  // A table without a Spline block is an error unless the polynomial is requested (as DFTB+).
  const auto dir = scratchDir();
  const std::string path = writeFile(
      dir, "Y-Y.skf",
      syntheticTable(true, 20, "0.0 -0.2 -0.5 0.0 0.3 0.3 0.3 0.0 2.0 2.0",
                     [](int i, int) { return std::exp(-0.1 * i); }, ""));
  const std::string msg =
      inputErrorOf([&] { ParameterSet::load({"Y"}, {{"Y-Y", path}}, "test"); });
  EXPECT_NE(msg.find("Y-Y.skf"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Spline"), std::string::npos) << msg;
  EXPECT_NO_THROW(ParameterSet::load({"Y"}, {{"Y-Y", path}}, "test", {}, {"Y-Y"}));
}
