#include "common/plot/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/plot/bitmap_font.hpp"
#include "common/plot/png_io.hpp"

namespace mesochain::plot {

namespace {

constexpr Color kInk{40, 40, 40}, kGrid{228, 228, 228}, kLegendEdge{170, 170, 170},
    kWhite{255, 255, 255};

bool finitePoint(const Series& s, std::size_t i) { return std::isfinite(s.x[i]) && std::isfinite(s.y[i]); }

int skippedPoints(const Series& s) {
  int n = 0;
  for (std::size_t i = 0; i < s.x.size(); ++i) n += !finitePoint(s, i);
  return n;
}

void checkAxisEnds(const AxisSpec& a, const char* name, const std::string& source) {
  for (const auto& end : {a.min, a.max})
    if (end && (!std::isfinite(*end) || (a.scale == Scale::Log10 && *end <= 0)))
      throw InputError(source, fmt::format("{} axis range", name), fmt::format("an end {}", *end),
                       a.scale == Scale::Log10 ? "a positive finite number on a logarithmic axis"
                                               : "a finite number");
  if (a.min && a.max && !(*a.min < *a.max))
    throw InputError(source, fmt::format("{} axis range", name),
                     fmt::format("min {} and max {}", *a.min, *a.max), "min < max");
}

void validate(const Figure& f, const std::string& source) {
  checkAxisEnds(f.x, "x", source);
  checkAxisEnds(f.y, "y", source);
  for (const Series& s : f.series) {
    const std::string where = fmt::format("series '{}'", s.name);
    if (s.x.size() != s.y.size())
      throw InputError(source, where, fmt::format("{} x values and {} y values", s.x.size(), s.y.size()),
                       "as many x values as y values");
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!finitePoint(s, i)) continue;
      for (auto [v, axis, name] : {std::tuple{s.x[i], &f.x, "x"}, std::tuple{s.y[i], &f.y, "y"}})
        if (axis->scale == Scale::Log10 && v <= 0)
          throw InputError(source, fmt::format("{}, point {}", where, i), fmt::format("{} = {}", name, v),
                           fmt::format("positive values on the logarithmic {} axis", name));
    }
  }
}

AxisTicks ticksFor(const Figure& f, bool isX, int target) {
  const AxisSpec& a = isX ? f.x : f.y;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : f.series)
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (finitePoint(s, i)) {
        const double v = isX ? s.x[i] : s.y[i];
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  if (lo > hi) {  // no data
    lo = a.scale == Scale::Log10 ? 1.0 : 0.0;
    hi = a.scale == Scale::Log10 ? 10.0 : 1.0;
  }
  if (a.min) lo = *a.min;
  if (a.max) hi = *a.max;
  lo = std::min(lo, hi);
  AxisTicks t = a.scale == Scale::Log10 ? logTicks(lo, hi, target) : linearTicks(lo, hi, target);
  if (a.min || a.max) {  // fixed ends: the axis is exactly that range
    if (a.min) t.lo = *a.min;
    if (a.max) t.hi = *a.max;
    AxisTicks kept{t.lo, t.hi, {}, {}, {}};
    const double slack = 1e-9 * (t.hi - t.lo);
    for (std::size_t i = 0; i < t.major.size(); ++i)
      if (t.major[i] >= t.lo - slack && t.major[i] <= t.hi + slack) {
        kept.major.push_back(t.major[i]);
        kept.labels.push_back(t.labels[i]);
      }
    for (double m : t.minor)
      if (m >= t.lo && m <= t.hi) kept.minor.push_back(m);
    t = kept;
  }
  return t;
}

std::string legendText(const Series& s) {
  const int skipped = skippedPoints(s);
  if (skipped == 0) return s.name;
  return fmt::format("{} ({} non-finite point{} skipped)", s.name, skipped, skipped == 1 ? "" : "s");
}

Color seriesColor(const Figure& f, std::size_t i) {
  return f.series[i].style.color.value_or(paletteColor(static_cast<int>(i)));
}

// Runs of consecutive finite points, in pixels.
std::vector<std::vector<Point>> pixelRuns(const Series& s, const FigureLayout& L) {
  std::vector<std::vector<Point>> runs(1);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (!finitePoint(s, i)) {
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    runs.back().push_back({L.x.toPixel(s.x[i]), L.y.toPixel(s.y[i])});
  }
  if (runs.back().empty()) runs.pop_back();
  return runs;
}

// The named series, and the legend's size for them (pixels).
struct LegendSize {
  std::vector<std::size_t> shown;
  int width = 0, height = 0;
};
constexpr int kLegendPad = 10, kLegendSample = 36, kLegendInset = 12, kLegendGap = 16;
LegendSize legendSize(const Figure& f, int s) {
  LegendSize z;
  for (std::size_t i = 0; i < f.series.size(); ++i)
    if (!f.series[i].name.empty()) z.shown.push_back(i);
  if (z.shown.empty()) return z;
  const int rowH = textHeight(s) + 6;
  int textW = 0;
  for (std::size_t i : z.shown) textW = std::max(textW, markupWidth(legendText(f.series[i]), s));
  z.width = kLegendPad + kLegendSample + 8 + textW + kLegendPad;
  z.height = kLegendPad + static_cast<int>(z.shown.size()) * rowH - 6 + kLegendPad;
  return z;
}

