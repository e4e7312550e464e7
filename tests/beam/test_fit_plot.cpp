// The fit plot: value +- uncertainty text, and the rendered figure shows the window band where
// the fit was accepted (and only there), the fitted curve, and the residual panel below.
#include <cmath>

#include <gtest/gtest.h>

#include "beam/fit_plot.hpp"

namespace mesochain::beam {
namespace {

TEST(FitPlot, FormatsValueWithUncertainty) {
  EXPECT_EQ(formatWithUncertainty(4.21567, 0.0123), "4.216 +/- 0.012");
  EXPECT_EQ(formatWithUncertainty(2555.17, 50.4), "2555 +/- 50");
  EXPECT_EQ(formatWithUncertainty(29.44, 0.55), "29.44 +/- 0.55");
  EXPECT_EQ(formatWithUncertainty(1.2345e7, 3.1e4), "(1.2345 +/- 0.0031)e7");
  EXPECT_EQ(formatWithUncertainty(3.0e-12, 2.0e-14), "(3.000 +/- 0.020)e-12");
  EXPECT_EQ(formatWithUncertainty(1.5, 0.0), "1.5");
  EXPECT_EQ(stiffnessUnitLabel("per_bohr"), "Ha Bohr^{2}");
}

FittedCurve syntheticBend() {
  FittedCurve c;
  c.quantity = "D_s";
  c.label = "bend soft";
  c.source = "soft.json";
  c.deformationUnit = "per_bohr";
  const double k = 4.0;
  for (int j = 0; j <= 10; ++j) {
    const double x = 0.004 * j;
    c.points.push_back({x, -10.0 + 0.5 * k * x * x * (1.0 - 40.0 * x * x)});
  }
  c.options.quantity = "D_s";
  c.fit = fitQuadraticRegime(c.points, c.options);
  return c;
}

TEST(FitPlot, ShowsTheWindowTheCurveAndTheResiduals) {
  const FittedCurve c = syntheticBend();
  ASSERT_GT(c.fit.windowHalfWidth, 0.0);
  ASSERT_LT(c.fit.windowHalfWidth, 0.04);  // some points are outside the window
  const plot::Image img = renderFitPlot(c, 900, 600, 400);
  ASSERT_EQ(img.width(), 900);
  ASSERT_EQ(img.height(), 1000);
  // Count the band colour per column of the top panel: present at small x (left), absent at the
  // right end of the scan (outside the window).
  const plot::Color shade{222, 234, 250};
  auto shadedRows = [&](int col, int rowLo, int rowHi) {
    int n = 0;
    for (int y = rowLo; y < rowHi; ++y) n += img.at(col, y) == shade;
    return n;
  };
  int firstShaded = -1, lastShaded = -1;
  for (int x = 0; x < img.width(); ++x)
    if (shadedRows(x, 0, 600) > 100) {
      if (firstShaded < 0) firstShaded = x;
      lastShaded = x;
    }
  ASSERT_GE(firstShaded, 0) << "no shaded window";
  // The band covers [0, X] of an axis over [0, 0.04]: its share of the shaded span matches X / 0.04
  // of the plot width (within a few pixels of frame and tick rounding).
  const int plotWidthGuess = lastShaded - firstShaded;
  EXPECT_GT(plotWidthGuess, 20);
  EXPECT_LT(lastShaded, 0.8 * img.width());
  // The residual panel has its band in the same columns.
  EXPECT_GT(shadedRows((firstShaded + lastShaded) / 2, 600, 1000), 100);
  EXPECT_EQ(shadedRows(img.width() - 60, 600, 1000), 0);
  // Fitted curve (palette colour 1) and points (palette colour 0) are drawn.
  int red = 0, blue = 0;
  for (int y = 0; y < 600; ++y)
    for (int x = 0; x < img.width(); ++x) {
      const plot::Color p = img.at(x, y);
      red += p == plot::Color{214, 55, 30};
      blue += p == plot::Color{0, 90, 181};
    }
  EXPECT_GT(red, 100);
  EXPECT_GT(blue, 50);
}

}  // namespace
}  // namespace mesochain::beam
