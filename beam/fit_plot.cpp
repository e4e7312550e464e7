#include "beam/fit_plot.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "common/units.hpp"

namespace mesochain::beam {

namespace {

constexpr double kMeVPerHartree = 1e3 * units::kHartreeInEv;
constexpr plot::Color kShade = kFitWindowShade, kEdge = kFitWindowEdge, kZero{150, 150, 150}, kOutside{225, 135, 0};

std::string deformationLabel(const std::string& unit) {
  if (unit == "strain") return "strain";
  if (unit == "rad_per_cell") return "twist per cell (rad)";
  if (unit == "per_bohr") return "curvature 1/R (1/Bohr)";
  return unit;
}

// An axis range on whole tick steps that the figure's own tick placement keeps as it is (it
// recomputes the step from the fixed range, so widen until the range is stable).
plot::AxisTicks stableTicks(double lo, double hi, int target) {
  plot::AxisTicks t = plot::linearTicks(lo, hi, target);
  for (int i = 0; i < 8; ++i) {
    const plot::AxisTicks u = plot::linearTicks(t.lo, t.hi, target);
    if (u.lo == t.lo && u.hi == t.hi) break;
    t = u;
  }
  return t;
}

std::vector<double> samples(double a, double b, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = a + (b - a) * i / (n - 1);
  return x;
}

// The accepted window as the data cover it, and the whole data range.
struct Ranges {
  double lo = 0.0, hi = 0.0;    // data
  double wlo = 0.0, whi = 0.0;  // window within the data
};

Ranges rangesOf(const FittedCurve& c) {
  Ranges r{INFINITY, -INFINITY, INFINITY, -INFINITY};
  const double X = c.fit.windowHalfWidth * (1.0 + 1e-12);
  for (const CurvePoint& p : c.points) {
    r.lo = std::min(r.lo, p.x), r.hi = std::max(r.hi, p.x);
    if (std::abs(p.x) <= X) r.wlo = std::min(r.wlo, p.x), r.whi = std::max(r.whi, p.x);
  }
  return r;
}

// A light band over [a, b] drawn as one very wide vertical stroke (the figure has no area
// fills): its width in pixels is set from the layout once the axes are fixed.
void addBand(plot::Figure& f, double a, double b, double ylo, double yhi) {
  plot::SeriesStyle s;
  s.color = kShade;
  const double span = yhi - ylo;
  f.add("", {0.5 * (a + b), 0.5 * (a + b)}, {ylo - 2 * span, yhi + 2 * span}, s);
}

void sizeBand(plot::Figure& f, std::size_t band, double a, double b, int width, int height) {
  const plot::FigureLayout L = f.layout(width, height);
  f.series[band].style.lineWidth = std::max(1.0, std::abs(L.x.toPixel(b) - L.x.toPixel(a)));
}

void addEdges(plot::Figure& f, const Ranges& r, double ylo, double yhi, bool named) {
  plot::SeriesStyle s;
  s.color = kEdge;
  s.dashed = true;
  s.lineWidth = 1.5;
  f.add(named ? "window edges" : "", {r.wlo, r.wlo}, {ylo, yhi}, s);
  f.add("", {r.whi, r.whi}, {ylo, yhi}, s);
}

}  // namespace

std::string formatWithUncertainty(double v, double u) {
  if (!(u > 0.0) || !std::isfinite(u) || !std::isfinite(v)) return fmt::format("{:.6g}", v);
  const int e = static_cast<int>(std::floor(std::log10(u))) - 1;  // place of the 2nd digit of u
  if (e <= 0 && e >= -9 && std::abs(v) < 1e6)
    return fmt::format("{:.{}f} +/- {:.{}f}", v, -e, u, -e);
  const int ev = v != 0.0 ? static_cast<int>(std::floor(std::log10(std::abs(v)))) : e + 1;
  const int digits = std::max(0, ev - e);
  const double scale = std::pow(10.0, ev);
  return fmt::format("({:.{}f} +/- {:.{}f})e{}", v / scale, digits, u / scale, digits, ev);
}

std::string stiffnessUnitLabel(const std::string& unit) {
  if (unit == "strain") return "Ha";
  if (unit == "rad_per_cell") return "Ha/rad^{2}";
  if (unit == "per_bohr") return "Ha Bohr^{2}";
  return "Ha per unit^{2}";
}

plot::Image renderFitPlot(const FittedCurve& c, int width, int height, int residualHeight) {
  const QuadraticFit& f = c.fit;
  auto model = [&](double x) { return f.slope * x + 0.5 * f.stiffness * x * x; };  // U - U0
  const Ranges r = rangesOf(c);
  const double X = f.windowHalfWidth * (1.0 + 1e-12);

  std::vector<double> xin, yin, rin, xout, yout, rout;
  for (const CurvePoint& p : c.points) {
    const double du = (p.energy - f.energy0) * kMeVPerHartree;
    const double res = du - model(p.x) * kMeVPerHartree;
    const bool inside = std::abs(p.x) <= X;
    (inside ? xin : xout).push_back(p.x);
    (inside ? yin : yout).push_back(du);
    (inside ? rin : rout).push_back(res);
  }
  // The fitted quadratic over the window, extrapolated (dashed) over the rest of the scan.
  const std::vector<double> xw = samples(r.wlo, r.whi, 120);
  std::vector<double> yw;
  for (double x : xw) yw.push_back(model(x) * kMeVPerHartree);
  std::vector<std::vector<double>> xe, ye;
  for (auto [a, b] : {std::pair{r.lo, r.wlo}, std::pair{r.whi, r.hi}}) {
    if (!(b > a)) continue;
    xe.push_back(samples(a, b, 80));
    ye.emplace_back();
    for (double x : xe.back()) ye.back().push_back(model(x) * kMeVPerHartree);
  }

  // Common x axis of both panels; y range of the energies with a margin.
  const plot::AxisTicks xt = stableTicks(r.lo, r.hi, std::max(2, width / 150));
  double ylo = INFINITY, yhi = -INFINITY;
  for (const auto* v : {&yin, &yout, &yw}) {
    for (double y : *v) ylo = std::min(ylo, y), yhi = std::max(yhi, y);
  }
  for (const auto& v : ye)
    for (double y : v) ylo = std::min(ylo, y), yhi = std::max(yhi, y);
  const double pad = yhi > ylo ? 0.06 * (yhi - ylo) : 1.0;
  ylo -= pad, yhi += pad;

  plot::Figure top(fmt::format("{}: {} = {} {}, |x| <= {:.3g}", c.label, c.quantity,
                               formatWithUncertainty(f.stiffness, f.uncertainty),
                               stiffnessUnitLabel(c.deformationUnit), f.windowHalfWidth));
  top.x = {deformationLabel(c.deformationUnit), plot::Scale::Linear, xt.lo, xt.hi};
  top.y = {"U - U0 per cell (meV)", plot::Scale::Linear, ylo, yhi};
  addBand(top, r.wlo, r.whi, ylo, yhi);
  addEdges(top, r, ylo, yhi, true);
  plot::SeriesStyle fitStyle;
  fitStyle.color = plot::paletteColor(1);
  top.add(f.slope != 0.0 ? "fit U0 + b x + k x^{2}/2" : "fit U0 + k x^{2}/2", xw, yw, fitStyle);
  fitStyle.dashed = true;
  fitStyle.lineWidth = 1.5;
  for (std::size_t i = 0; i < xe.size(); ++i) top.add(i == 0 ? "extrapolated" : "", xe[i], ye[i], fitStyle);
  plot::SeriesStyle in{.line = false, .marker = plot::Marker::Circle, .color = plot::paletteColor(0)};
  plot::SeriesStyle out{.line = false, .marker = plot::Marker::Square, .color = kOutside};
  top.add(fmt::format("{} points in the window", xin.size()), xin, yin, in);
  if (!xout.empty()) top.add(fmt::format("{} outside", xout.size()), xout, yout, out);
  sizeBand(top, 0, r.wlo, r.whi, width, height);
  plot::Image img = top.render(width, height);
  if (residualHeight <= 0) return img;

  // Residuals; held to a few times the in-window ones when the outside points are far off.
  double inMax = 0.0, outMax = 0.0;
  for (double v : rin) inMax = std::max(inMax, std::abs(v));
  for (double v : rout) outMax = std::max(outMax, std::abs(v));
  double rlo = -inMax, rhi = inMax;
  int offScale = 0;
  if (inMax > 0.0 && outMax > 10.0 * inMax) {
    rlo = -3.0 * inMax, rhi = 3.0 * inMax;
  } else {
    for (double v : rout) rlo = std::min(rlo, v), rhi = std::max(rhi, v);
    const double rp = rhi > rlo ? 0.1 * (rhi - rlo) : 1e-6;
    rlo -= rp, rhi += rp;
  }
  const plot::AxisTicks rt = stableTicks(rlo, rhi, std::max(2, residualHeight / 110));
  rlo = rt.lo, rhi = rt.hi;
  for (double v : rout) offScale += v < rlo || v > rhi;
  plot::Figure bottom(fmt::format("residual U - fit ({})", c.source));
  bottom.x = top.x;
  bottom.y = {"meV", plot::Scale::Linear, rlo, rhi};
  addBand(bottom, r.wlo, r.whi, rlo, rhi);
  addEdges(bottom, r, rlo, rhi, false);
  plot::SeriesStyle zero;
  zero.color = kZero;
  zero.lineWidth = 1.0;
  bottom.add("", {xt.lo, xt.hi}, {0.0, 0.0}, zero);
  bottom.add("", xin, rin, in);
  if (!xout.empty())
    bottom.add(offScale > 0 ? fmt::format("{} outside off the scale", offScale) : "", xout, rout, out);
  sizeBand(bottom, 0, r.wlo, r.whi, width, residualHeight);
  return plot::aboveEachOther(img, bottom.render(width, residualHeight));
}

void writeFitPlot(const FittedCurve& curve, const std::string& path) {
  plot::writePng(path, renderFitPlot(curve));
}

}  // namespace mesochain::beam