// Places the legend (FigureLayout::legend): the inner corner that hides the fewest data points
// (lines sampled between points too); when every corner hides some and the image is wide enough,
// outside on the right, with the plot narrowed.
void placeLegend(const Figure& f, FigureLayout& L, int width) {
  const LegendSize z = legendSize(f, L.textScale);
  if (z.shown.empty()) return;
  const int w = z.width, h = z.height;
  const Rect& p = L.plot;
  const std::array<Rect, 4> corners{
      Rect{p.right - kLegendInset - w, p.top + kLegendInset, p.right - kLegendInset, p.top + kLegendInset + h},
      Rect{p.left + kLegendInset, p.top + kLegendInset, p.left + kLegendInset + w, p.top + kLegendInset + h},
      Rect{p.right - kLegendInset - w, p.bottom - kLegendInset - h, p.right - kLegendInset, p.bottom - kLegendInset},
      Rect{p.left + kLegendInset, p.bottom - kLegendInset - h, p.left + kLegendInset + w, p.bottom - kLegendInset}};
  std::array<long, 4> hidden{};
  for (const Series& ser : f.series)
    for (const auto& run : pixelRuns(ser, L))
      for (std::size_t k = 0; k < run.size(); ++k) {
        const int samples = (k + 1 < run.size() && ser.style.line) ? 8 : 1;
        for (int j = 0; j < samples; ++j) {
          const Point a = run[k], b = k + 1 < run.size() ? run[k + 1] : run[k];
          const double t = static_cast<double>(j) / samples;
          for (int c = 0; c < 4; ++c)
            hidden[c] += corners[c].contains(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        }
      }
  const auto best = std::min_element(hidden.begin(), hidden.end());
  L.legend = corners[best - hidden.begin()];
  // Outside only when the plot keeps at least half the image's width.
  const int right = width - kLegendInset - w - kLegendGap;
  if (*best == 0 || right - L.plot.left < width / 2) return;
  L.plot.right = right;
  L.x.pixHi = L.plot.right - 0.5;
  L.legend = {right + kLegendGap, p.top, right + kLegendGap + w, p.top + h};
  L.legendOutside = true;
}

void drawLegend(Image& img, const Figure& f, const FigureLayout& L) {
  const LegendSize z = legendSize(f, L.textScale);
  if (z.shown.empty()) return;
  const std::vector<std::size_t>& shown = z.shown;
  const int s = L.textScale, rowH = textHeight(s) + 6, sample = kLegendSample, pad = kLegendPad;
  const Rect box = L.legend;
  fillRect(img, box, kWhite);
  strokeRect(img, box, kLegendEdge);
  for (std::size_t r = 0; r < shown.size(); ++r) {
    const Series& ser = f.series[shown[r]];
    const Color c = seriesColor(f, shown[r]);
    const int top = box.top + pad + static_cast<int>(r) * rowH;
    const double mid = top + 0.5 * kGlyphAscent * s;
    const Point a{box.left + pad + 0.0, mid}, b{box.left + pad + sample + 0.0, mid};
    if (ser.style.line)
      strokePolyline(img, {a, b}, c, {ser.style.lineWidth, ser.style.dashed, 8.0, 5.0}, box);
    drawMarker(img, ser.style.marker, {0.5 * (a.x + b.x), mid}, ser.style.markerSize, c, box);
    drawText(img, box.left + pad + sample + 8, top, legendText(ser), s, kInk);
  }
}

}  // namespace

Color paletteColor(int i) {
  static constexpr std::array<Color, 8> kPalette{{{0, 90, 181},
                                                  {214, 55, 30},
                                                  {0, 140, 70},
                                                  {140, 60, 170},
                                                  {225, 135, 0},
                                                  {0, 160, 190},
                                                  {125, 80, 40},
                                                  {100, 100, 100}}};
  return kPalette[static_cast<std::size_t>(i) % kPalette.size()];
}

double AxisMap::toPixel(double v) const {
  const double u = scale == Scale::Log10 ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                                         : (v - lo) / (hi - lo);
  return pixLo + u * (pixHi - pixLo);
}

Series& Figure::add(std::string name, std::vector<double> xs, std::vector<double> ys, SeriesStyle style) {
  series.push_back({std::move(name), std::move(xs), std::move(ys), style});
  return series.back();
}

