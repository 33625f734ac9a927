#include "core/world_loader.h"

#include <algorithm>
#include <sstream>

#include "core/world_io.h"

namespace dashbed::core {

namespace {

/// Throws WorldError naming robots[i].home[j] when a home angle is outside its joint's limits.
void requireHomesWithinLimits(const World& world, const RobotSet& robots) {
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    const RobotModel& model = *robots[r].model;
    for (int j = 0; j < 6; ++j) {
      const JointModel& joint = model.joints()[model.movableJoints()[j]];
      const double q = world.robots[r].home[j];
      if (q < joint.lower || q > joint.upper) {
        std::ostringstream msg;
        msg << joint.name << " at " << q << " rad is outside its limits [" << joint.lower << ", " << joint.upper << "]";
        throw WorldError(world.robots[r].where,
                         "robots[" + std::to_string(r) + "].home[" + std::to_string(j) + "]", msg.str());
      }
    }
  }
}

}  // namespace

LoadedWorld validateWorld(World world) {
  // a world built in memory (every fixture has solid parts once derived); derived entries
  // edited since are kept
  if (std::any_of(world.fixtures.begin(), world.fixtures.end(), [](const FixtureSpec& f) { return f.boxes.empty(); })) {
    deriveFixtureGeometry(world);
  }
  LoadedWorld loaded;
  loaded.world = std::make_unique<const World>(std::move(world));
  loaded.robots = std::make_unique<const RobotSet>(*loaded.world);
  requireHomesWithinLimits(*loaded.world, *loaded.robots);
  loaded.reach = computeReach(*loaded.world, *loaded.robots);
  requireReachable(*loaded.world, loaded.reach);
  return loaded;
}

LoadedWorld loadWorld(const std::filesystem::path& file) { return validateWorld(loadWorldFile(file)); }

void validatePlanForWorld(const Plan& plan, const World& world, const RobotSet& robots,
                          const std::string& plan_file) {
  if (robots.size() == 0) throw PlanError(plan_file + ": the world has no robots");
  const RobotModel& model = *robots[0].model;
  std::array<std::string, 6> names;
  std::array<double, 6> lower{}, upper{}, velocity{};
  for (int i = 0; i < 6; ++i) {
    const JointModel& joint = model.joints()[model.movableJoints()[i]];
    names[i] = joint.name;
    lower[i] = joint.lower;
    upper[i] = joint.upper;
    velocity[i] = joint.max_velocity;
  }
  validatePlan(plan, world, names, lower, upper, velocity, plan_file);
}

}  // namespace dashbed::core
