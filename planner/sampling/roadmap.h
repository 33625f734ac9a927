#pragma once
// The move planner of the motion hypergraph (paper: Method > Motion Hypergraph, Alg. 3):
// a probabilistic roadmap per task-space element — one robot alone (fingers open), or one
// robot holding an object in a fixed grasp (the held object is part of the robot's collision
// geometry). The roadmap is grown incrementally: `grow(n)` adds n collision-free samples (the
// paper starts with 10 per element and adds 10 per round); transition start and end
// configurations are added as nodes with `addConfiguration`, which connects them to their
// nearest neighbours.
//
// Edges are straight joint-space motions, validated lazily (only when a query's shortest path
// uses them) with CollisionChecker::motionFree at the scene's motion resolution against the
// static scene. Each validated edge also records which object sites (ObjectSites: every
// object at its start and at its goal) it would touch; a query passes the set of sites that
// are occupied at the time of the move and only uses edges that touch none of them.
//
// Metric: the time a rest-to-rest move needs at full joint speed, max_j |dq_j| / v_j [s].
// Everything is deterministic: the same seed and calls give the same roadmap and paths.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/ur_ik.h"
#include "planner/collision/collision_checker.h"
#include "planner/sampling/object_sites.h"

namespace dashbed::planner {

struct RoadmapSettings {
  /// Nearest nodes each new node is connected to (fixed k, not PRM*'s growing k); more edges to
  /// validate, better connectivity.
  int neighbours = 10;
  /// Longest edge, as rest-to-rest time at full joint speed [s]; longer edges connect sparse
  /// roadmaps but collide more often.
  double max_edge_time = 1.5;
  /// Seeded random shortcut attempts per returned path; more give shorter paths, more checks.
  int shortcut_attempts = 30;
};

class Roadmap {
 public:
  /// A roadmap for `robot` of `scene`, holding `held` (std::nullopt: the robot alone, fingers
  /// at `finger` = open). `finger` is the finger position used for every configuration [m].
  /// `sites` must outlive the roadmap. `seed` seeds its sampler.
  Roadmap(const CollisionScene& scene, const ObjectSites& sites, int robot, std::optional<HeldObject> held,
          double finger, std::uint64_t seed, const RoadmapSettings& settings = {});

  /// Adds `samples` uniformly sampled configurations within the arm's joint limits that are
  /// free against the static scene (and itself), each connected to its nearest neighbours.
  /// Gives up on a sample after 100 rejected draws. Returns the number added.
  int grow(int samples);

  /// Like grow(), with each joint drawn within +-spread [rad] of `center`'s (and the sampled
  /// range): nodes in the pocket of a configuration that uniform samples rarely reach, such as
  /// an arm reaching into a shelf.
  int growNear(const core::ArmConfig& center, int samples, double spread);

  /// Adds q as a node connected to its nearest neighbours and returns its id, or -1 when q
  /// collides with the static scene. Adding the same configuration twice returns the same id.
  int addConfiguration(const core::ArmConfig& q);

  /// Shortest path (waypoints, both ends included) from node `from` to node `to` using only
  /// edges that are free against the static scene and touch none of the `occupied` sites,
  /// shortcut (seeded, deterministic); std::nullopt when the roadmap does not connect them.
  /// The direct straight motion is tried first. One waypoint when from == to.
  std::optional<std::vector<core::ArmConfig>> query(int from, int to, const SiteSet& occupied);

  /// An extra condition on straight motions, true when a -> b is clear of something the
  /// roadmap does not know (e.g. another robot standing in the way).
  using MotionFilter = std::function<bool(const core::ArmConfig& a, const core::ArmConfig& b)>;

  /// query() using only motions that also pass `clear`. What `clear` rejects is forgotten after
  /// the call; the static checks it causes are cached as usual. Gives up (std::nullopt) after
  /// 25 edges rejected by `clear`.
  std::optional<std::vector<core::ArmConfig>> query(int from, int to, const SiteSet& occupied,
                                                    const MotionFilter& clear);

  /// True when the straight motion a -> b is free against the static scene and touches none of
  /// the `occupied` sites.
  bool motionFree(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& occupied);

  /// The sites of `among` (of objects other than the held one) that the straight motion a -> b
  /// touches, i.e. those for which motionFree with only that site occupied is false. Every
  /// motion's check (static scene, each site) is cached by its directed ends.
  SiteSet touchedSites(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& among);

  int robot() const;
  const std::optional<HeldObject>& held() const;
  int numNodes() const;
  int numEdges() const;
  int numValidatedEdges() const;
  const core::ArmConfig& node(int id) const;

  /// The full model configuration (arm + fingers at this roadmap's finger position) of an arm
  /// configuration, as the collision checker wants it.
  Eigen::VectorXd fullConfiguration(const core::ArmConfig& q) const;

 private:
  struct Impl;  // scene, sampler, checker, nodes, edges and caches (roadmap.cpp)
  std::unique_ptr<Impl> impl_;

 public:
  ~Roadmap();
  Roadmap(Roadmap&&) noexcept;
  Roadmap& operator=(Roadmap&&) noexcept;
};

}  // namespace dashbed::planner
