#pragma once
// The colour names world files may use instead of [r, g, b] triples. Scenario generators use
// the same table, so generated worlds write their colours by name.

#include <array>
#include <optional>
#include <string_view>

#include "core/world.h"

namespace dashbed::core {

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

}  // namespace dashbed::core
