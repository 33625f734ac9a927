#pragma once
// Robots at home: where every plan starts and ends. A world in which a robot standing at its
// home configuration collides with a fixture, the floor or another robot at home can never be
// planned, whatever the sampling: its base or home pose is written wrong, so it is a world-file
// error (core::WorldError, exit 3 on the command line), not a planning outcome.
// Also where a sequential plan's idle robots may wait instead of home: folded back over their
// bases, out of the shared workspace.

#include <vector>

#include <Eigen/Core>

#include "core/hande.h"
#include "core/world.h"
#include "planner/collision/collision_checker.h"

namespace dashbed::planner {

using core::kFingersOpen;

/// `robot` at its home configuration (World::robots[robot].home) with its gripper open, as the
/// collision checker takes it.
Eigen::VectorXd homeConfiguration(const core::World& world, const CollisionScene& scene, int robot);

/// Throws core::WorldError naming the world file, line and field (robots[i].home) when a robot
/// at home collides with the static scene or with another robot at home. `scene` must have
/// been built for `world`.
void requireFreeHomes(const core::World& world, const CollisionScene& scene);

/// Per robot, its folded configuration: home's shoulder pan and wrist angles with the upper arm
/// leaning back over the base and the forearm folded down in front of it (the gripper 0.21 m in
/// front of the base and 0.20 m above it, where home puts it 0.49 m in front). A robot whose
/// folded configuration (gripper open) collides with the static scene, or with another robot at
/// home or folded, gets its home instead. `scene` must have been built for `world`.
std::vector<core::ArmConfig> foldedConfigurations(const core::World& world, const CollisionScene& scene);

}  // namespace dashbed::planner
