// Action scripts: parsed against the default world (words, names, numbers) or refused with a
// ScriptError naming line and column.
#include "core/asset_paths.h"
#include "core/world_io.h"
#include "fuzz_input.h"
#include "tools/script/script_parser.h"
#include "tools/script/scripted_plan.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  static const core::World world = core::loadWorldFile(core::defaultWorldPath());
  fuzz::expectReadOrRefuse<tools::ScriptError>([&] {
    const tools::ScriptParser parser(world, "fuzz.script");
    parser.parse(fuzz::textOf(data, size));
  });
  return 0;
}
