#pragma once
// An RGB raster image and the drawing primitives the plots need: anti-aliased thick polylines
// (optionally dashed) and markers, clipped to a rectangle; rectangles; bitmap text (horizontal
// or turned 90 degrees counter-clockwise) with a `^{...}` superscript markup.
#include <cstdint>
#include <string>
#include <vector>

namespace mesochain::plot {

struct Color {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Color&) const = default;
};

struct Point {
  double x = 0.0, y = 0.0;  // pixels; (0, 0) is the top-left corner of the top-left pixel
};

struct Rect {
  int left = 0, top = 0, right = 0, bottom = 0;  // pixel columns [left, right), rows [top, bottom)
  bool contains(double x, double y) const { return x >= left && x < right && y >= top && y < bottom; }
};

enum class Marker { None, Circle, Square, Triangle, Diamond, Cross };

class Image {
 public:
  Image() = default;
  Image(int width, int height, Color background = {255, 255, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  Color at(int x, int y) const;
  void set(int x, int y, Color c);
  // Mixes c into pixel (x, y) with weight alpha in [0, 1]; outside the image nothing happens.
  void blend(int x, int y, Color c, double alpha);
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }  // row-major, 3 bytes a pixel
  std::vector<std::uint8_t>& rgb() { return rgb_; }

  // Copies `other` with its top-left corner at (x, y).
  void paste(const Image& other, int x, int y);

 private:
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> rgb_;
};

void fillRect(Image& img, const Rect& r, Color c);
void strokeRect(Image& img, const Rect& r, Color c);  // one-pixel outline inside r

struct StrokeStyle {
  double width = 2.0;   // pixels
  bool dashed = false;
  double dash = 10.0, gap = 6.0;  // pixels along the line
};

// Draws the connected polyline through `points` (anti-aliased, round joins, no double-darkened
// joins), limited to `clip`.
void strokePolyline(Image& img, const std::vector<Point>& points, Color c, const StrokeStyle& s,
                    const Rect& clip);

// A filled marker of the given size (pixels across) centred at p, limited to `clip`.
void drawMarker(Image& img, Marker m, Point p, double size, Color c, const Rect& clip);

// Text with the markup `^{...}` for a raised superscript drawn one scale smaller (at least 1).
// (x, top) is the top-left corner of the text box of height textHeight(scale).
int markupWidth(const std::string& text, int scale);
void drawText(Image& img, int x, int top, const std::string& text, int scale, Color c);
// The same text turned 90 degrees counter-clockwise (reading upwards); (x, top) is the top-left
// corner of its box of width textHeight(scale) and height markupWidth(text, scale).
void drawTextUp(Image& img, int x, int top, const std::string& text, int scale, Color c);

// Places two images side by side / one above the other (white filling).
Image besideEachOther(const Image& left, const Image& right);
Image aboveEachOther(const Image& top, const Image& bottom);

}  // namespace mesochain::plot
