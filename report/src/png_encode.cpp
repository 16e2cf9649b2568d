// encode_png: libpng writing into memory. libpng reports errors by longjmp, so nothing with a
// destructor is created between setjmp and the end of the write.

#include "meshprep/report/surface_picture.h"

#include "meshprep/core/errors.h"

#include <png.h>

#include <csetjmp>

namespace meshprep {
namespace {

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void no_flush(png_structp) {}

// Returns false if libpng failed (it longjmps back here).
bool write_png(const RgbImage& image, std::vector<std::uint8_t>& out, std::vector<png_bytep>& rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, &out, append, no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const RgbImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != std::size_t(3) * std::size_t(image.width) * std::size_t(image.height))
    throw InvalidInput("encode_png: the pixel buffer does not match the image size");
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (std::size_t y = 0; y < rows.size(); ++y)
    rows[y] = const_cast<png_bytep>(image.rgb.data() + 3 * y * std::size_t(image.width));  // libpng only reads
  std::vector<std::uint8_t> out;
  if (!write_png(image, out, rows)) throw Error("encode_png: libpng could not write the image");
  return out;
}

}  // namespace meshprep
