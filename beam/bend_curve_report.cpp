#include "beam/bend_curve_report.hpp"
#include "beam/fit_plot.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/units.hpp"
#include "common/plot/figure.hpp"
#include "common/units.hpp"

namespace mesochain::beam {

namespace {

using nlohmann::json;


double nm() { return units::si::kBohrInNm; }

json constantJson(const LeastSquaresConstant& c) {
  const double f = hartreeBohr2InEvNm2();
  return {{"value_hartree_bohr2", c.value}, {"error_hartree_bohr2", c.error}, {"value_eV_nm2", c.value * f},
          {"error_eV_nm2", c.error * f}, {"points", c.points}};
}

}  // namespace

double hartreeBohr2InEvNm2() { return units::kHartreeInEv * nm() * nm(); }

json bendCurveJson(const BendCurve& c, const std::string& label) {
  const double f = hartreeBohr2InEvNm2();
  json j;
  j["format"] = 1;
  j["curve"] = label;
  j["reference_energy_hartree"] = c.referenceEnergy;
  j["quadratic_regime"] = {{"points", c.quadraticPoints}, {"verified", c.quadraticVerified},
                           {"max_curvature_per_bohr", c.quadraticMaxCurvature},
                           {"min_radius_nm", nm() / c.quadraticMaxCurvature},
                           {"stiffness", constantJson(c.linear)}};
  if (c.hasQuartic) {
    const double f4 = units::kHartreeInEv * std::pow(nm(), 4);
    j["quartic_law"] = {{"stiffness", constantJson(c.quarticStiffness)},
                        {"c_hartree_bohr4", c.quarticCoefficient}, {"c_error_hartree_bohr4", c.quarticError},
                        {"c_eV_nm4", c.quarticCoefficient * f4}, {"c_error_eV_nm4", c.quarticError * f4}};
  }
  if (c.hasFreeOffset)
    j["free_offset_fit"] = {{"stiffness", constantJson(c.freeStiffness)}, {"offset_hartree", c.freeOffset},
                            {"offset_error_hartree", c.freeOffsetError}};
  if (c.window) {
    const WindowConstant& w = *c.window;
    j["window"] = {{"min_curvature_per_bohr", w.lo}, {"max_curvature_per_bohr", w.hi},
                   {"min_radius_nm", nm() / w.hi}, {"max_radius_nm", w.lo > 0.0 ? json(nm() / w.lo) : json(nullptr)},
                   {"stiffness", constantJson(w.stiffness)}, {"secant_min_eV_nm2", w.secantMin * f},
                   {"secant_max_eV_nm2", w.secantMax * f}, {"quadratic", w.quadratic}};
  }
  json pts = json::array();
  for (const BendCurvePoint& p : c.points) {
    json q = {{"curvature_per_bohr", p.sample.curvature}, {"radius_nm", nm() / p.sample.curvature},
              {"energy_hartree", p.sample.energy}, {"energy_above_reference_hartree", p.energyAbove},
              {"secant_hartree_bohr2", p.secant}, {"tangent_hartree_bohr2", p.tangent},
              {"moment_hartree_bohr", p.moment}, {"secant_eV_nm2", p.secant * f}, {"tangent_eV_nm2", p.tangent * f},
              {"quadratic", p.quadratic}};
    if (std::isfinite(p.sample.radialExtent)) {
      q["radial_extent_bohr"] = p.sample.radialExtent;
      q["mean_square_radial_offset_bohr2"] = p.sample.meanSquareRadialOffset;
      q["axial_extent_bohr"] = p.sample.axialExtent;
    }
    pts.push_back(q);
  }
  j["points"] = pts;
  j["warnings"] = c.warnings;
  return j;
}

std::string bendCurveCsv(const BendCurve& c) {
  const double f = hartreeBohr2InEvNm2();
  std::string s = fmt::format("# reference_energy_hartree = {:.17g}\n", c.referenceEnergy);
  s += "curvature_per_bohr,radius_nm,energy_above_reference_hartree,secant_eV_nm2,tangent_eV_nm2,"
       "moment_hartree_bohr,quadratic,radial_extent_bohr,mean_square_radial_offset_bohr2,axial_extent_bohr\n";
  auto opt = [](double x) { return std::isfinite(x) ? fmt::format("{:.10g}", x) : std::string(); };
  for (const BendCurvePoint& p : c.points)
    s += fmt::format("{:.17g},{:.10g},{:.17g},{:.10g},{:.10g},{:.10g},{},{},{},{}\n", p.sample.curvature,
                     nm() / p.sample.curvature, p.energyAbove, p.secant * f, p.tangent * f, p.moment,
                     p.quadratic ? "true" : "false", opt(p.sample.radialExtent), opt(p.sample.meanSquareRadialOffset),
                     opt(p.sample.axialExtent));
  return s;
}

plot::Image renderBendCurvePlot(const BendCurve& c, const std::string& title, int width, int height) {
  const double f = hartreeBohr2InEvNm2();
  std::vector<double> k, sec, tan;
  double ylo = INFINITY, yhi = -INFINITY;
  for (const BendCurvePoint& p : c.points) {
    k.push_back(p.sample.curvature / nm());  // 1/nm
    sec.push_back(p.secant * f);
    tan.push_back(p.tangent * f);
    ylo = std::min({ylo, sec.back(), tan.back()}), yhi = std::max({yhi, sec.back(), tan.back()});
  }
  const double pad = yhi > ylo ? 0.08 * (yhi - ylo) : 0.1 * std::abs(yhi) + 1.0;
  ylo -= pad, yhi += pad;
  const double klo = k.front() / 1.5, khi = k.back() * 1.5;
  plot::Figure fig(title);
  fig.x = {"curvature 1/R (1/nm)", plot::Scale::Log10, klo, khi};
  fig.y = {"bending stiffness per cell (eV nm^{2})", plot::Scale::Linear, ylo, yhi};
  // The quadratic regime: from the axis to halfway (geometrically) to the first ring outside.
  std::size_t band = 0;
  double bandHi = 0.0;
  if (c.quadraticVerified) {
    const std::size_t q = static_cast<std::size_t>(c.quadraticPoints);
    bandHi = q < k.size() ? std::sqrt(k[q - 1] * k[q]) : khi;
    band = fig.series.size();
    fig.add("", {std::sqrt(klo * bandHi), std::sqrt(klo * bandHi)}, {ylo, yhi}, {.color = kFitWindowShade});
    fig.add("quadratic regime", {bandHi, bandHi}, {ylo, yhi}, {.dashed = true, .color = kFitWindowEdge, .lineWidth = 1.5});
  }
  const double d0 = c.linear.value * f;
  fig.add(fmt::format("D_0 = {:.4g} eV nm^{{2}}", d0), {klo, khi}, {d0, d0},
          {.dashed = true, .color = plot::paletteColor(3), .lineWidth = 1.5});
  if (c.window) {
    const double a = std::max(klo, c.window->lo / nm()), b = std::min(khi, c.window->hi / nm());
    plot::SeriesStyle w{.dashed = true, .color = plot::paletteColor(4), .lineWidth = 1.5};
    fig.add(fmt::format("window: {:.4g} eV nm^{{2}}", c.window->stiffness.value * f), {a, a}, {ylo, yhi}, w);
    fig.add("", {b, b}, {ylo, yhi}, w);
  }
  fig.add("secant 2 dU / k^{2}", k, sec, {.marker = plot::Marker::Circle, .color = plot::paletteColor(0)});
  fig.add("tangent d^{2}U / dk^{2}", k, tan,
          {.marker = plot::Marker::Triangle, .dashed = true, .color = plot::paletteColor(1)});
  if (c.quadraticVerified) {
    const plot::FigureLayout L = fig.layout(width, height);
    fig.series[band].style.lineWidth = std::max(1.0, std::abs(L.x.toPixel(bandHi) - L.x.toPixel(klo)));
  }
  return fig.render(width, height);
}

}  // namespace mesochain::beam
