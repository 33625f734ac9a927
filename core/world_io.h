#pragma once
// Reading and writing world files (YAML, format version kWorldFormatVersion; see README).

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/input_text.h"
#include "core/world.h"

namespace dashbed::core {

/// Bad world input. The message starts with "FILE:LINE:COLUMN: FIELD: " and says what is wrong.
class WorldError : public InputError {
 public:
  using InputError::InputError;
};

/// Parses and validates a world from YAML text; `file_name` is used in messages.
/// Checks structure (unknown keys, types, missing fields, non-finite numbers, version),
/// names (duplicates, dangling references) and geometry (overlaps, objects resting on a
/// stable surface). Derives fixture boxes, bin regions and shelf surfaces.
/// Does NOT check reachability (see core/reach.h). Throws WorldError.
World parseWorldYaml(std::string_view yaml_text, const std::string& file_name);

/// Reads a file and calls parseWorldYaml. Throws WorldError (also when the file is unreadable).
World loadWorldFile(const std::filesystem::path& file);

/// Writes a world as YAML that parseWorldYaml reads back to an equal world. Derived elements
/// (fixture boxes, bin regions, shelf surfaces) are not written. Deterministic: same world,
/// same bytes. Numbers are written in their shortest exact form and angles chosen so that
/// they rebuild bit-identical rotations. Throws WorldError if a fixture, object, surface or
/// region pose turns about anything but +z (the format cannot express it).
std::string writeWorldYaml(const World& world);

}  // namespace dashbed::core
