// Rendering and PNG output of plots: file size on disk, where data lands in pixels, bad data,
// bitmap text.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/plot/bitmap_font.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"

using namespace mesochain;
using namespace mesochain::plot;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       (std::string("mesochain_") + info->name() + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const Color kRed{214, 55, 30}, kBlue{0, 90, 181};

bool isWhite(Color c) { return c == Color{255, 255, 255}; }

// Rows (or columns) in which most pixels carry exactly colour c: the frame lines.
std::vector<int> frameRows(const Image& img, Color c) {
  std::vector<int> rows;
  for (int y = 0; y < img.height(); ++y) {
    int n = 0;
    for (int x = 0; x < img.width(); ++x) n += img.at(x, y) == c;
    if (n > img.width() / 2) rows.push_back(y);
  }
  return rows;
}
std::vector<int> frameColumns(const Image& img, Color c) {
  std::vector<int> cols;
  for (int x = 0; x < img.width(); ++x) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y) n += img.at(x, y) == c;
    if (n > img.height() / 2) cols.push_back(x);
  }
  return cols;
}

// How strongly pixel c shows colour `want` over white (1 = pure).
double strength(Color c, Color want) {
  const double d = (255.0 - c.r) + (255.0 - c.g) + (255.0 - c.b);
  const double full = (255.0 - want.r) + (255.0 - want.g) + (255.0 - want.b);
  return d / full;
}

Figure crossFigure() {
  Figure f("A cross");
  f.x.label = "x (nm)";
  f.y.label = "y (zJ)";
  f.add("horizontal", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, {3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3},
        {.color = kBlue});
  f.add("vertical", {4, 4}, {0, 8}, {.color = kRed});
  return f;
}

}  // namespace

TEST(PlotImage, PngWrittenAndReadBackHasTheRequestedSizeAndPixels) {
  const fs::path dir = scratch();
  const Figure f = crossFigure();
  const std::string path = (dir / "cross.png").string();
  f.savePng(path, 900, 600);
  const Image back = readPng(path);
  EXPECT_EQ(back.width(), 900);
  EXPECT_EQ(back.height(), 600);
  EXPECT_EQ(back.rgb(), f.render(900, 600, path).rgb());  // lossless
  const Image small = [&] { f.savePng(path, 420, 300); return readPng(path); }();
  EXPECT_EQ(small.width(), 420);
  EXPECT_EQ(small.height(), 300);
}

