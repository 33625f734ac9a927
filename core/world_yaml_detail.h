#pragma once
// Internal to the world-file reader and writer: names and tables both must agree on.

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "core/world.h"

namespace dashbed::core::world_yaml {

/// Shortest decimal text that reads back to exactly x (std::to_chars without precision);
/// YAML's .nan, .inf, -.inf for non-finite values; "0" for -0.
inline std::string formatNumber(double x) {
  if (std::isnan(x)) return ".nan";
  if (std::isinf(x)) return x > 0 ? ".inf" : "-.inf";
  if (x == 0.0) return "0";  // also -0
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), x);
  if (ec != std::errc()) return "0";  // cannot happen: 32 chars hold any double
  return std::string(buffer, end);
}

struct NamedColor {
  std::string_view name;
  Color color;
};

/// The colour names a world file may use instead of [r, g, b].
inline constexpr std::array<NamedColor, 12> kNamedColors{{
    {"red", {0.85, 0.15, 0.15}},
    {"green", {0.2, 0.7, 0.2}},
    {"blue", {0.15, 0.3, 0.85}},
    {"yellow", {0.95, 0.85, 0.1}},
    {"orange", {1.0, 0.55, 0.0}},
    {"purple", {0.55, 0.2, 0.75}},
    {"cyan", {0.1, 0.8, 0.85}},
    {"magenta", {0.9, 0.2, 0.7}},
    {"white", {1.0, 1.0, 1.0}},
    {"black", {0.0, 0.0, 0.0}},
    {"grey", {0.5, 0.5, 0.5}},
    {"brown", {0.55, 0.35, 0.2}},
}};

inline std::optional<Color> colorByName(std::string_view name) {
  for (const NamedColor& named : kNamedColors) {
    if (named.name == name) return named.color;
  }
  return std::nullopt;
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
