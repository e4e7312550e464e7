#include "common/plot/png_io.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"

namespace mesochain::plot {

namespace {
struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors by longjmp to the setjmp point of the calling function. The functions
// holding a setjmp below keep only trivially destructible locals, so the jump skips no
// destructor; the message is kept for the InputError thrown afterwards.
struct ErrorSink {
  char message[256] = "unknown libpng error";
};
void onError(png_structp png, png_const_charp message) {
  auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message);
  png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}

bool encode(png_structp png, png_infop info, std::FILE* f, const Image& img) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, f);
  png_set_IHDR(png, info, img.width(), img.height(), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(img.width()) * 3;
  for (int y = 0; y < img.height(); ++y) png_write_row(png, img.rgb().data() + y * stride);
  png_write_end(png, nullptr);
  return true;
}

bool decodeHeader(png_structp png, png_infop info, std::FILE* f, int* w, int* h) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, f);
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  // Every colour type and depth becomes 8-bit RGB.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_set_gray_to_rgb(png);
  png_read_update_info(png, info);
  *w = static_cast<int>(png_get_image_width(png, info));
  *h = static_cast<int>(png_get_image_height(png, info));
  return png_get_rowbytes(png, info) == static_cast<png_size_t>(*w) * 3;
}

bool decodeRows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}
}  // namespace

void writePng(const std::string& path, const Image& img) {
  // Encoded into a temporary file beside `path`, renamed over it when complete.
  AtomicOutputFile out(path);
  out.stream().close();
  File f(std::fopen(out.temporaryPath().c_str(), "wb"));
  if (!f) throw InputError(path, "", "a PNG file that cannot be opened for writing", "a writable path");
  ErrorSink sink;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, onError, onWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && encode(png, info, f.get(), img);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw InputError(path, std::string("writing the PNG failed: ") + sink.message);
  if (std::fclose(f.release()) != 0)
    throw InputError(path, "", "a PNG file that could not be written completely", "a writable path");
  out.commit();
}

Image readPng(const std::string& path) {
  File f(std::fopen(path.c_str(), "rb"));
  if (!f) throw InputError(path, "", "a file that cannot be opened", "a readable PNG file");
  unsigned char signature[8] = {};
  if (std::fread(signature, 1, 8, f.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
    throw InputError(path, "", "a file without the PNG signature", "a PNG file");
  ErrorSink sink;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &sink, onError, onWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  int w = 0, h = 0;
  bool ok = info && decodeHeader(png, info, f.get(), &w, &h) && w > 0 && h > 0;
  Image img;
  if (ok) {
    img = Image(w, h);
    std::vector<png_bytep> rows(h);
    for (int y = 0; y < h; ++y) rows[y] = img.rgb().data() + static_cast<std::size_t>(y) * w * 3;
    ok = decodeRows(png, rows.data());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (!ok) throw InputError(path, std::string("reading the PNG failed: ") + sink.message);
  return img;
}

}  // namespace mesochain::plot
