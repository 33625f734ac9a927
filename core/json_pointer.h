#pragma once
// Building RFC 6901 JSON pointers for error messages ("/robots/0/points/3/t").

#include <cstddef>
#include <string>
#include <string_view>

namespace dashbed::core {

/// `pointer` extended by an object key ('~' and '/' escaped as ~0 and ~1).
inline std::string jsonPointerAt(const std::string& pointer, std::string_view key) {
  std::string out = pointer + "/";
  for (const char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

/// `pointer` extended by an array index.
inline std::string jsonPointerAt(const std::string& pointer, std::size_t index) {
  return pointer + "/" + std::to_string(index);
}

}  // namespace dashbed::core
