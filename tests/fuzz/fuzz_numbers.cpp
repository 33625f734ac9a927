// The command line's number checks: every text is accepted or refused with a message, and a
// text accepted as in a range reads back to a number in that range.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_input.h"
#include "tools/cli/number_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  const std::string text(fuzz::textOf(data, size));
  const auto accepted = [&](CLI::Validator validator) {
    std::string copy = text;
    return validator(copy).empty();
  };
  if (accepted(tools::integerIn(-5, 1000))) {
    long long value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    if (value < -5 || value > 1000) std::abort();
  }
  if (accepted(tools::unsigned64()) && (text.empty() || text[0] == '-')) std::abort();
  if (accepted(tools::positiveNumber())) {
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    if (!(value > 0.0) || !std::isfinite(value)) std::abort();
  }
  accepted(tools::nonNegativeNumber());
  return 0;
}
