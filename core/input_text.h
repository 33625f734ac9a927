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

/// The base of every reader's error (WorldError, PlanError, ...): its message is printable
/// (printableText), whatever the file held.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(printableText(message)) {}
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

/// The contents of `file`, at most `max_bytes` of it. Throws `Error` (constructible from a
/// string) with "FILE: cannot read the KIND file: REASON" when it is missing, a directory,
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
  if (!bytes) throw Error(file.string() + ": cannot read the " + kind + " file: " + reason);
  return std::move(*bytes);
}

}  // namespace dashbed::core
