#pragma once
// PNG files through libpng: 8-bit RGB, no interlacing.
#include <string>

#include "common/plot/canvas.hpp"

namespace mesochain::plot {

// Writes img to path; throws mesochain::InputError naming the path when it cannot be written.
void writePng(const std::string& path, const Image& img);

// Reads a PNG (any bit depth or colour type, converted to 8-bit RGB); throws InputError naming
// the path when the file is missing or is not a PNG.
Image readPng(const std::string& path);

}  // namespace mesochain::plot
