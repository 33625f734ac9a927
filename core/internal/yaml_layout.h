#pragma once
// Internal to the world-file reader: where a YAML text nests and where it uses aliases, from
// yaml-cpp's event stream. yaml-cpp's tree gives an alias the anchor's position, and a
// document nested too deep only a bare "bad file"; these put both at their own line.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace dashbed::core::world_yaml {

/// A 0-based position as yaml-cpp counts it.
struct TextMark {
  int line = 0;
  int column = 0;
  int offset = 0;  ///< in bytes from the start of the text
};

/// One use of an alias (`*name`): the field path it stands at ("robots[1].base"), where it is
/// written, and the anchor it repeats.
struct AliasUse {
  std::string path;
  TextMark mark;
  std::string anchor;
  TextMark anchor_mark;
};

/// What scanYamlLayout found.
struct YamlLayout {
  std::vector<AliasUse> aliases;  ///< in the first document
  bool too_deep = false;          ///< nesting went past the limit at `too_deep_mark`
  TextMark too_deep_mark;
  std::size_t documents = 0;  ///< 0, 1, or 2 for "more than one"
  TextMark second_document;   ///< where the second document starts
};

/// Scans `text` (paths as the world reader writes them: "a.b[2].c"), stopping at the first
/// sequence or map nested deeper than `max_depth` or at the start of a second document.
/// Throws YAML::Exception on a syntax error before that. (yaml-cpp's LoadAll never returns on
/// a ',' outside a flow collection at the start of a document: it finds one empty document
/// there after another. Stopping at the second document avoids that.)
YamlLayout scanYamlLayout(std::string_view text, std::size_t max_depth);

/// The alias use whose path is `path` or contains it ("a.b" contains "a.b.c" and "a.b[0]"),
/// or nullptr.
const AliasUse* aliasAbove(const YamlLayout& layout, std::string_view path);

}  // namespace dashbed::core::world_yaml
