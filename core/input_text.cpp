#include "core/input_text.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <system_error>

namespace dashbed::core {
namespace {

std::string hexByte(unsigned char byte) {
  std::array<char, 5> text{};
  std::snprintf(text.data(), text.size(), "\\x%02X", byte);
  return text.data();
}

// Length of the valid UTF-8 sequence starting at text[i] (RFC 3629: no overlong forms, no
// surrogates, at most U+10FFFF), or 0 when the bytes there are not one.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = at(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (at(i + 1) < low || at(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (at(i + k) < 0x80 || at(i + k) > 0xBF) return 0;
  }
  return length;
}

bool isControl(unsigned char byte) { return byte < 0x20 || byte == 0x7F; }

}  // namespace

std::string formatLocation(const SourceLocation& where) {
  const std::string file = where.file.empty() ? "<memory>" : where.file;
  if (where.line <= 0) return file;
  return file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

namespace {

std::string locatedMessage(const SourceLocation& where, const std::string& field, const std::string& problem) {
  std::string message = formatLocation(where);
  if (!field.empty()) message.append(": ").append(field);
  return message.append(": ").append(problem);
}

}  // namespace

InputError::InputError(SourceLocation where, std::string field, const std::string& problem)
    : std::runtime_error(printableText(locatedMessage(where, field, problem))),
      where_(std::move(where)),
      field_(printableText(field)),
      problem_(printableText(problem)) {}

std::string printableText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8SequenceLength(text, i);
    if (length == 0 || (isControl(byte) && byte != '\n')) {
      out += hexByte(byte);
      ++i;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

std::string lineAndColumn(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const std::string_view before = text.substr(0, offset);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t last_break = before.rfind('\n');
  const std::size_t line_start = last_break == std::string_view::npos ? 0 : last_break + 1;
  return "line " + std::to_string(line) + ", column " + std::to_string(offset - line_start + 1);
}

std::optional<TextProblem> findTextProblem(std::string_view text) {
  const auto startsWith = [&](std::string_view mark) { return text.substr(0, mark.size()) == mark; };
  // UTF-32 first: its little-endian mark begins with UTF-16's
  const std::pair<std::string_view, const char*> marks[] = {
      {std::string_view("\xFF\xFE\x00\x00", 4), "UTF-32 (it starts with the byte-order mark FF FE 00 00)"},
      {std::string_view("\x00\x00\xFE\xFF", 4), "UTF-32 (it starts with the byte-order mark 00 00 FE FF)"},
      {"\xFF\xFE", "UTF-16 (it starts with the byte-order mark FF FE)"},
      {"\xFE\xFF", "UTF-16 (it starts with the byte-order mark FE FF)"},
  };
  for (const auto& [mark, encoding] : marks) {
    if (startsWith(mark)) return TextProblem{1, 1, std::string("the file is ") + encoding + "; dashbed reads UTF-8 text"};
  }
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const auto here = [&](std::string what) {
      return TextProblem{line, static_cast<int>(i - line_start + 1), std::move(what)};
    };
    if (byte == '\n') {
      ++line;
      line_start = ++i;
      continue;
    }
    if (byte == 0) return here("a NUL byte (\\x00): not UTF-8 text (UTF-16 without a byte-order mark, or a binary file?)");
    if (isControl(byte) && byte != '\t' && byte != '\r') {
      return here("control character " + hexByte(byte) + " (only tab, line feed and carriage return may appear)");
    }
    const std::size_t length = utf8SequenceLength(text, i);
    if (length == 0) return here("byte " + hexByte(byte) + " is not part of a UTF-8 character");
    i += length;
  }
  return std::nullopt;
}

std::optional<std::string> readFileBytes(const std::filesystem::path& file, std::size_t max_bytes,
                                         std::string& reason) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    reason = "it is a directory";
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    reason = std::filesystem::exists(file, ec) ? "permission denied or unreadable" : "no such file";
    return std::nullopt;
  }
  std::string bytes;
  std::array<char, 1 << 16> chunk{};
  while (in) {
    in.read(chunk.data(), chunk.size());
    bytes.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (bytes.size() > max_bytes) {
      reason = max_bytes % (1 << 20) == 0 ? "larger than " + std::to_string(max_bytes >> 20) + " MiB"
                                          : "larger than " + std::to_string(max_bytes) + " bytes";
      return std::nullopt;
    }
  }
  if (in.bad()) {
    reason = "read error";
    return std::nullopt;
  }
  return bytes;
}

}  // namespace dashbed::core
