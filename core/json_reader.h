#pragma once
// Reading JSON files that someone else may have written (plans, reports, stress outcomes):
// parsing that refuses duplicate keys and absurd nesting and says where the text is broken,
// and type-checked access that fails with "FILE: POINTER: what" (RFC 6901 pointers).

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/input_text.h"
#include "core/json_pointer.h"

namespace dashbed::core {

/// Nesting deeper than this is refused while parsing: a value that deep would be copied and
/// destroyed recursively, overflowing the stack. No dashbed file comes near it.
inline constexpr std::size_t kMaxJsonNesting = 256;

/// What is wrong where in a JSON text: a pointer ("" the root) and the problem.
struct JsonProblem {
  std::string pointer;
  std::string what;
};

/// Parses `text` into nlohmann::json (keys sorted) or nlohmann::ordered_json (keys in the
/// text's order). Throws JsonProblem for a syntax error (with line and column), a number out
/// of range, a key given twice in one object, or nesting deeper than kMaxJsonNesting.
template <class Json>
Json parseJsonText(std::string_view text);

/// "a string", "an object", "null", ...: what a value is, for messages.
template <class Json>
std::string describeJsonValue(const Json& value);

/// "a, b, c" of `names`.
std::string listOfNames(std::initializer_list<std::string_view> names);

/// Type-checked access to one document of `file`; every failure throws Error (constructible
/// from a string) with the message "FILE: POINTER: what" ("<memory>" for an empty file name).
template <class Error, class JsonType = nlohmann::json>
class JsonReader {
 public:
  using Json = JsonType;

  explicit JsonReader(const std::string& file) : file_(file.empty() ? "<memory>" : file) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw Error(core::SourceLocation{file_}, pointer.empty() ? "/" : pointer, what);
  }

  /// parseJsonText, failing as above.
  Json parse(std::string_view text) const {
    try {
      return parseJsonText<Json>(text);
    } catch (const JsonProblem& problem) {
      fail(problem.pointer, problem.what);
    }
  }

  void expectType(const Json& value, const std::string& pointer, bool ok, std::string_view expected) const {
    if (!ok) fail(pointer, "expected " + std::string(expected) + ", got " + describeJsonValue(value));
  }

  /// Checks the format version member `key` of a dashbed file of `kind` ("plan", "report"):
  /// missing (not such a file), not an integer, or another version than `version`.
  void formatVersion(const Json& document, std::string_view key, int version, std::string_view kind) const {
    const std::string pointer = jsonPointerAt("", key);
    std::string expected = "\"";  // appended: GCC 12 warns falsely on "literal" + std::string here
    expected.append(key).append("\": ").append(std::to_string(version));
    const auto found = document.find(key);
    if (found == document.end()) fail(pointer, "missing: not a dashbed " + std::string(kind) + " (expected " + expected + ")");
    if (!found->is_number_integer()) {
      fail(pointer, "expected the integer " + std::to_string(version) + ", got " + describeJsonValue(*found) + " " +
                        found->dump(-1, ' ', false, Json::error_handler_t::replace));
    }
    if (found->template get<std::int64_t>() != version) {
      fail(pointer, "unsupported " + std::string(kind) + " format version " + found->dump() +
                        " (this build reads version " + std::to_string(version) + ")");
    }
  }

  /// An object whose keys are all in `allowed`.
  void expectObject(const Json& value, const std::string& pointer,
                    std::initializer_list<std::string_view> allowed) const {
    expectType(value, pointer, value.is_object(), "an object");
    for (const auto& [key, member] : value.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(jsonPointerAt(pointer, key), "unknown key (expected " + listOfNames(allowed) + ")");
      }
    }
  }

  /// The member `key` of the object at `pointer`; `context` says why it is needed.
  const Json& required(const Json& object, const std::string& pointer, std::string_view key,
                       std::string_view context = {}) const {
    expectType(object, pointer, object.is_object(), "an object");
    const auto it = object.find(key);
    if (it == object.end()) {
      fail(jsonPointerAt(pointer, key), context.empty() ? "missing" : "missing (" + std::string(context) + ")");
    }
    return *it;
  }

  /// The member `key`, or null when absent.
  const Json* optional(const Json& object, std::string_view key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  double number(const Json& value, const std::string& pointer) const {
    expectType(value, pointer, value.is_number(), "a number");
    return value.template get<double>();
  }
  std::string string(const Json& value, const std::string& pointer) const {
    expectType(value, pointer, value.is_string(), "a string");
    return value.template get<std::string>();
  }
  bool boolean(const Json& value, const std::string& pointer) const {
    expectType(value, pointer, value.is_boolean(), "true or false");
    return value.template get<bool>();
  }
  std::uint64_t unsignedInteger(const Json& value, const std::string& pointer) const {
    if (!value.is_number_unsigned()) {
      fail(pointer, "expected a non-negative integer, got " + (value.is_number() ? value.dump() : describeJsonValue(value)));
    }
    return value.template get<std::uint64_t>();
  }
  const Json& array(const Json& value, const std::string& pointer) const {
    expectType(value, pointer, value.is_array(), "an array");
    return value;
  }

  // the same for a required member `key` of the object at `pointer`
  double number(const Json& object, const std::string& pointer, std::string_view key) const {
    return number(required(object, pointer, key), jsonPointerAt(pointer, key));
  }
  std::string string(const Json& object, const std::string& pointer, std::string_view key) const {
    return string(required(object, pointer, key), jsonPointerAt(pointer, key));
  }
  bool boolean(const Json& object, const std::string& pointer, std::string_view key) const {
    return boolean(required(object, pointer, key), jsonPointerAt(pointer, key));
  }
  std::uint64_t unsignedInteger(const Json& object, const std::string& pointer, std::string_view key) const {
    return unsignedInteger(required(object, pointer, key), jsonPointerAt(pointer, key));
  }
  const Json& array(const Json& object, const std::string& pointer, std::string_view key) const {
    return array(required(object, pointer, key), jsonPointerAt(pointer, key));
  }

 private:
  std::string file_;
};

}  // namespace dashbed::core
