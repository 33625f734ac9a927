// The independent plan checker the planner tests use (plan_checks.h): it must find what it
// claims to find, on plans made to collide.

#include <catch2/catch.hpp>

#include <string>

#include "core/asset_paths.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "tests/planner/plan_checks.h"
#include "tests/sim/sim_test_worlds.h"
#include "tools/script/scripted_plan.h"

using namespace dashbed;
using planner::testing::collisionsAlong;

namespace {

const core::LoadedWorld& defaultWorld() {
  static const core::LoadedWorld loaded = core::loadWorld(core::defaultWorldPath());
  return loaded;
}

std::string downAt(int r, const Eigen::Vector3d& p_W) { return test::downAt(defaultWorld(), r, p_W); }

std::vector<std::string> collisionsOf(const std::string& script) {
  return collisionsAlong(tools::planFromScript(defaultWorld(), script), defaultWorld());
}

bool mentions(const std::vector<std::string>& found, const std::string& what) {
  for (const std::string& line : found) {
    if (line.find(what) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("plan checker: a clean pick, handoff and place has no collision", "[plan_checks]") {
  CHECK(collisionsOf("r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red").empty());
}

TEST_CASE("plan checker: two arms reaching for the same point collide", "[plan_checks]") {
  const std::vector<std::string> found =
      collisionsOf("r0 moves to" + downAt(0, {0.0, 0.0, 0.9}) + "; r1 moves to" + downAt(1, {0.0, 0.0, 0.9}));
  INFO((found.empty() ? "" : found.front()));
  CHECK(mentions(found, "robot r0") );
  CHECK(mentions(found, "and robot r1"));
}

TEST_CASE("plan checker: an arm pressed into the table or through a resting cube collides", "[plan_checks]") {
  const Eigen::Vector3d cube_1 = defaultWorld().world->findObject("cube_1")->X_WO.translation();
  const std::vector<std::string> through_cube = collisionsOf("r0 moves to" + downAt(0, cube_1));
  CHECK(mentions(through_cube, "object cube_1 and robot r0"));
  const std::vector<std::string> into_table = collisionsOf("r0 moves to" + downAt(0, {-0.3, 0.3, 0.70}));
  CHECK(mentions(into_table, "fixture table and robot r0"));
}

TEST_CASE("plan checker: a carried cube is checked where the gripper takes it", "[plan_checks]") {
  // r0 waits low over the middle of the table while r1 brings cube_0 down onto its wrist
  const std::vector<std::string> found =
      collisionsOf("r0 moves to" + downAt(0, {0.0, 0.0, 0.85}) + "; r0 waits 15; r1 picks cube_0; r1 moves to" +
                   downAt(1, {0.0, 0.0, 0.97}) + "; r1 waits 1");
  INFO((found.empty() ? "" : found.front()));
  CHECK(mentions(found, "object cube_0 and robot r0"));
}
