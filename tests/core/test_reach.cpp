#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "core/grasps.h"
#include "core/reach.h"
#include "core/world_io.h"
#include "core/world_loader.h"

using namespace dashbed::core;

namespace {

const std::string kRoot = DASHBED_SOURCE_ROOT;

std::string defaultWorldText() {
  std::ifstream in(kRoot + "/worlds/default.yaml");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("the default world is reachable: cross starts need a handoff", "[reach]") {
  const LoadedWorld dut = loadWorld(kRoot + "/worlds/default.yaml");
  for (std::size_t o = 0; o < dut.world->objects.size(); ++o) {
    INFO(dut.world->objects[o].name);
    CHECK(dut.reach.start[o].size() == 1);
    CHECK(dut.reach.goal[o].size() == 1);
    CHECK(dut.reach.start[o] != dut.reach.goal[o]);
  }
  CHECK(handoffZone(*dut.world, (*dut.robots)[0], (*dut.robots)[1]));
}

TEST_CASE("a handoff zone starts over the midpoint of the bases, heights from the higher base", "[reach]") {
  const LoadedWorld dut = loadWorld(kRoot + "/worlds/default.yaml");
  const std::optional<HandoffZone> zone = handoffZone(*dut.world, (*dut.robots)[0], (*dut.robots)[1]);
  REQUIRE(zone);
  CHECK(zone->mid.x() == Approx(0.0).margin(1e-12));  // bases at x = -0.7 and 0.7
  CHECK(zone->mid.y() == Approx(0.0).margin(1e-12));
  CHECK(zone->top == 0.75);

  // 2.2 m apart, nothing between them is in reach of both
  World apart = *dut.world;
  apart.robots[1].X_WBase.translation().x() = 1.5;
  const RobotSet robots(apart);
  CHECK_FALSE(handoffZone(apart, robots[0], robots[1]));
}

TEST_CASE("a post between the robots moves their handoff zone in front of it, in either order", "[reach]") {
  const LoadedWorld dut = loadWorld(kRoot + "/tests/planner/worlds/post_between.yaml");
  const std::optional<HandoffZone> zone = handoffZone(*dut.world, (*dut.robots)[0], (*dut.robots)[1]);
  REQUIRE(zone);
  // the post stands at (0, -0.45), 0.16 m square, on the line between the bases; the zone
  // (0.1 m either side of its middle, 3 cm clearance) keeps clear of it
  const HandoffShape shape;
  CHECK(std::abs(zone->mid.y() - -0.45) >= 0.08 + shape.spread + 0.03 - 1e-9);
  CHECK(zone->top == 0.75);
  const std::optional<HandoffZone> reverse = handoffZone(*dut.world, (*dut.robots)[1], (*dut.robots)[0]);
  REQUIRE(reverse);
  CHECK(reverse->mid == zone->mid);
  CHECK(reverse->top == zone->top);
}

TEST_CASE("a base on a riser moves the handoff zone towards the robot below", "[reach]") {
  // r0 at x = -0.65 on the table, r1 at x = 0.7 on a 0.5 m riser: over the midpoint, 0.15-0.45 m
  // above r1's base, r0 reaches no point of the box
  const LoadedWorld dut = loadWorld(kRoot + "/tests/planner/worlds/riser_handoff.yaml");
  const std::optional<HandoffZone> zone = handoffZone(*dut.world, (*dut.robots)[0], (*dut.robots)[1]);
  REQUIRE(zone);
  CHECK(zone->mid.x() < 0.025 - 0.05);
  CHECK(zone->top <= 1.25);
}

TEST_CASE("an object out of every robot's reach names its file, line and field", "[reach]") {
  // move cube_0 to the far corner of the table, more than a metre from both bases
  World world = parseWorldYaml(defaultWorldText(), "worlds/default.yaml");
  const auto cube = std::find_if(world.objects.begin(), world.objects.end(),
                                 [](const ObjectSpec& o) { return o.name == "cube_0"; });
  REQUIRE(cube != world.objects.end());
  cube->X_WO.translation() = Eigen::Vector3d(0.0, 0.66, 0.77);
  const int line = cube->where.line;
  REQUIRE(line > 0);
  REQUIRE_THROWS_AS(validateWorld(world), WorldError);
  REQUIRE_THROWS_WITH(validateWorld(world), Catch::Matchers::Contains("worlds/default.yaml:" + std::to_string(line)) &&
                                                Catch::Matchers::Contains("pose: object 'cube_0'") &&
                                                Catch::Matchers::Contains("out of every robot's reach"));
}

TEST_CASE("a goal region out of every robot's reach names the goal", "[reach]") {
  World world = parseWorldYaml(defaultWorldText(), "worlds/default.yaml");
  // lift every region 2 m up: nothing can place there
  for (Region& region : world.regions) region.X_WR.translation().z() += 2.0;
  REQUIRE_THROWS_AS(validateWorld(world), WorldError);
  REQUIRE_THROWS_WITH(validateWorld(world), Catch::Matchers::Contains("goals[") &&
                                                Catch::Matchers::Contains("out of every robot's reach"));
}

TEST_CASE("grasps of a resting cube come from above only", "[reach]") {
  // a 40 mm cube is too low for the 75 mm Hand-E body to come in from the side
  const auto cube = boxGrasps(Eigen::Vector3d::Constant(0.04));
  CHECK(cube.size() == 4);
  for (const BoxGrasp& g : cube) CHECK(g.approach == GraspApproach::kTop);
  // a 120 mm item also has side grasps, held high enough for the body to clear the surface
  const auto item = boxGrasps(Eigen::Vector3d(0.04, 0.04, 0.12));
  CHECK(item.size() == 12);
  for (const BoxGrasp& g : item) {
    if (g.approach != GraspApproach::kSide) continue;
    CHECK(0.06 + g.X_OT.translation().z() - kHandeBodyHalfWidth >= 0.0);
  }
  // with a limit on how far it reaches above the TCP from above, the TCP moves up towards its
  // top; a cube, well within the limit, keeps its centred grasps
  for (const BoxGrasp& g : boxGrasps(Eigen::Vector3d(0.04, 0.04, 0.12), kGraspClearance, 0.0414)) {
    if (g.approach == GraspApproach::kTop) CHECK(g.X_OT.translation().z() == Approx(0.06 - 0.0414));
  }
  for (const BoxGrasp& g : boxGrasps(Eigen::Vector3d::Constant(0.04), kGraspClearance, 0.0414)) {
    CHECK(g.X_OT.translation().z() == 0.0);
  }
  // wider than the opening: no grasp across that face pair
  CHECK(boxGrasps(Eigen::Vector3d(0.06, 0.03, 0.04)).size() == 2);
}

TEST_CASE("a grip holds by friction what two pads pressing with the grip force carry", "[reach]") {
  // the default world: cube friction 0.8, rubber pads 1.0, 60 N: 9.8 kg, far above a 0.1 kg cube
  CHECK(frictionHoldMass(0.8 * 1.0, 60.0, 9.81) == Approx(9.79).margin(0.01));
  // a slippery cube (0.3) on worn pads (0.5) at the Hand-E's least force (20 N): 0.61 kg
  CHECK(frictionHoldMass(0.3 * 0.5, 20.0, 9.81) == Approx(0.612).margin(0.001));
}

TEST_CASE("an object too wide for the gripper says so, not that it is out of reach", "[reach]") {
  World world = parseWorldYaml(defaultWorldText(), "worlds/default.yaml");
  const auto cube = std::find_if(world.objects.begin(), world.objects.end(),
                                 [](const ObjectSpec& o) { return o.name == "cube_0"; });
  REQUIRE(cube != world.objects.end());
  const int line = cube->where.line;
  SECTION("46 mm: narrower than the opening, but without the clearance") {
    cube->size = Eigen::Vector3d::Constant(0.046);
    REQUIRE_THROWS_WITH(validateWorld(world), Catch::Matchers::Contains("worlds/default.yaml:" + std::to_string(line)) &&
                                                  Catch::Matchers::Contains("size: object 'cube_0'") &&
                                                  Catch::Matchers::Contains("too wide for the gripper"));
  }
  SECTION("44 mm fits") {
    cube->size = Eigen::Vector3d::Constant(0.044);
    CHECK_NOTHROW(validateWorld(world));
  }
}

TEST_CASE("a goal region whose centre is out of reach is a goal when its near part is not", "[reach]") {
  const LoadedWorld dut = loadWorld(kRoot + "/tests/planner/worlds/bin_centre_out_of_reach.yaml");
  const ObjectSpec& cube = dut.world->objects.front();
  const Region& bin = *dut.world->goalRegionOf(cube);
  const PlacedRobot& robot = (*dut.robots)[0];
  // the premise: the centre is out of reach
  REQUIRE_FALSE(reachesBox(robot, placementPose(bin, cube), cube.size));
  CHECK(reachesPlacementIn(robot, bin, cube));
  for (std::size_t o = 0; o < dut.world->objects.size(); ++o) CHECK(dut.reach.goal[o] == std::vector<int>{0});

  // moved 0.3 m farther away, no part of it is within reach: the goal names its line
  World world = loadWorldFile(kRoot + "/tests/planner/worlds/bin_centre_out_of_reach.yaml");
  for (Region& region : world.regions) region.X_WR.translation().x() += 0.3;
  CHECK_THROWS_WITH(validateWorld(std::move(world)),
                    Catch::Matchers::Contains("bin_centre_out_of_reach.yaml:13:5: goals[0].region") &&
                        Catch::Matchers::Contains("out of every robot's reach"));
}
