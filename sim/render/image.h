#pragma once
// Image: an 8-bit RGB raster, and PNG files of it.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace dashbed::render {

/// An 8-bit RGB image, rows top to bottom, each row left to right, 3 bytes per pixel.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes

  /// A width x height image filled with one colour. Throws std::invalid_argument for a
  /// negative size.
  static Image filled(int width, int height, std::uint8_t r = 0, std::uint8_t g = 0, std::uint8_t b = 0);

  /// Pointer to the three bytes of pixel (x, y), x to the right, y down. No bounds check.
  std::uint8_t* pixel(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
  const std::uint8_t* pixel(int x, int y) const {
    return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3;
  }
  bool operator==(const Image&) const = default;
};

/// Writes `image` as an 8-bit RGB PNG. The bytes depend on the pixels only (no time stamp,
/// fixed zlib level and filters), so equal images give equal files. Throws std::runtime_error
/// naming the file if it cannot be written, std::invalid_argument for an inconsistent image.
void writePng(const Image& image, const std::filesystem::path& file);

/// Reads a PNG (any bit depth or colour type; alpha is dropped, grey expanded) into 8-bit RGB.
/// Throws std::runtime_error naming the file on any problem.
Image readPng(const std::filesystem::path& file);

}  // namespace dashbed::render
