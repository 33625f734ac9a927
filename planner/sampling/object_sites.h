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
//
// Set-aside sites: an object may also be given a spot to be set down at for a while, picked up
// again later and carried on to its goal (an intermediate placement). The planner gives one to
// an object standing where some other object's every pick reaches over it (setAsideSites): a
// shelf item in the way of the one behind it, which must go in after that one.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/pose.h"
#include "core/world.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"

namespace dashbed::planner {

/// Room a gripper needs beside a placed object on each side: 17.4 mm fingertip thickness plus
/// clearance (URDF finger geometry) [m].
inline constexpr double kFingerRoom = 0.025;
/// How far an open Hand-E reaches from the TCP along its closing axis, plus 2 mm clearance:
/// 25 mm stroke + 17.4 mm fingertip (URDF finger geometry) + 2 mm [m]. A slot's centre keeps
/// this far from the region's edges, so the gripper can open there beside a bin wall.
inline constexpr double kOpenFingerReach = 0.0444;

/// A set of occupied object sites (bit per site index of ObjectSites).
class SiteSet {
 public:
  explicit SiteSet(int sites = 0) : bits_((sites + 63) / 64, 0) {}
  void set(int site, bool on = true);
  bool test(int site) const;
  bool intersects(const SiteSet& other) const;
  /// Every site of this set is in `other` (sets of the same sites).
  bool subsetOf(const SiteSet& other) const;
  bool none() const;
  bool operator==(const SiteSet&) const = default;

 private:
  std::vector<std::uint64_t> bits_;
};

struct ObjectSites {
  std::vector<core::Pose> start;                ///< [object] X_WO at its start
  std::vector<std::optional<core::Pose>> goal;  ///< [object] X_WO of its goal placement; none without a goal
  std::vector<int> goal_region;                 ///< [object] index into World::regions, or -1
  /// [object] X_WO where it may be set aside (none by default; empty: none for any object)
  std::vector<std::optional<core::Pose>> aside;

  int numObjects() const { return static_cast<int>(start.size()); }
  /// Sites are numbered 3 o (object o at its start), 3 o + 1 (at its goal) and 3 o + 2 (set
  /// aside).
  int numSites() const { return 3 * numObjects(); }
  static int startSite(int object) { return 3 * object; }
  static int goalSite(int object) { return 3 * object + 1; }
  static int asideSite(int object) { return 3 * object + 2; }
  static int objectOf(int site) { return site / 3; }
  /// The object resting at a site; std::nullopt for a goal or set-aside site the object does
  /// not have.
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

/// Least room a set-aside spot keeps around the object, to every other site, the regions, the
/// fixtures and the robots' bases, when the surface has such a spot (else the roomiest is
/// taken) [m].
inline constexpr double kAsideRoom = 0.12;

/// Gives each of `objects` a set-aside site (ObjectSites::aside): a spot on the stable surface it
/// starts on, in its start orientation, that a robot picking it at its start reaches, out of
/// every other site (start, goal, set-aside), every goal region, fixture and robot base by the
/// open gripper's reach. Of those, the nearest to its start with kAsideRoom all round, else the
/// roomiest; and of those, the first that `keeps_clear(object, X_WO)` accepts when it accepts
/// any (the planner: a spot that leaves some pick of each object it is set aside for clear).
/// An object without such a spot (e.g. no surface has room) gets none. Returns the objects
/// given one.
std::vector<int> setAsideSites(const core::LoadedWorld& world, ObjectSites& sites, const std::vector<int>& objects,
                               const std::function<bool(int, const core::Pose&)>& keeps_clear = {});

}  // namespace dashbed::planner
