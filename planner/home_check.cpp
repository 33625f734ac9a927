#include "planner/home_check.h"

#include <string>

#include "core/world_io.h"

namespace dashbed::planner {

Eigen::VectorXd homeConfiguration(const core::World& world, const CollisionScene& scene, int robot) {
  return scene.configuration(robot, world.robots.at(static_cast<std::size_t>(robot)).home, kFingersOpen);
}

void requireFreeHomes(const core::World& world, const CollisionScene& scene) {
  CollisionChecker checker(scene);
  const auto at_home = [&](std::size_t r) { return homeConfiguration(world, scene, static_cast<int>(r)); };
  const auto field = [&](std::size_t r) {
    return core::formatLocation(world.robots[r].where) + ": robots[" + std::to_string(r) + "].home: robot '" +
           world.robots[r].name + "'";
  };
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    if (!checker.robotFree(static_cast<int>(r), at_home(r), {})) {
      throw core::WorldError(field(r) +
                             " collides with a fixture, the floor, another robot's pedestal or itself at its home "
                             "configuration (gripper open); move its base or change its home angles");
    }
    for (std::size_t s = 0; s < r; ++s) {
      if (!checker.robotsFree(static_cast<int>(r), at_home(r), std::nullopt, static_cast<int>(s), at_home(s),
                              std::nullopt)) {
        throw core::WorldError(field(r) + " collides with robot '" + world.robots[s].name +
                               "' when both stand at their home configurations; move their bases apart");
      }
    }
  }
}

}  // namespace dashbed::planner
