#pragma once
// Reading a whole input file (world, plan, report) with an error that names it.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace dashbed::core {

/// The contents of `file`. Throws `Error` (an exception type constructible from a string)
/// with "FILE: cannot read the KIND file: REASON" when it is missing, a directory or unreadable.
template <typename Error>
std::string readTextFile(const std::filesystem::path& file, const std::string& kind) {
  const auto fail = [&](const std::string& reason) {
    return Error(file.string() + ": cannot read the " + kind + " file: " + reason);
  };
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw fail("it is a directory");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw fail(std::filesystem::exists(file, ec) ? "permission denied or unreadable" : "no such file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw fail("read error");
  return text.str();
}

}  // namespace dashbed::core
