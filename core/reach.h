#pragma once
// Which robot can reach what: the IK-level reachability of object starts and goals.
//
// A robot "reaches" an object pose when its arm has an IK solution within joint limits for at
// least one parallel-jaw grasp of the object there (core/grasps.h). Collisions are not
// considered here; the planner checks them.

#include <vector>

#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::core {

struct ReachMap {
  std::vector<std::vector<int>> start;  ///< [object] -> robots reaching its start pose
  /// [object] -> robots reaching a placement in its goal region (reachesPlacementIn)
  std::vector<std::vector<int>> goal;
};

/// Where an object sits when placed in a region: centred on the region floor, region yaw.
Pose placementPose(const Region& region, const ObjectSpec& object);

/// True when robot `robot` has an IK solution for some grasp of a box of `size` at X_WO.
bool reachesBox(const PlacedRobot& robot, const Pose& X_WO, const Eigen::Vector3d& size);

/// True when `robot` reaches some placement of `object` in `region`: at its centre
/// (placementPose), or else at a point of a 5 x 5 grid over its floor, half the object's width
/// in from the edges. A bin only partly in reach is a goal (the planner fills its reachable
/// part); which robots may place an object is decided by its goal slot (planner/object_sites.h).
bool reachesPlacementIn(const PlacedRobot& robot, const Region& region, const ObjectSpec& object);

ReachMap computeReach(const World& world, const RobotSet& robots);

/// Throws WorldError (file:line: objects[i] / goals[j] ...) for the first object whose start,
/// or whose goal placement, no robot reaches.
void requireReachable(const World& world, const ReachMap& reach);

}  // namespace dashbed::core

namespace dashbed::core {

/// True when two robots can both grasp a cube held in the air between them: some pose near
/// the middle of their bases (a small grid of points 0.15-0.45 m above the higher base) is
/// reachable by both. This is the handoff overlap test of the task-space hypergraph.
bool workspacesOverlap(const PlacedRobot& a, const PlacedRobot& b);

}  // namespace dashbed::core
