#pragma once
// The outputs of a bend-curve analysis (beam/bend_curve.hpp): JSON (every number with its unit
// in its key, atomic and eV/nm), CSV (one row per ring) and a PNG of the secant and tangent
// stiffness against curvature with the quadratic regime shaded (docs/beam.md).
#include <string>

#include <nlohmann/json.hpp>

#include "beam/bend_curve.hpp"
#include "common/plot/canvas.hpp"

namespace mesochain::beam {

// Conversion of a bending stiffness per cell (Hartree Bohr²) to eV nm².
double hartreeBohr2InEvNm2();

nlohmann::json bendCurveJson(const BendCurve& curve, const std::string& label);
std::string bendCurveCsv(const BendCurve& curve);
// Secant (circles) and tangent (triangles) stiffness in eV nm² against 1/R in 1/nm; the
// quadratic regime shaded, D_0 as a horizontal line, the window (if any) between dashed lines.
plot::Image renderBendCurvePlot(const BendCurve& curve, const std::string& title, int width = 900,
                                int height = 560);

}  // namespace mesochain::beam
