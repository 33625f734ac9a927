#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "core/world_loader.h"
#include "sim/render/image.h"
#include "tools/script/scripted_plan.h"
#include "sim/job/recorded_run.h"

using namespace dashbed;

TEST_CASE("a failing run comes with stills of the failed check and of the final state", "[stills]") {
  const core::LoadedWorld world = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml");
  const core::Plan plan = tools::planFromScript(world, "r1 picks cube_0; r1 opens; r1 moves home");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "dashbed_test_stills";
  std::filesystem::remove_all(dir);
  const sim::Report report =
      sim::simulateAndRecord(*world.world, *world.robots, plan, "drop.json", sim::RecordingOptions{}, dir.string()).report;
  REQUIRE(!report.passed());
  REQUIRE(!report.final_still.empty());
  // referenced relative to the stills folder's parent, wherever that is
  CHECK(report.final_still == "dashbed_test_stills/final.png");
  CHECK(std::filesystem::file_size(dir.parent_path() / report.final_still) > 1000);
  bool drop_still = false;
  for (const sim::ExecutionEvent& event : report.events) {
    if (event.kind != "drop") continue;
    REQUIRE(!event.still.empty());
    CHECK(event.still.rfind("dashbed_test_stills/event_", 0) == 0);
    const render::Image image = render::readPng(dir.parent_path() / event.still);
    CHECK(image.width == 640);
    CHECK(image.height == 480);
    drop_still = true;
  }
  CHECK(drop_still);
  std::filesystem::remove_all(dir);
}