FigureLayout Figure::layout(int width, int height, const std::string& source) const {
  validate(*this, source);
  FigureLayout L;
  L.textScale = std::min(width, height) >= 400 ? 2 : 1;
  const int s = L.textScale, th = textHeight(s);
  L.xTicks = ticksFor(*this, true, std::max(2, width / 150));
  L.yTicks = ticksFor(*this, false, std::max(2, height / 110));
  int yLabelW = 0;
  for (const auto& l : L.yTicks.labels) yLabelW = std::max(yLabelW, markupWidth(l, s));
  const int lastXLabel = L.xTicks.labels.empty() ? 0 : markupWidth(L.xTicks.labels.back(), s);
  L.plot.left = 12 + (y.label.empty() ? 0 : th + 10) + yLabelW + 8;
  L.plot.top = title.empty() ? 16 : 12 + th + 12;
  L.plot.right = width - std::max(20, lastXLabel / 2 + 8);
  L.plot.bottom = height - (8 + th + (x.label.empty() ? 0 : 8 + th) + 12);
  if (L.plot.right - L.plot.left < 40 || L.plot.bottom - L.plot.top < 40)
    throw InputError(source, "", fmt::format("an image of {} x {} pixels", width, height),
                     "an image large enough for the axes and labels");
  L.x = {x.scale, L.xTicks.lo, L.xTicks.hi, L.plot.left + 0.5, L.plot.right - 0.5};
  L.y = {y.scale, L.yTicks.lo, L.yTicks.hi, L.plot.bottom - 0.5, L.plot.top + 0.5};
  placeLegend(*this, L, width);
  return L;
}

Image Figure::render(int width, int height, const std::string& source) const {
  const FigureLayout L = layout(width, height, source);
  const Rect& p = L.plot;
  const int s = L.textScale, th = textHeight(s);
  Image img(width, height);
  // Grid, frame, ticks and their labels.
  for (double v : L.xTicks.major) {
    const int c = static_cast<int>(std::floor(L.x.toPixel(v)));
    fillRect(img, {c, p.top, c + 1, p.bottom}, kGrid);
  }
  for (double v : L.yTicks.major) {
    const int r = static_cast<int>(std::floor(L.y.toPixel(v)));
    fillRect(img, {p.left, r, p.right, r + 1}, kGrid);
  }
  strokeRect(img, p, kInk);
  auto xTick = [&](double v, int len) {
    const int c = static_cast<int>(std::floor(L.x.toPixel(v)));
    fillRect(img, {c, p.bottom - len, c + 1, p.bottom}, kInk);
    fillRect(img, {c, p.top, c + 1, p.top + len}, kInk);
  };
  auto yTick = [&](double v, int len) {
    const int r = static_cast<int>(std::floor(L.y.toPixel(v)));
    fillRect(img, {p.left, r, p.left + len, r + 1}, kInk);
    fillRect(img, {p.right - len, r, p.right, r + 1}, kInk);
  };
  for (double v : L.xTicks.minor) xTick(v, 4);
  for (double v : L.yTicks.minor) yTick(v, 4);
  for (std::size_t i = 0; i < L.xTicks.major.size(); ++i) {
    xTick(L.xTicks.major[i], 8);
    const int c = static_cast<int>(std::floor(L.x.toPixel(L.xTicks.major[i])));
    drawText(img, c - markupWidth(L.xTicks.labels[i], s) / 2, p.bottom + 8, L.xTicks.labels[i], s, kInk);
  }
  for (std::size_t i = 0; i < L.yTicks.major.size(); ++i) {
    yTick(L.yTicks.major[i], 8);
    const int r = static_cast<int>(std::floor(L.y.toPixel(L.yTicks.major[i])));
    drawText(img, p.left - 8 - markupWidth(L.yTicks.labels[i], s), r - kGlyphAscent * s / 2,
             L.yTicks.labels[i], s, kInk);
  }
  // Title and axis labels.
  if (!title.empty())
    drawText(img, (p.left + p.right - markupWidth(title, s)) / 2, 12, title, s, kInk);
  if (!x.label.empty())
    drawText(img, (p.left + p.right - markupWidth(x.label, s)) / 2, p.bottom + 8 + th + 8, x.label, s, kInk);
  if (!y.label.empty())
    drawTextUp(img, 12, (p.top + p.bottom - markupWidth(y.label, s)) / 2, y.label, s, kInk);
  // Data inside the frame.
  const Rect inside{p.left + 1, p.top + 1, p.right - 1, p.bottom - 1};
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Series& ser = series[i];
    const Color c = seriesColor(*this, i);
    for (const auto& run : pixelRuns(ser, L)) {
      if (ser.style.line) strokePolyline(img, run, c, {ser.style.lineWidth, ser.style.dashed}, inside);
      for (const Point& q : run) drawMarker(img, ser.style.marker, q, ser.style.markerSize, c, inside);
    }
  }
  drawLegend(img, *this, L);
  return img;
}

void Figure::savePng(const std::string& path, int width, int height) const {
  writePng(path, render(width, height, path));
}

}  // namespace mesochain::plot
