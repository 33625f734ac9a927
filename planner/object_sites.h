#pragma once
// Where objects rest during a rearrangement: each object's start pose and its assigned goal
// placement. These are the "sites" the planner checks motions against: a motion that would
// touch an object at one of its sites is allowed only while the object is elsewhere, which the
// hyperpath search turns into scheduling constraints (e.g. on a shelf, place the back object
// before the front one blocks the way).
//
// Goal placements: the objects sent to a region are given slots in it, in object order, side
// by side in rows (pitch = object size + room for the fingertips on both sides), centred on
// the region floor; slots some robot reaches (core::reachesBox) come first, so a region only
// partly within reach fills its reachable part. The object rests on the face it rests on at
// its start, turned about the vertical into line with the region. An object that starts in its
// goal region (restsIn) has no goal site: the plan leaves it where it is (the simulation's
// goal check still wants it there at the end), and the other objects' slots keep clear of it;
// unless that leaves a region no room for the objects sent there: then every object gets a slot.

#include <optional>
#include <vector>

#include "core/pose.h"
#include "core/world.h"
#include "core/world_loader.h"
#include "planner/collision_checker.h"

namespace dashbed::planner {

/// Room a gripper needs beside a placed object on each side: 17.4 mm fingertip thickness plus
/// clearance (URDF finger geometry) [m].
inline constexpr double kFingerRoom = 0.025;
/// How far an open Hand-E reaches from the TCP along its closing axis, plus 2 mm clearance:
/// 25 mm stroke + 17.4 mm fingertip (URDF finger geometry) + 2 mm [m]. A slot's centre keeps
/// this far from the region's edges, so the gripper can open there beside a bin wall.
inline constexpr double kOpenFingerReach = 0.0444;

struct ObjectSites {
  std::vector<core::Pose> start;                ///< [object] X_WO at its start
  std::vector<std::optional<core::Pose>> goal;  ///< [object] X_WO of its goal placement; none without a goal
  std::vector<int> goal_region;                 ///< [object] index into World::regions, or -1

  int numObjects() const { return static_cast<int>(start.size()); }
  /// Sites are numbered 2 o (object o at its start) and 2 o + 1 (at its goal).
  int numSites() const { return 2 * numObjects(); }
  static int startSite(int object) { return 2 * object; }
  static int goalSite(int object) { return 2 * object + 1; }
  /// The object resting at a site; std::nullopt for the goal site of an object without a goal.
  std::optional<RestingObject> site(int index) const;
};

/// Object-centre positions for objects of `size` side by side in a region, row by row, at
/// least kOpenFingerReach (or half the object) from its edges; one centred slot when none fits.
std::vector<Eigen::Vector3d> regionSlots(const core::Region& region, const Eigen::Vector3d& size);

/// True when an object at X_WO has its centre inside the region's box (as the simulation
/// judges a placement, without its tolerance).
bool restsIn(const core::Region& region, const core::Pose& X_WO);

/// The sites of every object of a world. Throws std::runtime_error naming the region when more
/// objects are sent to it than fit side by side within reach of a robot.
ObjectSites objectSites(const core::LoadedWorld& world);

/// The reach map the planner's task-space hypergraph is built from: the world's (which robots
/// reach each object's start), with the robots that may place an object being those reaching
/// its goal site rather than the region's centre (core::ReachMap::goal). A slot off-centre may
/// be in reach of a robot that misses the centre, and out of reach of one that reaches it.
core::ReachMap placementReach(const core::LoadedWorld& world, const ObjectSites& sites);

}  // namespace dashbed::planner
