#pragma once
// mesochain's own 5x9 bitmap font for printable ASCII (32..126): 5 columns, 7 rows from the
// cap line to the baseline plus 2 descender rows. Drawn at an integer scale (no anti-aliasing).
#include <array>
#include <cstdint>
#include <string>

namespace mesochain::plot {

struct Glyph {
  // rows[r] bit c (c = 0 is the leftmost column, bit 4) is ink at column c of row r.
  std::array<std::uint8_t, 9> rows{};
  bool ink(int column, int row) const { return (rows[row] >> (4 - column)) & 1u; }
};

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 9;      // including the descender rows
constexpr int kGlyphAscent = 7;      // rows above the baseline
constexpr int kGlyphAdvance = 6;     // glyph width plus one column of spacing

// The glyph of character c; characters outside 32..126 are drawn as '?'.
const Glyph& glyph(char c);

// Width and height in pixels of `text` drawn at `scale` (one line, no markup).
int textWidth(const std::string& text, int scale);
inline int textHeight(int scale) { return kGlyphHeight * scale; }

}  // namespace mesochain::plot
