// Plan files: parsed, then checked against the default world (robots, objects, joint limits,
// speeds), or refused with a PlanError; a plan that is read writes back to text that reads
// to the same plan.
#include <cstdlib>

#include "core/plan.h"
#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  static const core::LoadedWorld world = core::loadWorld(core::defaultWorldPath());
  fuzz::expectReadOrRefuse<core::PlanError>([&] {
    const core::Plan plan = core::parsePlanJson(fuzz::textOf(data, size), "fuzz.json");
    const std::string text = core::writePlanJson(plan);
    if (core::writePlanJson(core::parsePlanJson(text, "written.json")) != text) std::abort();
    core::validatePlanForWorld(plan, *world.world, *world.robots, "fuzz.json");
  });
  return 0;
}
