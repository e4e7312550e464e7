// Beam idealisation: the closures round-trip (constants -> Y, G, w, h -> constants, with the
// constants built here from the textbook formulas), residuals of an inconsistent set follow
// from the thickness ratio, round sections, and the few-layer plate formula against a direct
// sum over layers.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "beam/beam_model.hpp"
#include "beam/plate.hpp"
#include "common/errors.hpp"

namespace mesochain::beam {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A collapsed-tube-like rectangle in atomic units (Bohr, Hartree / Bohr^3).
constexpr double kT0 = 4.65, kH = 1.7, kW = 45.0, kY = 0.034, kG = 0.013;

BeamConstants rectangleConstants(double y, double g, double h, double w, double t0) {
  BeamConstants c;
  c.cellLength = t0;
  c.stretch = y * h * w * t0;                                      // C = Y A T0
  c.twist = g * (h * w * w * w + w * h * h * h) / 12.0 / t0;       // K = G (I_x + I_y) / T0
  c.bendSoft = y * w * h * h * h / 12.0 * t0;                      // D_s = Y I_y T0
  c.bendHard = y * h * w * w * w / 12.0 * t0;                      // D_h = Y I_x T0
  return c;
}

TEST(BeamModel, RectangleRoundTrip) {
  const BeamConstants c = rectangleConstants(kY, kG, kH, kW, kT0);
  const Beam b = rectangleFourConstants(c, "constants.toml");
  EXPECT_EQ(b.closure, "four_constants");
  EXPECT_NEAR(b.thickness / kH, 1.0, 1e-13);
  EXPECT_NEAR(b.width / kW, 1.0, 1e-13);
  EXPECT_NEAR(b.young / kY, 1.0, 1e-13);
  EXPECT_NEAR(b.shear / kG, 1.0, 1e-13);
  EXPECT_NEAR(b.section.area, kH * kW, 1e-12);
  EXPECT_NEAR(b.section.polar, b.section.ix + b.section.iy, 1e-9);
  for (double r : {b.residuals.stretch, b.residuals.twist, b.residuals.bendSoft, b.residuals.bendHard})
    EXPECT_NEAR(r, 0.0, 1e-13);
  const BeamConstants back = predictConstants(b);
  EXPECT_NEAR(back.stretch / c.stretch, 1.0, 1e-13);
  EXPECT_NEAR(back.twist / c.twist, 1.0, 1e-13);
  EXPECT_NEAR(back.bendSoft / c.bendSoft, 1.0, 1e-13);
  EXPECT_NEAR(back.bendHard / c.bendHard, 1.0, 1e-13);
}

// Constants of a rectangle of thickness h, closed with a measured thickness h_m: w is kept
// (D_h / C = w^2 / 12 does not involve h), Y' = Y h / h_m, so D_s is off by (h_m / h)^2 while
// C, K and D_h are met.
TEST(BeamModel, MeasuredThicknessClosureReportsTheSoftBendingResidual) {
  const BeamConstants c = rectangleConstants(kY, kG, kH, kW, kT0);
  const double hm = 6.4;  // two graphene layers, Bohr
  const Beam b = rectangleMeasuredThickness(c, hm, "scan.json");
  EXPECT_EQ(b.closure, "measured_thickness");
  EXPECT_DOUBLE_EQ(b.thickness, hm);
  EXPECT_NEAR(b.width / kW, 1.0, 1e-13);
  EXPECT_NEAR(b.young / (kY * kH / hm), 1.0, 1e-13);
  EXPECT_NEAR(b.residuals.stretch, 0.0, 1e-13);
  EXPECT_NEAR(b.residuals.twist, 0.0, 1e-13);
  EXPECT_NEAR(b.residuals.bendHard, 0.0, 1e-13);
  EXPECT_NEAR(b.residuals.bendSoft, (hm / kH) * (hm / kH) - 1.0, 1e-12);
  EXPECT_GT(b.residuals.bendSoft, 10.0);  // the thick beam is far too stiff in soft bending
}

TEST(BeamModel, RefusesNonPositiveConstants) {
  BeamConstants c = rectangleConstants(kY, kG, kH, kW, kT0);
  c.twist = -1e-3;
  try {
    rectangleFourConstants(c, "bad.toml");
    ADD_FAILURE() << "accepted a negative K";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("K (twisting)"), std::string::npos) << m;
  }
}

TEST(BeamModel, SolidCircleRoundTrip) {
  const double r = 6.0, y = 0.03, g = 0.012;
  BeamConstants c;
  c.cellLength = kT0;
  c.stretch = y * kPi * r * r * kT0;
  c.bendSoft = c.bendHard = y * kPi * r * r * r * r / 4.0 * kT0;
  c.twist = g * kPi * r * r * r * r / 2.0 / kT0;
  const Beam b = solidCircle(c, "tube.toml");
  EXPECT_NEAR(b.radius / r, 1.0, 1e-13);
  EXPECT_NEAR(b.young / y, 1.0, 1e-13);
  EXPECT_NEAR(b.shear / g, 1.0, 1e-13);
  EXPECT_NEAR(b.residuals.bendHard, 0.0, 1e-13);
}

// Annulus of mean radius R and wall t: A = 2 pi R t, I = pi R t (R^2 + t^2 / 4), J = 2 I.
TEST(BeamModel, AnnulusRoundTripAndTooThickWall) {
  const double r = 12.8, t = 6.4, y = 0.03, g = 0.012;
  const double a = 2.0 * kPi * r * t, i = kPi * r * t * (r * r + t * t / 4.0);
  BeamConstants c;
  c.cellLength = kT0;
  c.stretch = y * a * kT0;
  c.bendSoft = c.bendHard = y * i * kT0;
  c.twist = g * 2.0 * i / kT0;
  const Beam b = annulus(c, t, "tube.toml");
  EXPECT_NEAR(b.radius / r, 1.0, 1e-12);
  EXPECT_NEAR(b.young / y, 1.0, 1e-12);
  EXPECT_NEAR(b.shear / g, 1.0, 1e-12);
  EXPECT_NEAR(b.section.area / a, 1.0, 1e-12);
  // D / C = R^2/2 + t^2/8 must exceed t^2/4: a wall of 2 sqrt(D/C) or more is refused.
  EXPECT_THROW(annulus(c, 2.0 * std::sqrt(c.bendSoft / c.stretch) * 1.01, "tube.toml"), InputError);
}

// N layers at spacing Z0 about the mid-plane: D = N D1 + sum_i C2 z_i^2 / (1 - nu^2).
TEST(BeamPlate, FewLayerFormulaMatchesASumOverLayers) {
  const double c2 = 21.3, z0 = 3.35, nu = 0.165, d1 = 1.44;  // eV/Å^2, Å, -, eV
  for (int n = 1; n <= 8; ++n) {
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
      const double z = (k - 0.5 * (n - 1)) * z0;
      sum += c2 * z * z;
    }
    const double expected = n * d1 + sum / (1.0 - nu * nu);
    EXPECT_NEAR(plateBendingRigidity(n, c2, z0, nu, d1) / expected, 1.0, 1e-13) << n;
    EXPECT_DOUBLE_EQ(slidingLayersRigidity(n, d1), n * d1);
  }
  EXPECT_DOUBLE_EQ(plateBendingRigidity(1, c2, z0, nu, d1), d1);
  EXPECT_DOUBLE_EQ(ribbonBendingConstant(2.0, 3.0, 5.0), 30.0);
}

}  // namespace
}  // namespace mesochain::beam
