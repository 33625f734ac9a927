#pragma once
// Checks of the commands' numeric options, on the text as typed: exact ranges said in plain
// words, no wrap-around of negative or oversized integers, no infinities or NaN.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

#include "core/number_text.h"

namespace dashbed::tools {

/// An integer from `lo` to `hi` written in decimal digits (an optional leading '-').
inline CLI::Validator integerIn(long long lo, long long hi) {
  const std::string range = "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) {
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool ok = error == std::errc() && end == text.data() + text.size() && value >= lo && value <= hi;
        return ok ? std::string() : "must be " + range + ", got '" + text + "'";
      },
      range, "INTEGER");
}

/// An unsigned 64-bit integer (a seed): decimal digits only, at most 2^64 - 1.
inline CLI::Validator unsigned64() {
  return CLI::Validator(
      [](std::string& text) {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool ok = !text.empty() && error == std::errc() && end == text.data() + text.size();
        return ok ? std::string()
                  : "must be an integer from 0 to " + std::to_string(std::numeric_limits<std::uint64_t>::max()) +
                        ", got '" + text + "'";
      },
      "an unsigned 64-bit integer", "UINT64");
}

/// A finite number above `bound` (or at least it, with `or_equal`).
inline CLI::Validator finiteAbove(double bound, bool or_equal) {
  const std::string what = std::string("a finite number ") + (or_equal ? ">= " : "> ") + core::shortestText(bound);
  return CLI::Validator(
      [bound, or_equal, what](std::string& text) {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool parsed = error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
        const bool ok = parsed && (or_equal ? value >= bound : value > bound);
        return ok ? std::string() : "must be " + what + ", got '" + text + "'";
      },
      what, "NUMBER");
}

/// A finite number > 0, and >= 0.
inline CLI::Validator positiveNumber() { return finiteAbove(0.0, false); }
inline CLI::Validator nonNegativeNumber() { return finiteAbove(0.0, true); }

}  // namespace dashbed::tools
