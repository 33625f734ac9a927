// Goal sites of objects sent to a region (planner/sampling/object_sites.h): one slot each, inside the
// region, apart from each other; slots a robot reaches are used first, and a region without
// enough of them is an error that says so; objects already in their regions stay.
#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/reach.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "planner/sampling/object_sites.h"

using namespace dashbed;
using Catch::Matchers::Contains;

namespace {

std::string testWorld(const std::string& name) {
  return std::string(DASHBED_SOURCE_ROOT) + "/tests/planner/worlds/" + name;
}

bool reachedByARobot(const core::LoadedWorld& world, const core::Pose& X_WO, const Eigen::Vector3d& size) {
  const auto& robots = world.robots->robots();
  return std::any_of(robots.begin(), robots.end(), [&](const core::PlacedRobot& r) { return core::reachesBox(r, X_WO, size); });
}

}  // namespace

TEST_CASE("objects sent to a bin only partly in reach get slots a robot reaches", "[planner][sites]") {
  const core::LoadedWorld world = core::loadWorld(testWorld("bin_partly_in_reach.yaml"));
  const core::ObjectSpec& first = world.world->objects.front();
  const core::Region& bin = *world.world->goalRegionOf(first);
  // the premise: some slot of the bin is out of reach
  const std::vector<Eigen::Vector3d> slots = planner::regionSlots(bin, first.size);
  const std::size_t unreached = static_cast<std::size_t>(std::count_if(slots.begin(), slots.end(), [&](const Eigen::Vector3d& p) {
    core::Pose X_WO = core::Pose::Identity();
    X_WO.translation() = p;
    return !reachedByARobot(world, X_WO, first.size);
  }));
  REQUIRE(unreached > 0);
  REQUIRE(slots.size() - unreached >= world.world->objects.size());

  const planner::ObjectSites sites = planner::objectSites(world);
  for (std::size_t o = 0; o < world.world->objects.size(); ++o) {
    INFO(world.world->objects[o].name);
    REQUIRE(sites.goal[o]);
    CHECK(reachedByARobot(world, *sites.goal[o], world.world->objects[o].size));
    for (std::size_t p = 0; p < o; ++p) {
      CHECK((sites.goal[o]->translation() - sites.goal[p]->translation()).norm() >= first.size.maxCoeff());
    }
  }
}

TEST_CASE("an object already in its goal region stays, and the others' slots keep clear of it", "[planner][sites]") {
  core::World world = core::loadWorldFile(testWorld("already_in_bin.yaml"));
  const core::Region& bin = *world.goalRegionOf(world.objects[0]);
  REQUIRE(planner::restsIn(bin, world.objects[0].X_WO));
  REQUIRE_FALSE(planner::restsIn(bin, world.objects[1].X_WO));
  {
    const core::LoadedWorld loaded = core::validateWorld(world);
    const planner::ObjectSites sites = planner::objectSites(loaded);
    CHECK_FALSE(sites.goal[0]);  // red_in: no goal site, nothing to do
    CHECK(sites.goal_region[0] == -1);
    REQUIRE(sites.goal[1]);
    CHECK(planner::restsIn(bin, *sites.goal[1]));
    // 40 mm cubes: centres at least a cube and the fingers' room apart along some axis
    const Eigen::Vector3d d = sites.goal[1]->translation() - world.objects[0].X_WO.translation();
    CHECK(std::max(std::abs(d.x()), std::abs(d.y())) >= 0.04 + planner::kFingerRoom - 1e-9);
  }
  // at the bin's centre red_in leaves no slot for red_out: both get slots, red_in is moved
  world.objects[0].X_WO.translation().head<2>() = bin.X_WR.translation().head<2>();
  const core::LoadedWorld loaded = core::validateWorld(world);
  const planner::ObjectSites sites = planner::objectSites(loaded);
  CHECK(sites.goal[0]);
  CHECK(sites.goal[1]);
}

TEST_CASE("more objects than a region has reachable slots for is an error naming the region", "[planner][sites]") {
  core::World world = core::loadWorldFile(testWorld("bin_partly_in_reach.yaml"));
  const core::ObjectSpec cube = world.objects.front();
  const core::Region& bin = *world.goalRegionOf(cube);
  // as many cubes as the bin has slots: some of them out of reach
  const std::size_t slots = planner::regionSlots(bin, cube.size).size();
  while (world.objects.size() < slots) {
    core::ObjectSpec more = cube;
    more.name = "cube_" + std::to_string(world.objects.size());
    more.X_WO.translation().y() += 0.06 * static_cast<double>(world.objects.size());
    world.objects.push_back(more);
  }
  const core::LoadedWorld loaded = core::validateWorld(std::move(world));
  CHECK_THROWS_WITH(planner::objectSites(loaded), Contains("bin_blue") && Contains("within reach of a robot"));
}

TEST_CASE("the robots that may place an object are those reaching its goal slot", "[planner][sites]") {
  const core::LoadedWorld world = core::loadWorld(testWorld("slot_off_centre_reach.yaml"));
  // the premise: r1 reaches the bin's centre and r0 does not
  const core::ObjectSpec& cube = world.world->objects[0];
  const core::Pose centre = core::placementPose(*world.world->goalRegionOf(cube), cube);
  REQUIRE(core::reachesBox((*world.robots)[1], centre, cube.size));
  REQUIRE_FALSE(core::reachesBox((*world.robots)[0], centre, cube.size));
  const planner::ObjectSites sites = planner::objectSites(world);
  REQUIRE(sites.goal[0]);
  const core::ReachMap reach = planner::placementReach(world, sites);
  CHECK(reach.start == world.reach.start);
  // the cube's slot is one only r0 reaches
  CHECK(reach.goal[0] == std::vector<int>{0});
  CHECK(core::reachesBox((*world.robots)[0], *sites.goal[0], cube.size));
  CHECK_FALSE(core::reachesBox((*world.robots)[1], *sites.goal[0], cube.size));
}

