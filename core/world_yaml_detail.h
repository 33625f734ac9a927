#pragma once
// Internal to the world-file reader and writer: names and tables both must agree on.

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "core/colors.h"
#include "core/number_text.h"
#include "core/world.h"

namespace dashbed::core::world_yaml {

/// Shortest decimal text that reads back to exactly x (std::to_chars without precision);
/// YAML's .nan, .inf, -.inf for non-finite values; "0" for -0.
inline std::string formatNumber(double x) {
  if (std::isnan(x)) return ".nan";
  if (std::isinf(x)) return x > 0 ? ".inf" : "-.inf";
  if (x == 0.0) return "0";  // also -0
  return shortestText(x);
}


inline std::string_view fixtureTypeName(FixtureType type) {
  switch (type) {
    case FixtureType::kBox: return "box";
    case FixtureType::kBin: return "bin";
    case FixtureType::kShelf: return "shelf";
  }
  return "box";
}

/// Names of robots, fixtures, surfaces, regions, objects, and model and class names:
/// non-empty, letters, digits, '_', '-', '.' only ('/' is reserved for derived surfaces).
inline bool isIdentifier(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace dashbed::core::world_yaml
