#pragma once
// SceneState: everything that moves in a rendered frame, independent of Bullet.

#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::sim {
class Simulation;
}

namespace dashbed::render {

/// The moving part of a scene at one instant; the static part (fixtures, regions, floor)
/// comes from the World.
struct SceneState {
  std::vector<std::vector<core::Pose>> link_poses;  ///< X_WL per [robot][model link], world frame
  std::vector<core::Pose> object_poses;             ///< X_WO per object of the World
  double time = 0.0;                                ///< the instant shown [s] (informative)
};

/// The current state of a simulation (its link poses, object poses and time).
SceneState captureScene(const sim::Simulation& simulation);

/// Robots at their given configurations (q per robot, all of the model's joints: arm then
/// fingers) and objects at the given poses, by the model's forward kinematics. Throws
/// std::invalid_argument if the counts or a q size do not match the world.
SceneState sceneFromConfigurations(const core::World& world, const core::RobotSet& robots,
                                   const std::vector<Eigen::VectorXd>& q, const std::vector<core::Pose>& X_WO,
                                   double time = 0.0);

/// Robots at their home configurations with open grippers, objects at their start poses
/// (the simulation's initial scene before it settles); uses core forward kinematics only.
SceneState sceneAtHome(const core::World& world, const core::RobotSet& robots);

}  // namespace dashbed::render
