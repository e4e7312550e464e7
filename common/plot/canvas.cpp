#include "common/plot/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/plot/bitmap_font.hpp"

namespace mesochain::plot {

Image::Image(int width, int height, Color background) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("plot::Image: non-positive size");
  rgb_.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = background.r;
    rgb_[i + 1] = background.g;
    rgb_[i + 2] = background.b;
  }
}

Color Image::at(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * width_ + x) * 3;
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void Image::set(int x, int y, Color c) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  const std::size_t i = (static_cast<std::size_t>(y) * width_ + x) * 3;
  rgb_[i] = c.r;
  rgb_[i + 1] = c.g;
  rgb_[i + 2] = c.b;
}

void Image::blend(int x, int y, Color c, double alpha) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || !(alpha > 0.0)) return;
  alpha = std::min(alpha, 1.0);
  const std::size_t i = (static_cast<std::size_t>(y) * width_ + x) * 3;
  auto mix = [alpha](std::uint8_t old, std::uint8_t add) {
    return static_cast<std::uint8_t>(std::lround(old + alpha * (add - old)));
  };
  rgb_[i] = mix(rgb_[i], c.r);
  rgb_[i + 1] = mix(rgb_[i + 1], c.g);
  rgb_[i + 2] = mix(rgb_[i + 2], c.b);
}

void Image::paste(const Image& other, int x, int y) {
  for (int v = 0; v < other.height(); ++v)
    for (int u = 0; u < other.width(); ++u) set(x + u, y + v, other.at(u, v));
}

void fillRect(Image& img, const Rect& r, Color c) {
  for (int y = std::max(0, r.top); y < std::min(img.height(), r.bottom); ++y)
    for (int x = std::max(0, r.left); x < std::min(img.width(), r.right); ++x) img.set(x, y, c);
}

void strokeRect(Image& img, const Rect& r, Color c) {
  for (int x = r.left; x < r.right; ++x) {
    img.set(x, r.top, c);
    img.set(x, r.bottom - 1, c);
  }
  for (int y = r.top; y < r.bottom; ++y) {
    img.set(r.left, y, c);
    img.set(r.right - 1, y, c);
  }
}

namespace {

// Coverage (0..1) of the pixels of `clip`, combined by maximum so that overlapping pieces of one
// stroke do not darken each other; composited once at the end.
class CoverageMask {
 public:
  explicit CoverageMask(const Rect& clip)
      : clip_(clip), w_(std::max(0, clip.right - clip.left)), h_(std::max(0, clip.bottom - clip.top)),
        a_(static_cast<std::size_t>(w_) * h_, 0.0f) {}

  void cover(int x, int y, double alpha) {
    const int u = x - clip_.left, v = y - clip_.top;
    if (u < 0 || v < 0 || u >= w_ || v >= h_ || !(alpha > 0)) return;
    float& a = a_[static_cast<std::size_t>(v) * w_ + u];
    a = std::max(a, static_cast<float>(std::min(alpha, 1.0)));
  }

