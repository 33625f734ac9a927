#pragma once
// Numbers as text, independent of the locale (std::to_chars): for file writers and messages.

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>

namespace dashbed::core {

/// `format` applied to a finite x; "nan", "inf", "-inf" otherwise.
template <typename Format>
std::string numberText(double x, Format&& format) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[64];
  const std::to_chars_result result = format(buffer, buffer + sizeof(buffer), x);
  return result.ec == std::errc() ? std::string(buffer, result.ptr) : "?";
}

/// The shortest text that reads back to exactly x.
inline std::string shortestText(double x) {
  return numberText(x, [](char* first, char* last, double v) { return std::to_chars(first, last, v); });
}

/// `digits` significant digits (%g style).
inline std::string significantText(double x, int digits) {
  return numberText(x, [digits](char* first, char* last, double v) {
    return std::to_chars(first, last, v, std::chars_format::general, digits);
  });
}

/// `decimals` digits after the point, never an exponent.
inline std::string fixedText(double x, int decimals) {
  return numberText(x, [decimals](char* first, char* last, double v) {
    return std::to_chars(first, last, v, std::chars_format::fixed, decimals);
  });
}

}  // namespace dashbed::core
