// The command line's numeric checks: exact ranges, no wrap-around, no infinities or NaN.

#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include "tools/cli/number_checks.h"

using namespace dashbed::tools;

namespace {

/// The validator's message for `text` ("" when accepted).
std::string verdict(const CLI::Validator& check, std::string text) { return check(text); }

}  // namespace

TEST_CASE("seeds are unsigned 64-bit integers, neither wrapped nor cut", "[cli]") {
  const CLI::Validator seed = unsigned64();
  CHECK(verdict(seed, "0").empty());
  CHECK(verdict(seed, "18446744073709551615").empty());
  CHECK(verdict(seed, "-1") == "must be an integer from 0 to 18446744073709551615, got '-1'");
  CHECK_FALSE(verdict(seed, "18446744073709551616").empty());
  for (const char* bad : {"", "+1", "1.0", "1e3", " 1", "0x10", "7 "}) {
    INFO(bad);
    CHECK_FALSE(verdict(seed, bad).empty());
  }
}

TEST_CASE("integer options hold their range", "[cli]") {
  const CLI::Validator rounds = integerIn(1, std::numeric_limits<int>::max());
  CHECK(verdict(rounds, "1").empty());
  CHECK(verdict(rounds, "2147483647").empty());
  CHECK(verdict(rounds, "0") == "must be an integer from 1 to 2147483647, got '0'");
  for (const char* bad : {"2147483648", "99999999999", "-3", "1.5", "ten", ""}) {
    INFO(bad);
    CHECK_FALSE(verdict(rounds, bad).empty());
  }
  CHECK(verdict(integerIn(0, 10), "0").empty());
}

TEST_CASE("number options are finite and on the right side of their bound", "[cli]") {
  const CLI::Validator budget = positiveNumber();
  CHECK(verdict(budget, "120").empty());
  CHECK(verdict(budget, "0.5").empty());
  CHECK(verdict(budget, "1e-3").empty());
  CHECK(verdict(budget, "-1") == "must be a finite number > 0, got '-1'");
  for (const char* bad : {"0", "inf", "-inf", "nan", "1e400", "1s", ""}) {
    INFO(bad);
    CHECK_FALSE(verdict(budget, bad).empty());
  }
  CHECK(verdict(nonNegativeNumber(), "0").empty());
  CHECK(verdict(nonNegativeNumber(), "-0.001") == "must be a finite number >= 0, got '-0.001'");
}
