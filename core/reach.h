#pragma once
// Which robot can reach what: the IK-level reachability of object starts and goals.
//
// A robot "reaches" an object pose when its arm has an IK solution within joint limits for at
// least one parallel-jaw grasp of the object there (core/grasps.h). Collisions are not
// considered here; the planner checks them.

#include <optional>
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
/// part); which robots may place an object is decided by its goal slot (planner/sampling/object_sites.h).
bool reachesPlacementIn(const PlacedRobot& robot, const Region& region, const ObjectSpec& object);

ReachMap computeReach(const World& world, const RobotSet& robots);

/// Throws WorldError (file:line: objects[i] / goals[j] ...) for the first object whose start,
/// or whose goal placement, no robot reaches.
void requireReachable(const World& world, const ReachMap& reach);

}  // namespace dashbed::core

namespace dashbed::core {

/// The box in which two robots hand an object over, in the frame of the line between their
/// bases: object centres within `spread` of the zone's middle along and across the line, from
/// `min_height` to `max_height` above the zone's reference height.
struct HandoffShape {
  /// Lowest object-centre height of the zone above its reference height (the higher base, for
  /// the box over the bases' midpoint) [m].
  double min_height = 0.15;
  /// Highest object-centre height of the zone above that reference height [m].
  double max_height = 0.45;
  /// Half-width of the zone along and across the line between the two bases [m].
  double spread = 0.10;
};

/// Where two robots hand objects over: the HandoffShape box around `mid`, its heights counted
/// from `top`.
struct HandoffZone {
  Eigen::Vector3d mid = Eigen::Vector3d::Zero();  ///< horizontal middle of the zone (z unused)
  double top = 0.0;                               ///< [m] the heights' reference
};

/// The handoff zone of two robots: the first box, of a fixed list, that no fixture comes
/// within 3 cm of, with no fixture on the straight lines (0.12 m wide) from the robots'
/// shoulders to its centre, and in which both can grasp a 40 mm cube (at one of its centre, the
/// middles of its faces and edges, or its corners: 27 points). The list starts with the box over the
/// midpoint of the bases, heights counted from the higher base, and goes on with that box moved
/// along and across the line between the bases by up to 0.3 and 0.4 m and up or down by up to
/// 0.3 and 0.75 m, nearest first, boxes whose middle is behind either robot (against its
/// base's x axis) after all others: so a post between the robots, a base on a riser or one
/// hanging from a beam move the zone to where a handoff can happen. std::nullopt when no box
/// qualifies (the robots cannot hand over). The task-space hypergraph's handoff test and the
/// handoff sampler's poses; symmetric in the two robots.
std::optional<HandoffZone> handoffZone(const World& world, const PlacedRobot& a, const PlacedRobot& b,
                                       const HandoffShape& shape = {});

}  // namespace dashbed::core