TEST(PlotImage, ReadingSomethingElseIsAClearError) {
  const fs::path dir = scratch();
  const std::string path = (dir / "not.png").string();
  std::ofstream(path) << "hello, not a png";
  try {
    readPng(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writePng((dir / "no-such-dir" / "x.png").string(), Image(10, 10)), InputError);
}

TEST(PlotImage, ConstantLinesLandWhereTheAxisMappingPutsThem) {
  const Figure f = crossFigure();
  const Image img = f.render(900, 600);
  const FigureLayout L = f.layout(900, 600);
  // The axis range comes from the tick rule (y data 0..8 -> 0..8; x 0..10 -> 0..10); the frame
  // is found in the picture itself.
  ASSERT_DOUBLE_EQ(L.yTicks.lo, 0.0);
  ASSERT_DOUBLE_EQ(L.yTicks.hi, 8.0);
  ASSERT_DOUBLE_EQ(L.xTicks.lo, 0.0);
  ASSERT_DOUBLE_EQ(L.xTicks.hi, 10.0);
  const Color ink{40, 40, 40};
  const std::vector<int> rows = frameRows(img, ink), cols = frameColumns(img, ink);
  ASSERT_EQ(rows.size(), 2u);
  ASSERT_EQ(cols.size(), 2u);
  const double top = rows[0] + 0.5, bottom = rows[1] + 0.5, left = cols[0] + 0.5, right = cols[1] + 0.5;
  const int expectRow = static_cast<int>(std::floor(top + (8.0 - 3.0) / 8.0 * (bottom - top)));
  const int expectCol = static_cast<int>(std::floor(left + (4.0 - 0.0) / 10.0 * (right - left)));
  // Darkest blue pixel in a column away from the vertical line and the legend.
  const int probeCol = static_cast<int>(left + 0.75 * (right - left));
  int bestRow = -1;
  double best = 0;
  for (int y = rows[0] + 1; y < rows[1]; ++y)
    if (img.at(probeCol, y).b > 150 && strength(img.at(probeCol, y), kBlue) > best) {
      best = strength(img.at(probeCol, y), kBlue);
      bestRow = y;
    }
  EXPECT_GT(best, 0.9);
  EXPECT_NEAR(bestRow, expectRow, 1);
  // The same for the red vertical line, in a row below the horizontal one.
  const int probeRow = static_cast<int>(top + 0.8 * (bottom - top));
  int bestCol = -1;
  best = 0;
  for (int x = cols[0] + 1; x < cols[1]; ++x)
    if (img.at(x, probeRow).r > 150 && strength(img.at(x, probeRow), kRed) > best) {
      best = strength(img.at(x, probeRow), kRed);
      bestCol = x;
    }
  EXPECT_GT(best, 0.9);
  EXPECT_NEAR(bestCol, expectCol, 1);
  // The 2-pixel line is thin: three rows away from the centre the probe column is background.
  EXPECT_LT(strength(img.at(probeCol, bestRow + 3), kBlue), 0.15);
  EXPECT_LT(strength(img.at(probeCol, bestRow - 3), kBlue), 0.15);
}

// The legend never covers data it could avoid: in a free inner corner when there is one,
// otherwise beside the plot (the energies of a relaxation fill every corner: eight series
// from the top to the bottom of the plot).
TEST(PlotImage, LegendGoesBesideThePlotWhenEveryCornerHoldsData) {
  auto lines = [](const std::vector<double>& levels) {
    Figure f("Levels");
    f.y.min = 0.0, f.y.max = 8.0;
    for (std::size_t k = 0; k < levels.size(); ++k)
      f.add("series " + std::to_string(k), {0.0, 10.0}, {levels[k], levels[k]});
    return f;
  };
  // Lines near the top and near the bottom, across the whole width.
  const Figure full = lines({0.3, 0.6, 1.0, 1.4, 6.6, 7.0, 7.4, 7.7});
  const FigureLayout L = full.layout(900, 600);
  ASSERT_TRUE(L.legendOutside);
  EXPECT_GE(L.legend.left, L.plot.right);
  EXPECT_LE(L.legend.right, 900);
  EXPECT_GT(L.plot.right - L.plot.left, 450);
  // Each line is drawn across the plot's whole width, right up to its right edge.
  const Image img = full.render(900, 600);
  for (std::size_t k = 0; k < full.series.size(); ++k) {
    const int row = static_cast<int>(std::floor(L.y.toPixel(full.series[k].y[0])));
    const int col = L.plot.right - 6;
    double best = 0.0;
    for (int y = row - 1; y <= row + 1; ++y) best = std::max(best, strength(img.at(col, y), paletteColor(static_cast<int>(k))));
    EXPECT_GT(best, 0.8) << "series " << k << " at its right end";
  }
  // The same lines only in the lower half: the upper corners are free and hold the legend.
  const Figure lower = lines({0.3, 0.6, 1.0, 1.4, 2.0, 2.4, 2.8, 3.2});
  const FigureLayout M = lower.layout(900, 600);
  EXPECT_FALSE(M.legendOutside);
  EXPECT_GE(M.legend.left, M.plot.left);
  EXPECT_LE(M.legend.right, M.plot.right);
  EXPECT_LT(M.legend.bottom, M.y.toPixel(3.2));
  EXPECT_GT(M.plot.right, L.plot.right);  // the plot keeps its width
}

TEST(PlotImage, LogAxisRefusesNonPositiveDataNamingTheSeries) {
  Figure f;
  f.y.scale = Scale::Log10;
  f.add("max force", {0, 1, 2}, {1e-2, 1e-3, 1e-4});
  f.add("energy change", {0, 1, 2}, {1e-3, 0.0, 1e-6});
  try {
    f.render(600, 400, "relax.png");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("relax.png"), std::string::npos) << m;
    EXPECT_NE(m.find("energy change"), std::string::npos) << m;
    EXPECT_NE(m.find("logarithmic y axis"), std::string::npos) << m;
  }
  f.series.pop_back();
  EXPECT_NO_THROW(f.render(600, 400));
  f.y.min = -1.0;  // a fixed non-positive end is refused too
  EXPECT_THROW(f.render(600, 400), InputError);
}

TEST(PlotImage, MismatchedSeriesIsAnError) {
  Figure f;
  f.add("short", {0, 1, 2}, {1, 2});
  EXPECT_THROW(f.render(), InputError);
}

