#pragma once
// A line/marker plot rendered to an RGB image or a PNG file: title, axis labels, linear or
// log10 axes with automatic ticks, several series with distinct colours, a legend.
//
//   plot::Figure fig("Relaxation");
//   fig.x.label = "step";
//   fig.y = {"max |force| (Ha/Bohr)", plot::Scale::Log10};
//   fig.add("max force", steps, forces, {.marker = plot::Marker::Circle});
//   fig.savePng("relax.png");
//
// Points with a non-finite coordinate are skipped (the line breaks there) and the legend says
// how many; on a log axis a non-positive value is an InputError naming the series.
#include <optional>
#include <string>
#include <vector>

#include "common/plot/canvas.hpp"
#include "common/plot/ticks.hpp"

namespace mesochain::plot {

enum class Scale { Linear, Log10 };

struct AxisSpec {
  std::string label;
  Scale scale = Scale::Linear;
  std::optional<double> min, max;  // fixed ends instead of the data range
};

struct SeriesStyle {
  bool line = true;
  Marker marker = Marker::None;
  bool dashed = false;
  std::optional<Color> color;  // default: the next colour of the palette
  double lineWidth = 2.0;      // pixels
  double markerSize = 8.0;     // pixels
};

struct Series {
  std::string name;
  std::vector<double> x, y;
  SeriesStyle style;
};

// Data value -> continuous pixel coordinate along one axis.
struct AxisMap {
  Scale scale = Scale::Linear;
  double lo = 0.0, hi = 1.0;    // axis range (data units)
  double pixLo = 0.0, pixHi = 1.0;  // pixel coordinates of lo and hi (pixel centres)
  double toPixel(double v) const;
};

struct FigureLayout {
  Rect plot;   // the framed plotting area; the frame is its outermost pixel ring
  AxisTicks xTicks, yTicks;
  AxisMap x, y;
  int textScale = 2;
  // The legend's box (empty without named series): the inner corner of the plot that hides the
  // fewest data points, or, when every corner would hide some, beside the plot on the right
  // (the plot narrowed to make room; legendOutside).
  Rect legend;
  bool legendOutside = false;
};

// The palette colour number i (cycled).
Color paletteColor(int i);

class Figure {
 public:
  explicit Figure(std::string title = "") : title(std::move(title)) {}

  std::string title;
  AxisSpec x, y;
  std::vector<Series> series;

  Series& add(std::string name, std::vector<double> xs, std::vector<double> ys, SeriesStyle style = {});

  // `source` names the output in error messages (the PNG path when saving).
  FigureLayout layout(int width, int height, const std::string& source = "<plot>") const;
  Image render(int width = 900, int height = 600, const std::string& source = "<plot>") const;
  void savePng(const std::string& path, int width = 900, int height = 600) const;
};

}  // namespace mesochain::plot