  // Round-capped segment a-b of the given width; coverage falls off over one pixel.
  void segment(Point a, Point b, double width) {
    const double r = 0.5 * width + 0.5;
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    auto distance = [&](double px, double py) {
      double t = len2 > 0 ? ((px - a.x) * dx + (py - a.y) * dy) / len2 : 0.0;
      t = std::clamp(t, 0.0, 1.0);
      return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
    };
    const bool flat = std::abs(dx) >= std::abs(dy);
    // Walk the major axis; on each line of pixels only a band around the segment is visited.
    const double lo = (flat ? std::min(a.x, b.x) : std::min(a.y, b.y)) - r - 1;
    const double hi = (flat ? std::max(a.x, b.x) : std::max(a.y, b.y)) + r + 1;
    const double slope = flat ? (dx != 0 ? dy / dx : 0) : (dy != 0 ? dx / dy : 0);
    const double band = r * std::sqrt(1 + slope * slope) + 1.5;
    // Clamped in floating point first: far-away points must not overflow an int.
    const double clipMajorLo = flat ? clip_.left : clip_.top, clipMajorHi = flat ? clip_.right : clip_.bottom;
    const double clipMinorLo = flat ? clip_.top : clip_.left, clipMinorHi = flat ? clip_.bottom : clip_.right;
    const int majorLo = static_cast<int>(std::clamp(std::floor(lo), clipMajorLo, clipMajorHi));
    const int majorHi = static_cast<int>(std::clamp(std::ceil(hi), clipMajorLo, clipMajorHi));
    for (int m = majorLo; m < majorHi; ++m) {
      const double c = m + 0.5;
      const double start = flat ? a.x : a.y, extent = flat ? dx : dy;
      const double t = extent != 0 ? std::clamp((c - start) / extent, 0.0, 1.0) : 0.0;
      const double minorCentre = flat ? a.y + t * dy : a.x + t * dx;
      const int nLo = static_cast<int>(std::clamp(std::floor(minorCentre - band), clipMinorLo - 1, clipMinorHi));
      const int nHi = static_cast<int>(std::clamp(std::ceil(minorCentre + band), clipMinorLo - 1, clipMinorHi));
      for (int n = nLo; n <= nHi; ++n) {
        const int x = flat ? m : n, y = flat ? n : m;
        cover(x, y, r - distance(x + 0.5, y + 0.5));
      }
    }
  }

  void composite(Image& img, Color c) const {
    for (int v = 0; v < h_; ++v)
      for (int u = 0; u < w_; ++u) {
        const float a = a_[static_cast<std::size_t>(v) * w_ + u];
        if (a > 0) img.blend(clip_.left + u, clip_.top + v, c, a);
      }
  }

 private:
  Rect clip_;
  int w_, h_;
  std::vector<float> a_;
};

Point along(Point a, Point b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

}  // namespace

void strokePolyline(Image& img, const std::vector<Point>& points, Color c, const StrokeStyle& s,
                    const Rect& clip) {
  const Rect inside{std::max(clip.left, 0), std::max(clip.top, 0), std::min(clip.right, img.width()),
                    std::min(clip.bottom, img.height())};
  if (points.empty() || inside.right <= inside.left || inside.bottom <= inside.top) return;
  CoverageMask mask(inside);
  if (points.size() == 1) mask.segment(points[0], points[0], s.width);
  const double period = s.dash + s.gap;
  double travelled = 0.0;  // along the polyline, for the dash pattern
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point a = points[i - 1], b = points[i];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    if (!s.dashed || period <= 0 || len == 0) {
      mask.segment(a, b, s.width);
    } else {
      double pos = 0.0;  // along this segment
      while (pos < len) {
        const double phase = std::fmod(travelled + pos, period);
        const bool on = phase < s.dash;
        const double next = std::min(len, pos + (on ? s.dash - phase : period - phase));
        if (on) mask.segment(along(a, b, pos / len), along(a, b, next / len), s.width);
        pos = next;
      }
    }
    travelled += len;
  }
  mask.composite(img, c);
}

