// The planner choice of `dashbed plan`, `run`, `bench plan` and `stress` reaches the planner.

#include <catch2/catch.hpp>
#include <stdexcept>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "tools/planning/run_planner.h"

namespace dashbed::tools {
namespace {

using Catch::Matchers::Contains;

TEST_CASE("the planner choice's rounds are the planner's settings", "[tools]") {
  const core::LoadedWorld world = core::loadWorld(core::defaultWorldPath());
  PlannerChoice choice;
  CHECK(choice.fallback_rounds == planner::PlannerSettings{}.sequential_fallback_rounds);
  choice.fallback_rounds = -1;
  CHECK_THROWS_WITH(planWorld(world, choice), Contains("sequential_fallback_rounds: must be >= 0"));
  choice.fallback_rounds = 0;
  choice.max_rounds = 0;
  CHECK_THROWS_AS(planWorld(world, choice), std::invalid_argument);
}

}  // namespace
}  // namespace dashbed::tools
