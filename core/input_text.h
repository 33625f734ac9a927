#pragma once
// Text that someone else wrote (world, plan, report, script files): the checks every reader
// makes before parsing, and messages that never carry a raw byte.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace dashbed::core {

/// `text` with every byte that is not printable UTF-8 written as "\xNN": control characters
/// (line feed excepted), DEL, and bytes that are not part of a valid UTF-8 sequence.
std::string printableText(std::string_view text);

/// Where something was written: file, 1-based line and column (0 when unknown or generated in
/// memory).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// "FILE:LINE:COLUMN", or "FILE" when the line is unknown ("<memory>" for no file).
std::string formatLocation(const SourceLocation& where);

/// The base of every reader's error (WorldError, PlanError, ...): its message is printable
/// (printableText), whatever the file held. Built from a location and a field it keeps them,
/// for callers that show them apart (the Python API's exceptions).
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(printableText(message)) {}
  /// "FILE[:LINE:COLUMN]: FIELD: PROBLEM" (without ": FIELD" when `field` is empty). The field
  /// is a world file's path (objects[2].pose) or a JSON pointer (/robots/0/points/3/t).
  InputError(SourceLocation where, std::string field, const std::string& problem);

  /// The location (file "" when the error was built from a message alone).
  const SourceLocation& where() const { return where_; }
  const std::string& field() const { return field_; }
  /// The message without location and field.
  const std::string& problem() const { return problem_; }

 private:
  SourceLocation where_;
  std::string field_;
  std::string problem_;
};

/// Where text is not what dashbed reads: a 1-based line and column (in bytes) and what is wrong.
struct TextProblem {
  int line = 0;
  int column = 0;
  std::string what;
};

/// The first reason `text` is not UTF-8 text: a UTF-16 or UTF-32 byte-order mark, a byte
/// sequence that is not UTF-8, a NUL or another control character than tab, line feed and
/// carriage return. A UTF-8 byte-order mark is allowed. Linear in the size of `text`.
std::optional<TextProblem> findTextProblem(std::string_view text);

/// "line L, column C" of byte `offset` of `text` (1-based; the column counts bytes).
std::string lineAndColumn(std::string_view text, std::size_t offset);

/// The largest file a reader takes [bytes]: far above any plan or world dashbed writes, and
/// low enough that a parser's tree of it fits in memory.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{256} << 20;

/// The contents of `file`, at most `max_bytes` of it. Throws `Error` (an InputError) with "FILE: cannot read the KIND file: REASON" when it is missing, a directory,
/// unreadable or larger than `max_bytes` (read in chunks, so a device or pipe that never
/// ends is refused rather than read forever).
template <typename Error>
std::string readTextFile(const std::filesystem::path& file, const std::string& kind,
                         std::size_t max_bytes = kMaxInputFileBytes);

/// The contents of `file`, or nullopt with `reason` set ("no such file", "it is a directory",
/// "larger than 256 MiB", ...).
std::optional<std::string> readFileBytes(const std::filesystem::path& file, std::size_t max_bytes,
                                         std::string& reason);

template <typename Error>
std::string readTextFile(const std::filesystem::path& file, const std::string& kind, std::size_t max_bytes) {
  std::string reason;
  std::optional<std::string> bytes = readFileBytes(file, max_bytes, reason);
  if (!bytes) throw Error(SourceLocation{file.string()}, "", "cannot read the " + kind + " file: " + reason);
  return std::move(*bytes);
}

}  // namespace dashbed::core