void drawMarker(Image& img, Marker m, Point p, double size, Color c, const Rect& clip) {
  if (m == Marker::None) return;
  const double h = 0.5 * size;
  if (!(p.x > clip.left - h - 1 && p.x < clip.right + h + 1 && p.y > clip.top - h - 1 &&
        p.y < clip.bottom + h + 1))
    return;  // wholly outside (also keeps far-away coordinates out of int conversions)
  auto inside = [m, h](double u, double v) {  // u, v relative to the centre, v downwards
    switch (m) {
      case Marker::Circle: return u * u + v * v <= h * h;
      case Marker::Square: return std::abs(u) <= 0.85 * h && std::abs(v) <= 0.85 * h;
      case Marker::Diamond: return std::abs(u) + std::abs(v) <= 1.1 * h;
      case Marker::Triangle: {  // apex up, centroid at the centre
        const double top = -h, bottom = 0.75 * h;
        if (v < top || v > bottom) return false;
        return std::abs(u) <= (v - top) / (bottom - top) * 1.05 * h;
      }
      case Marker::Cross: {
        if (std::abs(u) > h || std::abs(v) > h) return false;
        const double t = std::max(1.0, 0.2 * h);
        return std::abs(u - v) <= t * 1.2 || std::abs(u + v) <= t * 1.2;
      }
      case Marker::None: break;
    }
    return false;
  };
  constexpr int kSub = 4;  // 4 x 4 samples per pixel
  for (int y = static_cast<int>(std::floor(p.y - h - 1)); y <= static_cast<int>(p.y + h + 1); ++y)
    for (int x = static_cast<int>(std::floor(p.x - h - 1)); x <= static_cast<int>(p.x + h + 1); ++x) {
      if (!clip.contains(x, y)) continue;
      int hits = 0;
      for (int i = 0; i < kSub; ++i)
        for (int j = 0; j < kSub; ++j)
          hits += inside(x + (i + 0.5) / kSub - p.x, y + (j + 0.5) / kSub - p.y);
      if (hits) img.blend(x, y, c, static_cast<double>(hits) / (kSub * kSub));
    }
}

namespace {

struct Run {
  std::string text;
  bool superscript = false;
};

std::vector<Run> parseMarkup(const std::string& text) {
  std::vector<Run> runs(1);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "^{") == 0) {
      const std::size_t end = text.find('}', i + 2);
      if (end != std::string::npos) {
        runs.push_back({text.substr(i + 2, end - i - 2), true});
        runs.push_back({});
        i = end;
        continue;
      }
    }
    runs.back().text += text[i];
  }
  return runs;
}

int superscriptScale(int scale) { return std::max(1, scale - 1); }

// Calls ink(x, y) for every ink pixel of the text laid out from (0, 0).
template <class Ink>
int layOut(const std::string& text, int scale, Ink&& ink) {
  int pen = 0, lastScale = scale;
  for (const Run& run : parseMarkup(text)) {
    const int s = run.superscript ? superscriptScale(scale) : scale;
    // A superscript's baseline sits a little above the middle of the capitals, inside the box.
    const int top =
        run.superscript ? std::max(0, kGlyphAscent * scale / 2 - kGlyphAscent * s + scale) : 0;
    for (char ch : run.text) {
      const Glyph& g = glyph(ch);
      for (int r = 0; r < kGlyphHeight; ++r)
        for (int col = 0; col < kGlyphWidth; ++col)
          if (g.ink(col, r))
            for (int dy = 0; dy < s; ++dy)
              for (int dx = 0; dx < s; ++dx) ink(pen + col * s + dx, top + r * s + dy);
      pen += kGlyphAdvance * s;
      lastScale = s;
    }
  }
  return pen > 0 ? pen - lastScale : 0;
}

}  // namespace

int markupWidth(const std::string& text, int scale) {
  return layOut(text, scale, [](int, int) {});
}

void drawText(Image& img, int x, int top, const std::string& text, int scale, Color c) {
  layOut(text, scale, [&](int u, int v) { img.set(x + u, top + v, c); });
}

void drawTextUp(Image& img, int x, int top, const std::string& text, int scale, Color c) {
  const int w = markupWidth(text, scale);
  layOut(text, scale, [&](int u, int v) { img.set(x + v, top + (w - 1 - u), c); });
}

Image besideEachOther(const Image& left, const Image& right) {
  Image out(left.width() + right.width(), std::max(left.height(), right.height()));
  out.paste(left, 0, 0);
  out.paste(right, left.width(), 0);
  return out;
}

Image aboveEachOther(const Image& top, const Image& bottom) {
  Image out(std::max(top.width(), bottom.width()), top.height() + bottom.height());
  out.paste(top, 0, 0);
  out.paste(bottom, 0, top.height());
  return out;
}

}  // namespace mesochain::plot
