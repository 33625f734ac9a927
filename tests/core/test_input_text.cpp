// Checks before parsing (encoding, control characters, file size) and printable messages.

#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "core/input_text.h"
#include "core/plan.h"

using namespace dashbed::core;
using Catch::Matchers::Contains;

namespace {

std::string problemOf(std::string_view text) {
  const auto problem = findTextProblem(text);
  REQUIRE(problem);
  return std::to_string(problem->line) + ":" + std::to_string(problem->column) + ": " + problem->what;
}

}  // namespace

TEST_CASE("printableText escapes control bytes and bytes that are not UTF-8, nothing else", "[input]") {
  CHECK(printableText("plain text, line\nfeed") == "plain text, line\nfeed");
  CHECK(printableText(std::string("r\0" "1", 3)) == "r\\x001");
  CHECK(printableText("tab\there\r") == "tab\\x09here\\x0D");
  CHECK(printableText("\x1b[31mred\x7f") == "\\x1B[31mred\\x7F");
  CHECK(printableText("caf\xC3\xA9 \xE2\x80\x94 \xF0\x9F\x98\x80") == "caf\xC3\xA9 \xE2\x80\x94 \xF0\x9F\x98\x80");
  CHECK(printableText("\xFF\xFE" "a") == "\\xFF\\xFEa");
  CHECK(printableText("\xC0\xAF") == "\\xC0\\xAF");          // overlong '/'
  CHECK(printableText("\xED\xA0\x80") == "\\xED\\xA0\\x80");  // a UTF-16 surrogate
  CHECK(printableText("\xE2\x80") == "\\xE2\\x80");          // cut short
  CHECK(printableText(printableText("\x01\xFF")) == printableText("\x01\xFF"));  // idempotent
}

TEST_CASE("InputError messages are printable whatever the input held", "[input]") {
  const PlanError error(std::string("plan.json: /robots/0/name: unknown robot 'r\0\xFF'", 46));
  CHECK(std::string(error.what()) == "plan.json: /robots/0/name: unknown robot 'r\\x00\\xFF'");
}

TEST_CASE("findTextProblem names the first byte that is not UTF-8 text, with line and column", "[input]") {
  CHECK_FALSE(findTextProblem("a: 1\r\n\tb: [\"caf\xC3\xA9\"]\n"));
  CHECK_FALSE(findTextProblem("\xEF\xBB\xBF" "a: 1\n"));  // a UTF-8 byte-order mark
  CHECK(problemOf("\xFF\xFE" "a\0" ":\0") == "1:1: the file is UTF-16 (it starts with the byte-order mark FF FE); dashbed reads UTF-8 text");
  CHECK(problemOf("\xFE\xFF\0a") == "1:1: the file is UTF-16 (it starts with the byte-order mark FE FF); dashbed reads UTF-8 text");
  CHECK(problemOf(std::string("\xFF\xFE\0\0a\0\0\0", 8)) ==
        "1:1: the file is UTF-32 (it starts with the byte-order mark FF FE 00 00); dashbed reads UTF-8 text");
  CHECK(problemOf(std::string("a: 1\nb: \"x\0y\"\n", 14)).starts_with("2:6: a NUL byte (\\x00)"));
  CHECK(problemOf(std::string("a\0:\0 \0" "1\0", 8)).starts_with("1:2: a NUL byte"));  // UTF-16 without a mark
  CHECK(problemOf("a: 1\n\nname: x\x1b\n") == "3:8: control character \\x1B (only tab, line feed and carriage return may appear)");
  CHECK(problemOf("x\x7f") == "1:2: control character \\x7F (only tab, line feed and carriage return may appear)");
  CHECK(problemOf("d: caf\xE9\n") == "1:7: byte \\xE9 is not part of a UTF-8 character");
  CHECK(problemOf("ok\n\xC3") == "2:1: byte \\xC3 is not part of a UTF-8 character");
  CHECK(problemOf("\xF4\x90\x80\x80") == "1:1: byte \\xF4 is not part of a UTF-8 character");  // above U+10FFFF
}

TEST_CASE("lineAndColumn counts lines from 1 and columns in bytes", "[input]") {
  CHECK(lineAndColumn("ab\ncd", 0) == "line 1, column 1");
  CHECK(lineAndColumn("ab\ncd", 3) == "line 2, column 1");
  CHECK(lineAndColumn("ab\ncd", 4) == "line 2, column 2");
  CHECK(lineAndColumn("ab\ncd", 99) == "line 2, column 3");
}

TEST_CASE("readTextFile refuses files past its size limit, and inputs that never end", "[input]") {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "dashbed_input_text_100.txt";
  {
    std::ofstream out(file, std::ios::binary);
    out << std::string(100, 'x');
  }
  CHECK(readTextFile<PlanError>(file, "plan", 100).size() == 100);
  CHECK_THROWS_WITH(readTextFile<PlanError>(file, "plan", 99),
                    file.string() + ": cannot read the plan file: larger than 99 bytes");
  std::filesystem::remove(file);
  CHECK_THROWS_WITH(readTextFile<PlanError>("/dev/zero", "plan", std::size_t{1} << 20),
                    "/dev/zero: cannot read the plan file: larger than 1 MiB");
  CHECK_THROWS_WITH(readTextFile<PlanError>(file, "plan"), Contains("no such file"));
}