TEST_CASE("objects of other sizes sent to one region get slots clear of each other", "[planner][sites]") {
  const core::LoadedWorld world = core::loadWorld(testWorld("mixed_sizes_in_bin.yaml"));
  const std::vector<core::ObjectSpec>& objects = world.world->objects;
  const planner::ObjectSites sites = planner::objectSites(world);
  const core::Region& bin = *world.world->goalRegionOf(objects.front());
  for (std::size_t o = 0; o < objects.size(); ++o) {
    REQUIRE(sites.goal[o]);
    CHECK(planner::restsIn(bin, *sites.goal[o]));
    // the bin and every object are square to the world: footprints are the sizes' x and y
    for (std::size_t p = 0; p < o; ++p) {
      INFO(objects[o].name << " and " << objects[p].name);
      const Eigen::Vector3d d = (sites.goal[o]->translation() - sites.goal[p]->translation()).cwiseAbs();
      const Eigen::Vector3d apart = (objects[o].size + objects[p].size) / 2;
      CHECK((d.x() >= apart.x() + planner::kFingerRoom - 1e-9 || d.y() >= apart.y() + planner::kFingerRoom - 1e-9));
    }
  }
}

TEST_CASE("a set-aside spot is the first one keeps_clear accepts, else the first of all", "[planner][sites]") {
  const core::LoadedWorld world =
      core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/handwritten/x5_shelf_item_set_aside.yaml");
  const int blue_3 = 2;
  planner::ObjectSites plain = planner::objectSites(world);
  REQUIRE(planner::setAsideSites(world, plain, {blue_3}) == std::vector<int>{blue_3});
  const Eigen::Vector3d first = plain.aside[blue_3]->translation();
  // every spot within 0.1 m of the first rejected
  planner::ObjectSites moved = planner::objectSites(world);
  int asked = 0;
  const auto far_from_first = [&](int object, const core::Pose& X_WO) {
    ++asked;
    CHECK(object == blue_3);
    return (X_WO.translation() - first).norm() > 0.1;
  };
  REQUIRE(planner::setAsideSites(world, moved, {blue_3}, far_from_first) == std::vector<int>{blue_3});
  CHECK((moved.aside[blue_3]->translation() - first).norm() > 0.1);
  CHECK(asked > 1);
  // none accepted: the spot it takes without asking
  planner::ObjectSites fallback = planner::objectSites(world);
  REQUIRE(planner::setAsideSites(world, fallback, {blue_3}, [](int, const core::Pose&) { return false; }) ==
          std::vector<int>{blue_3});
  CHECK(fallback.aside[blue_3]->translation().isApprox(first));
}

TEST_CASE("a set-aside site stands where the object started, moved on its surface, clear of the rest and in reach",
          "[planner][sites]") {
  const core::LoadedWorld world =
      core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/handwritten/x5_shelf_item_set_aside.yaml");
  planner::ObjectSites sites = planner::objectSites(world);
  CHECK(std::none_of(sites.aside.begin(), sites.aside.end(), [](const auto& pose) { return pose.has_value(); }));
  const int blue_0 = 0, green_3 = 1, blue_3 = 2;
  REQUIRE(planner::setAsideSites(world, sites, {blue_0, blue_3}) == std::vector<int>{blue_0, blue_3});
  CHECK_FALSE(sites.aside[green_3]);
  CHECK_FALSE(sites.site(planner::ObjectSites::asideSite(green_3)));
  const auto radius = [](const Eigen::Vector3d& size) { return size.head<2>().norm() / 2; };  // upright boxes
  for (const int o : {blue_0, blue_3}) {
    INFO(world.world->objects[o].name);
    const Eigen::Vector3d& size = world.world->objects[o].size;
    const core::Pose& X_WO = *sites.aside[o];
    const std::optional<planner::RestingObject> site = sites.site(planner::ObjectSites::asideSite(o));
    REQUIRE(site);
    CHECK(site->object == o);
    CHECK(site->X_WO.isApprox(X_WO));
    // on the table as it started: same height and orientation
    CHECK(X_WO.translation().z() == Approx(sites.start[o].translation().z()));
    CHECK(X_WO.linear().isApprox(sites.start[o].linear()));
    CHECK(reachedByARobot(world, X_WO, size));
    // the open gripper's reach from every other site...
    for (int s = 0; s < sites.numSites(); ++s) {
      const std::optional<planner::RestingObject> other = sites.site(s);
      if (!other || s == planner::ObjectSites::asideSite(o)) continue;
      const double apart = (other->X_WO.translation() - X_WO.translation()).head<2>().norm();
      CHECK(apart >= radius(size) + radius(world.world->objects[other->object].size) + planner::kOpenFingerReach);
    }
    // ... and from the shelf, in front of the table's far half
    const core::FixtureSpec& shelf = *world.world->findFixture("shelf");
    CHECK(X_WO.translation().x() + radius(size) + planner::kOpenFingerReach <= shelf.X_WF.translation().x() - shelf.size.x() / 2);
  }
}
