#include "planner/collision/home_check.h"

#include <string>

#include "core/world_io.h"

namespace dashbed::planner {

Eigen::VectorXd homeConfiguration(const core::World& world, const CollisionScene& scene, int robot) {
  return scene.configuration(robot, world.robots.at(static_cast<std::size_t>(robot)).home, kFingersOpen);
}

void requireFreeHomes(const core::World& world, const CollisionScene& scene) {
  CollisionChecker checker(scene);
  const auto at_home = [&](std::size_t r) { return homeConfiguration(world, scene, static_cast<int>(r)); };
  const auto fail = [&](std::size_t r, const std::string& problem) {
    throw core::WorldError(world.robots[r].where, "robots[" + std::to_string(r) + "].home",
                           "robot '" + world.robots[r].name + "' " + problem);
  };
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    if (const std::string contact = checker.robotContact(static_cast<int>(r), at_home(r)); !contact.empty()) {
      fail(r, "collides at its home configuration (gripper open): " + contact +
                  "; move its base or change its home angles");
    }
    for (std::size_t s = 0; s < r; ++s) {
      const std::string contact = checker.robotsContact(static_cast<int>(r), at_home(r), static_cast<int>(s), at_home(s));
      if (!contact.empty()) {
        fail(r, "collides with robot '" + world.robots[s].name + "' when both stand at their home configurations: " +
                    contact + "; move their bases apart or change their home angles");
      }
    }
  }
}

std::vector<core::ArmConfig> foldedConfigurations(const core::World& world, const CollisionScene& scene) {
  // shoulder lift, elbow, wrist 1 [rad]: the upper arm 42 degrees behind vertical, the forearm
  // folded under it, the gripper pointing down
  constexpr double kLift = -2.3, kElbow = 2.4, kWrist1 = -1.67;
  const std::size_t n = world.robots.size();
  std::vector<core::ArmConfig> folded(n);
  for (std::size_t r = 0; r < n; ++r) {
    folded[r] = world.robots[r].home;
    folded[r][1] = kLift;
    folded[r][2] = kElbow;
    folded[r][3] = kWrist1;
  }
  CollisionChecker checker(scene);
  const auto at = [&](std::size_t r, const core::ArmConfig& q) { return scene.configuration(static_cast<int>(r), q, kFingersOpen); };
  const auto free_of = [&](std::size_t r, const core::ArmConfig& q, std::size_t s, const core::ArmConfig& q_s) {
    return checker.robotsFree(static_cast<int>(r), at(r, q), std::nullopt, static_cast<int>(s), at(s, q_s), std::nullopt);
  };
  // robot by robot: one that cannot fold stays at home for the robots after it too
  for (std::size_t r = 0; r < n; ++r) {
    bool free = checker.robotFree(static_cast<int>(r), at(r, folded[r]), {});
    for (std::size_t s = 0; s < n && free; ++s) {
      if (s == r) continue;
      free = free_of(r, folded[r], s, world.robots[s].home) && (s > r || free_of(r, folded[r], s, folded[s]));
    }
    if (!free) folded[r] = world.robots[r].home;
  }
  return folded;
}

}  // namespace dashbed::planner