TEST(PlotImage, NonFinitePointsAreSkippedAndBreakTheLine) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Figure f;
  f.add("with a hole", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10},
        {3, 3, 3, 3, 3, nan, 3, 3, 3, 3, std::numeric_limits<double>::infinity()}, {.color = kBlue});
  f.add("range", {0, 10}, {0, 8}, {.line = false, .color = kRed});
  const Image img = f.render(900, 600);
  const FigureLayout L = f.layout(900, 600);
  EXPECT_DOUBLE_EQ(L.xTicks.hi, 10.0);  // the infinite point does not stretch the axis
  const int row = static_cast<int>(std::floor(L.y.toPixel(3.0)));
  auto blueAt = [&](double x) {
    const Color c = img.at(static_cast<int>(std::floor(L.x.toPixel(x))), row);
    return c.b > 150 && strength(c, kBlue) > 0.8;
  };
  EXPECT_TRUE(blueAt(2.5));
  EXPECT_TRUE(blueAt(7.5));
  EXPECT_FALSE(blueAt(5.0));  // no segment across the NaN
  EXPECT_FALSE(blueAt(4.5));
}

TEST(PlotText, GlyphInkStaysInsideItsBox) {
  Image img(120, 80);
  const int x = 20, top = 30, s = 2;
  drawText(img, x, top, "H", s, {0, 0, 0});
  int inked = 0;
  for (int v = 0; v < img.height(); ++v)
    for (int u = 0; u < img.width(); ++u)
      if (!isWhite(img.at(u, v))) {
        ++inked;
        EXPECT_GE(u, x);
        EXPECT_LT(u, x + kGlyphWidth * s);
        EXPECT_GE(v, top);
        EXPECT_LT(v, top + kGlyphAscent * s);  // a capital has no descender
      }
  EXPECT_GT(inked, 2 * 7 * s * s);  // at least the two stems
  // Left and right stems of the H reach the edges of the box.
  EXPECT_FALSE(isWhite(img.at(x, top)));
  EXPECT_FALSE(isWhite(img.at(x + kGlyphWidth * s - 1, top + kGlyphAscent * s - 1)));
}

TEST(PlotText, DescendersAndWidthsAreAsLaidOut) {
  const int s = 2;
  EXPECT_EQ(textWidth("Hello", s), (5 * kGlyphAdvance - 1) * s);
  EXPECT_EQ(markupWidth("Hello", s), textWidth("Hello", s));
  Image img(200, 60);
  drawText(img, 10, 10, "gy", s, {0, 0, 0});
  bool belowBaseline = false, aboveXHeight = false;
  for (int v = 0; v < img.height(); ++v)
    for (int u = 0; u < img.width(); ++u)
      if (!isWhite(img.at(u, v))) {
        belowBaseline |= v >= 10 + kGlyphAscent * s;
        aboveXHeight |= v < 10 + 2 * s;
        EXPECT_LT(v, 10 + kGlyphHeight * s);
      }
  EXPECT_TRUE(belowBaseline);
  EXPECT_FALSE(aboveXHeight);
  // Turned text occupies the transposed box.
  Image up(60, 200);
  drawTextUp(up, 5, 7, "Hello", s, {0, 0, 0});
  for (int v = 0; v < up.height(); ++v)
    for (int u = 0; u < up.width(); ++u)
      if (!isWhite(up.at(u, v))) {
        EXPECT_GE(u, 5);
        EXPECT_LT(u, 5 + kGlyphHeight * s);
        EXPECT_GE(v, 7);
        EXPECT_LT(v, 7 + markupWidth("Hello", s));
      }
}

TEST(PlotText, EveryPrintableCharacterHasItsOwnGlyph) {
  std::set<std::array<std::uint8_t, 9>> seen;
  for (int c = 33; c <= 126; ++c) {
    const Glyph& g = glyph(static_cast<char>(c));
    int ink = 0;
    for (int r = 0; r < kGlyphHeight; ++r) ink += g.rows[r];
    EXPECT_GT(ink, 0) << static_cast<char>(c);
    EXPECT_TRUE(seen.insert(g.rows).second) << "glyph of '" << static_cast<char>(c) << "' repeats another";
  }
  for (int r = 0; r < kGlyphHeight; ++r) EXPECT_EQ(glyph(' ').rows[r], 0);
}

TEST(PlotText, SuperscriptIsRaisedAndSmaller) {
  const int s = 2;
  EXPECT_LT(markupWidth("10^{-3}", s), textWidth("10-3", s));
  Image img(200, 60);
  drawText(img, 0, 20, "^{3}", s, {0, 0, 0});
  int lowest = -1;
  for (int v = 0; v < img.height(); ++v)
    for (int u = 0; u < img.width(); ++u)
      if (!isWhite(img.at(u, v))) lowest = std::max(lowest, v);
  EXPECT_GE(lowest, 20);
  EXPECT_LT(lowest, 20 + kGlyphAscent * s - 2);  // ends above the baseline
}
