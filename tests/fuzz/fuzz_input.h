#pragma once
// Shared by the harnesses: the input as text, and the one way a harness reports a finding
// besides the sanitizers: an exception other than the reader's documented error.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "core/input_text.h"

namespace dashbed::fuzz {

inline std::string_view textOf(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs `read`; its documented error `Error` is a refusal (its message must be printable);
/// any other exception is a bug, reported by aborting.
template <class Error, class Read>
void expectReadOrRefuse(Read&& read) {
  try {
    read();
  } catch (const Error& error) {
    const std::string_view message = error.what();
    if (message.empty() || core::printableText(message) != message) {
      std::fprintf(stderr, "refusal without a printable message: '%s'\n", core::printableText(message).c_str());
      std::abort();
    }
  } catch (const std::exception& other) {
    std::fprintf(stderr, "undocumented exception: %s\n", core::printableText(other.what()).c_str());
    std::abort();
  }
}

}  // namespace dashbed::fuzz
