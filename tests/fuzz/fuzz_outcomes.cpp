// Stress outcome files (trials.json, the MPI gather): read or refused with core::InputError;
// outcomes that are read write back to text that reads to the same outcomes.
#include <cstdlib>

#include "fuzz_input.h"
#include "tools/stress/stress.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  fuzz::expectReadOrRefuse<core::InputError>([&] {
    const auto outcomes = tools::readOutcomesJson(fuzz::textOf(data, size));
    const std::string text = tools::writeOutcomesJson(outcomes);
    if (tools::writeOutcomesJson(tools::readOutcomesJson(text)) != text) std::abort();
  });
  return 0;
}
