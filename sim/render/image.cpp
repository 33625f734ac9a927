#include "sim/render/image.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace dashbed::render {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// libpng's error callback must not return. Throwing through libpng's C frames is not portable,
// so errors take libpng's own setjmp/longjmp path: the callback records the message and jumps
// back into the small functions below, which hold no objects with destructors.
struct PngErrorState {
  char message[256] = {};
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof(state->message), "%s", message);
  png_longjmp(png, 1);
}

void ignorePngWarning(png_structp, png_const_charp) {}

// Returns false (message in `error`) when libpng fails.
bool encodePng(std::FILE* out, const Image& image, PngErrorState& error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, onPngError, ignorePngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, out);
  // fixed settings, so the bytes depend on the pixels only (libpng writes no time stamp
  // unless asked); for rendered frames (large flat areas) zlib level 2 without row filters
  // is about six times faster than libpng's defaults for a file about 10 % larger
  png_set_compression_level(png, 2);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) png_write_row(png, image.pixel(0, y));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// Decodes into `image` (already default-constructed); false (message in `error`) on failure.
bool decodePng(std::FILE* in, Image& image, std::vector<png_bytep>& rows, PngErrorState& error) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, onPngError, ignorePngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, in);
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  // normalise every colour type to 8-bit RGB
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_set_packing(png);
  png_set_palette_to_rgb(png);
  png_set_expand_gray_1_2_4_to_8(png);
  png_set_gray_to_rgb(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (png_get_rowbytes(png, info) != static_cast<png_size_t>(width) * 3) {
    std::snprintf(error.message, sizeof(error.message), "unsupported pixel layout");
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  // the pixel storage belongs to the caller's objects, so a later jump leaks nothing
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  rows.resize(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.pixel(0, static_cast<int>(y));
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

Image Image::filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  if (width < 0 || height < 0) throw std::invalid_argument("Image::filled: negative size");
  Image image{width, height, {}};
  image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = r;
    image.rgb[i + 1] = g;
    image.rgb[i + 2] = b;
  }
  return image;
}

void writePng(const Image& image, const std::filesystem::path& file) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw std::invalid_argument("writePng: " + file.string() + ": image size and pixel data disagree");
  }
  const std::string name = file.string();
  FilePtr out(std::fopen(name.c_str(), "wb"));
  if (!out) throw std::runtime_error(name + ": cannot open for writing");
  PngErrorState error;
  if (!encodePng(out.get(), image, error)) throw std::runtime_error(name + ": PNG error: " + error.message);
  if (std::fclose(out.release()) != 0) throw std::runtime_error(name + ": write failed");
}

Image readPng(const std::filesystem::path& file) {
  const std::string name = file.string();
  FilePtr in(std::fopen(name.c_str(), "rb"));
  if (!in) throw std::runtime_error(name + ": cannot open for reading");
  png_byte signature[8];
  if (std::fread(signature, 1, 8, in.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
    throw std::runtime_error(name + ": not a PNG file");
  }
  Image image;
  std::vector<png_bytep> rows;
  PngErrorState error;
  if (!decodePng(in.get(), image, rows, error)) throw std::runtime_error(name + ": PNG error: " + error.message);
  return image;
}

}  // namespace dashbed::render
