// World files: parsed and validated, or refused with a WorldError; a world that is read is
// written and read back to the same text.
#include <cstdlib>

#include "core/world_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  fuzz::expectReadOrRefuse<core::WorldError>([&] {
    const core::World world = core::parseWorldYaml(fuzz::textOf(data, size), "fuzz.yaml");
    const std::string text = core::writeWorldYaml(world);
    if (core::writeWorldYaml(core::parseWorldYaml(text, "written.yaml")) != text) std::abort();
  });
  return 0;
}
