// The properties read off a stress-strain curve (mdem/tensile_properties.hpp), on piecewise-linear
// curves whose values follow in closed form: E = 100 MPa up to 4 % (4 MPa), hardening at 20 MPa
// to 10 % (5.2 MPa), then a linear fall of 40 MPa per unit strain to 0 at 23 %, sampled every
// 0.1 % (the knots are samples, so the trapezoid sums are exact):
//   0.2 % offset yield: 100 (e - 0.002) = 4 + 20 (e - 0.04)  ->  e = 0.0425, 4.05 MPa;
//   ultimate 5.2 MPa at 0.10; failure (half the ultimate, 2.6 MPa) at 0.165;
//   toughness 0.08 + 0.276 + 0.338 = 0.694 MJ/m^3, to failure 0.08 + 0.276 + 0.2535 = 0.6095.
// And the JSON a tensile stage writes holds what the function returns.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mdem/tensile_properties.hpp"
#include "tests/support/process_temp_dir.hpp"

namespace mesochain::mdem {
namespace {

std::vector<TensileSample> curve(int lastPerMille) {
  std::vector<TensileSample> s;
  for (int k = 0; k <= lastPerMille; ++k) {
    TensileSample t;
    t.strain = k * 1e-3;
    const double e = t.strain;
    t.stress = k <= 40 ? 100.0 * e : k <= 100 ? 4.0 + 20.0 * (e - 0.04) : 5.2 - 40.0 * (e - 0.1);
    s.push_back(t);
  }
  return s;
}

TEST(MdemTensileProperties, ClosedFormsOfAPiecewiseLinearCurve) {
  const TensileProperties p = tensileProperties(curve(230));
  EXPECT_EQ(p.samples, 231);
  ASSERT_TRUE(p.elastic.fitted);
  EXPECT_NEAR(p.elastic.slope, 100.0, 1e-9);
  EXPECT_NEAR(p.yieldStrain, 0.0425, 1e-12);
  EXPECT_NEAR(p.yieldStress, 4.05, 1e-10);
  EXPECT_NEAR(p.ultimateStress, 5.2, 1e-12);
  EXPECT_NEAR(p.ultimateStrain, 0.1, 1e-15);
  EXPECT_NEAR(p.failureStrain, 0.165, 1e-12);
  EXPECT_NEAR(p.toughness, 0.694, 1e-12);
  EXPECT_NEAR(p.toughnessToFailure, 0.6095, 1e-12);
  EXPECT_NEAR(p.finalStrain, 0.23, 1e-15);
  EXPECT_NEAR(p.finalStress, 0.0, 1e-12);
}

TEST(MdemTensileProperties, WhatATestDidNotReachIsNotReported) {
  // Stopped at 8 %: yield and ultimate so far, no failure.
  const TensileProperties partial = tensileProperties(curve(80));
  EXPECT_NEAR(partial.yieldStrain, 0.0425, 1e-12);
  EXPECT_NEAR(partial.ultimateStrain, 0.08, 1e-15);
  EXPECT_TRUE(std::isnan(partial.failureStrain));
  EXPECT_TRUE(std::isnan(partial.toughnessToFailure));
  EXPECT_NEAR(partial.toughness, 0.08 + 0.5 * (4.0 + 4.8) * 0.04, 1e-12);
  // Elastic only: no yield (the curve never leaves the line), toughness E e^2 / 2.
  const TensileProperties elastic = tensileProperties(curve(40));
  EXPECT_TRUE(std::isnan(elastic.yieldStrain));
  EXPECT_NEAR(elastic.toughness, 0.5 * 100.0 * 0.04 * 0.04, 1e-12);
  // Too few samples for a slope: no yield either; no samples: nothing, no crash.
  const TensileProperties few = tensileProperties(curve(1));
  EXPECT_FALSE(few.elastic.fitted);
  EXPECT_TRUE(std::isnan(few.yieldStrain));
  const TensileProperties none = tensileProperties({});
  EXPECT_EQ(none.samples, 0);
  EXPECT_TRUE(std::isnan(none.ultimateStress));
  EXPECT_EQ(none.toughness, 0.0);
}

TEST(MdemTensileProperties, JsonHoldsTheValuesAndNullsForWhatWasNotReached) {
  const auto dir = mesochain::testing::processTempDir("mesochain-tensile-properties");
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "pull-tensile.json").string();
  const TensileProperties p = tensileProperties(curve(80));
  writeTensilePropertiesJson(path, p, 500.0, 450.0, 0.1);
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["kind"], "tensile_properties");
  EXPECT_EQ(j["elastic"]["youngs_modulus_MPa"].get<double>(), p.elastic.slope);
  EXPECT_EQ(j["yield"]["strain"].get<double>(), p.yieldStrain);
  EXPECT_EQ(j["ultimate"]["stress_MPa"].get<double>(), p.ultimateStress);
  EXPECT_TRUE(j["failure"]["strain"].is_null());
  EXPECT_TRUE(j["toughness_MJ_per_m3"]["to_failure"].is_null());
  EXPECT_EQ(j["toughness_MJ_per_m3"]["to_last_sample"].get<double>(), p.toughness);
  EXPECT_EQ(j["cross_section_nm2"].get<double>(), 500.0);
}

}  // namespace
}  // namespace mesochain::mdem
