#pragma once
// Loading a world completely: parse and validate the file, load the robot models, and check
// that every object start and goal is within some robot's reach.

#include <filesystem>
#include <memory>

#include "core/plan.h"
#include "core/reach.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::core {

struct LoadedWorld {
  std::unique_ptr<const World> world;
  std::unique_ptr<const RobotSet> robots;  ///< points into *world
  ReachMap reach;
};

/// Parses `file` (core/world_io.h), loads the robots and checks reachability.
/// Throws WorldError with file, line and field for any problem.
LoadedWorld loadWorld(const std::filesystem::path& file);

/// The same for a world already in memory (e.g. from a scenario generator). A world whose
/// fixtures have no derived geometry yet gets it first (deriveFixtureGeometry), as parsing does.
LoadedWorld validateWorld(World world);

/// validatePlan with the arm joint names, limits and speeds of the world's robot model.
/// Throws PlanError naming `plan_file`.
void validatePlanForWorld(const Plan& plan, const World& world, const RobotSet& robots, const std::string& plan_file);

}  // namespace dashbed::core
