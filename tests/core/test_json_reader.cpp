#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "core/json_reader.h"

using dashbed::core::JsonReader;

namespace {

struct TestError : dashbed::core::InputError {
  using InputError::InputError;
};

}  // namespace

TEST_CASE("JSON reader: broken text is refused with where it breaks", "[json]") {
  const JsonReader<TestError> dut("f.json");
  CHECK_THROWS_WITH(dut.parse("{\"a\": 1,\n \"a\": 2}"), "f.json: /a: duplicate key");
  CHECK_THROWS_WITH(dut.parse("[{\"x\": {\"k\": 1, \"k\": 2}}]"), "f.json: /0/x/k: duplicate key");
  CHECK_THROWS_WITH(dut.parse("{\"a\": 1,\n  \"b\": }"),
                    Catch::Matchers::StartsWith("f.json: /: invalid JSON: parse error at line 2, column 8"));
  CHECK_THROWS_WITH(dut.parse(std::string(300, '[') + std::string(300, ']')),
                    Catch::Matchers::EndsWith(": nested deeper than 256 levels"));
  CHECK_NOTHROW(dut.parse(std::string(200, '[') + std::string(200, ']')));
  const JsonReader<TestError> unnamed("");
  CHECK_THROWS_WITH(unnamed.parse("{"), Catch::Matchers::StartsWith("<memory>: /: invalid JSON: "));
  // the parts of the message, apart
  try {
    dut.parse("[{\"x\": {\"k\": 1, \"k\": 2}}]");
    FAIL("no error");
  } catch (const TestError& e) {
    CHECK(e.where().file == "f.json");
    CHECK(e.where().line == 0);
    CHECK(e.field() == "/0/x/k");
    CHECK(e.problem() == "duplicate key");
  }
}

TEST_CASE("JSON reader: typed access names the pointer, what it expected and what it got", "[json]") {
  const JsonReader<TestError> dut("f.json");
  const auto doc = dut.parse(R"({"t": "soon", "n": -1, "list": [1, "two"], "ok": true, "o": {"x": 1.5}})");
  CHECK_THROWS_WITH(dut.number(doc, "", "t"), "f.json: /t: expected a number, got a string");
  CHECK_THROWS_WITH(dut.unsignedInteger(doc, "", "n"), "f.json: /n: expected a non-negative integer, got -1");
  CHECK_THROWS_WITH(dut.string(doc, "", "missing"), "f.json: /missing: missing");
  CHECK_THROWS_WITH(dut.number(doc["list"][1], "/list/1"), "f.json: /list/1: expected a number, got a string");
  CHECK_THROWS_WITH(dut.number(doc["list"], "/list", "x"), "f.json: /list: expected an object, got an array");
  CHECK_THROWS_WITH(dut.expectObject(doc, "", {"t", "n"}), Catch::Matchers::StartsWith("f.json: /list: unknown key (expected t, n)"));
  CHECK(dut.boolean(doc, "", "ok"));
  CHECK(dut.number(doc["o"], "/o", "x") == 1.5);
  CHECK(dut.array(doc, "", "list").size() == 2);
  CHECK(dut.optional(doc, "absent") == nullptr);
}

TEST_CASE("JSON reader: ordered documents keep the text's key order", "[json]") {
  const JsonReader<TestError, nlohmann::ordered_json> dut("f.json");
  const auto doc = dut.parse(R"({"b": 1, "a": 2, "c": 3})");
  std::string keys;
  for (const auto& [key, value] : doc.items()) keys += key;
  CHECK(keys == "bac");
  CHECK_THROWS_WITH(dut.parse(R"({"b": 1, "b": 2})"), "f.json: /b: duplicate key");
}
