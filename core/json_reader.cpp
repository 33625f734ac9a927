#include "core/json_reader.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <unordered_set>
#include <vector>

#include "core/input_text.h"

namespace dashbed::core {
namespace {

// nlohmann's message without its "[json.exception.parse_error.101] " prefix
std::string withoutExceptionId(const std::string& what) {
  if (what.rfind("[json.exception.", 0) == 0) {
    const std::size_t close = what.find("] ");
    if (close != std::string::npos) return what.substr(close + 2);
  }
  return what;
}

/// Thrown by the parser's callback at the first value nested deeper than kMaxJsonNesting.
struct TooDeep {};

// Byte offset of the first '[' or '{' (outside strings) that opens level `depth` + 1.
std::size_t offsetBeyondDepth(std::string_view text, std::size_t depth) {
  std::size_t level = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++level > depth) return i;
    } else if (c == ']' || c == '}') {
      if (level > 0) --level;
    }
  }
  return text.size();
}

// A first pass over the text with nlohmann's SAX interface, without building anything: finds
// the first key that occurs twice in one object (nlohmann keeps the last silently) and refuses
// nesting deeper than kMaxJsonNesting (throws TooDeep) before the document is built by a
// recursive parser. Syntax errors are rethrown as nlohmann's own exceptions. (nlohmann's parser
// callback would do the same in one pass, but it rescans the parent array at every object's
// end: quadratic in the length of an array of objects, such as a plan's points.)
template <class Json>
class StructureCheck {
 public:
  using number_integer_t = typename Json::number_integer_t;
  using number_unsigned_t = typename Json::number_unsigned_t;
  using number_float_t = typename Json::number_float_t;
  using string_t = typename Json::string_t;
  using binary_t = typename Json::binary_t;

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(number_integer_t) { return value(); }
  bool number_unsigned(number_unsigned_t) { return value(); }
  bool number_float(number_float_t, const string_t&) { return value(); }
  bool string(string_t&) { return value(); }
  bool binary(binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(true); }
  bool start_array(std::size_t) { return open(false); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(string_t& key) {
    Frame& frame = frames_.back();
    frame.key = key;
    if (!frame.keys.insert(key).second && !duplicate_) duplicate_ = pointer();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) {
    if (const auto* syntax = dynamic_cast<const typename Json::parse_error*>(&error)) throw *syntax;
    if (const auto* range = dynamic_cast<const typename Json::out_of_range*>(&error)) throw *range;
    throw std::runtime_error(error.what());
  }

  const std::optional<std::string>& duplicate() const { return duplicate_; }

 private:
  struct Frame {
    bool is_object = true;
    std::unordered_set<std::string> keys;
    std::string key;        // objects: the current key
    std::size_t index = 0;  // arrays: the current element
  };

  bool value() {
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
    return true;
  }
  bool open(bool is_object) {
    if (frames_.size() >= kMaxJsonNesting) throw TooDeep{};
    frames_.push_back({is_object, {}, {}, 0});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return value();
  }

  std::string pointer() const {
    std::string text;
    for (const Frame& frame : frames_) {
      text = frame.is_object ? jsonPointerAt(text, frame.key) : jsonPointerAt(text, frame.index);
    }
    return text;
  }

  std::vector<Frame> frames_;
  std::optional<std::string> duplicate_;
};

}  // namespace

template <class Json>
Json parseJsonText(std::string_view text) {
  if (const std::optional<TextProblem> problem = findTextProblem(text)) {
    throw JsonProblem{"", "line " + std::to_string(problem->line) + ", column " + std::to_string(problem->column) +
                              ": " + problem->what};
  }
  StructureCheck<Json> check;
  Json document;
  try {
    Json::sax_parse(text.begin(), text.end(), &check);
    if (check.duplicate()) throw JsonProblem{*check.duplicate(), "duplicate key"};
    document = Json::parse(text.begin(), text.end());
  } catch (const typename Json::parse_error& error) {
    // nlohmann's message has line and column; add the byte offset
    throw JsonProblem{"", "invalid JSON: " + withoutExceptionId(error.what()) + " (byte " +
                              std::to_string(error.byte) + ")"};
  } catch (const typename Json::exception& error) {
    // e.g. "number overflow parsing '1e400'": locate the quoted literal in the text
    std::string what = withoutExceptionId(error.what());
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    if (open != std::string::npos && close > open + 1) {
      const std::size_t found = text.find(what.substr(open + 1, close - open - 1));
      if (found != std::string_view::npos) what += " at " + lineAndColumn(text, found);
    }
    throw JsonProblem{"", "invalid JSON: " + what};
  } catch (const TooDeep&) {
    throw JsonProblem{"", lineAndColumn(text, offsetBeyondDepth(text, kMaxJsonNesting)) + ": nested deeper than " +
                              std::to_string(kMaxJsonNesting) + " levels"};
  }
  return document;
}

template <class Json>
std::string describeJsonValue(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    default:
      return "something else";
  }
}

template nlohmann::json parseJsonText<nlohmann::json>(std::string_view text);
template nlohmann::ordered_json parseJsonText<nlohmann::ordered_json>(std::string_view text);
template std::string describeJsonValue<nlohmann::json>(const nlohmann::json& value);
template std::string describeJsonValue<nlohmann::ordered_json>(const nlohmann::ordered_json& value);

std::string listOfNames(std::initializer_list<std::string_view> names) {
  constexpr std::size_t kMaxNames = 12;
  std::string text;
  std::size_t count = 0;
  for (const std::string_view name : names) {
    if (count == kMaxNames) return text + ", ...";
    if (count++ > 0) text += ", ";
    text += name;
  }
  return text.empty() ? "none" : text;
}

}  // namespace dashbed::core
