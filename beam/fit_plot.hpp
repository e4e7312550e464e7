#pragma once
// PNG of one fitted energy curve (docs/beam.md, "Plots"):
//   top panel: energy U - U0 per cell (meV) against the deformation, the points inside the
//   accepted window and those outside it, the fitted U0 + b x + k x^2 / 2 over the window (solid)
//   and extrapolated over the rest of the scan (dashed), the window shaded and bounded by dashed
//   vertical lines; the title gives k +- its uncertainty.
//   bottom panel: residuals U - fit (meV) of every point; when the points outside the window
//   are far off, the axis is held to a few times the in-window residuals (those points are
//   then off the scale, as the legend says).
#include <string>

#include "beam/beam_run.hpp"
#include "common/plot/canvas.hpp"

namespace mesochain::beam {

// The colours of the fit plots: the fitted window's shading and its edges.
inline constexpr plot::Color kFitWindowShade{222, 234, 250}, kFitWindowEdge{70, 100, 160};

// "4.2156 +/- 0.0012" (the uncertainty to two significant digits, the value to the same
// decimal place; "%.6g" alone when the uncertainty is 0 or not finite).
std::string formatWithUncertainty(double value, double uncertainty);

// Unit of the stiffness of a curve of this deformation unit ("Ha", "Ha/rad^{2}", "Ha Bohr^{2}").
std::string stiffnessUnitLabel(const std::string& deformationUnit);

plot::Image renderFitPlot(const FittedCurve& curve, int width = 900, int height = 600,
                          int residualHeight = 400);

// Renders and writes the PNG; throws InputError naming `path` when it cannot be written.
void writeFitPlot(const FittedCurve& curve, const std::string& path);

}  // namespace mesochain::beam
