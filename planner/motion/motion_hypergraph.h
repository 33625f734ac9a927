#pragma once
// The motion hypergraph H_M of the DaSH method (paper: Method > Motion Hypergraph, Alg. 3),
// grounded on a task-space hypergraph H_T.
//
//  motion vertices      a task-space vertex with a configuration: a robot alone or holding an
//                       object (the arm configuration, and for holding the grasp), an object
//                       resting at a site (its start, goal or set-aside pose). The vertex map lists the
//                       motion vertices of each task-space vertex.
//  transition hyperarcs sampled instances of H_T's pick, place and handoff hyperarcs, each
//                       carrying the timed motions of its robots (TransitionSampler).
//  move hyperarcs       paths within one task-space element between two of its motion
//                       vertices, from that element's roadmap: a robot alone, or a robot
//                       holding one object in one grasp (Roadmap). They are planned on demand by
//                       the search (implicit construction) and cached; a move depends on which
//                       object sites are occupied while it runs.
//  source and target    the virtual source leads to the start: every robot alone at its home
//                       configuration, every object at its start site; the virtual target is
//                       reached from every object with a goal resting at its goal site and every
//                       robot alone at home.
//
// Construction follows Alg. 3 in rounds: the first round samples every pick hyperarc and grows
// each roadmap when it is first used (RepresentationSettings::initial_roadmap_samples); place
// and handoff hyperarcs are sampled for each grasp the search finds an object held in, the
// first time it needs them (their tail vertex exists only once that grasp is reachable);
// every later round (expand()) adds handoff samples for every grasp seen so far, grows every
// roadmap by roadmap_samples_per_round and plans moves afresh on the grown roadmaps (a new
// round gives conflict resolution new paths, not only the moves that failed before). Sampling
// is seeded per hyperarc, grasp and round, so the hypergraph does not depend on the order in
// which the search asks.

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "planner/collision/home_check.h"
#include "planner/sampling/object_sites.h"
#include "planner/sampling/roadmap.h"
#include "planner/task_space/task_space_hypergraph.h"
#include "planner/sampling/timing.h"
#include "planner/sampling/transition_sampler.h"

namespace dashbed::planner {

/// Where a sequential plan's idle robots wait while the others' steps run.
enum class IdlePose {
  kHome,    ///< at home
  kFolded,  ///< folded back over their bases, out of the shared workspace (foldedConfigurations)
};

struct RepresentationSettings {
  /// Uniform samples of a roadmap when it is created, plus roadmap_samples_per_round per past
  /// round (paper: 10); fewer start cheaper and leave more to on-demand growth.
  int initial_roadmap_samples = 10;
  /// Samples added to every roadmap per round of expansion (paper: 10); more paths, more time.
  int roadmap_samples_per_round = 10;
  /// New handoff samples per handoff hyperarc and giver grasp per round (>= 1); more give more
  /// handoff poses and widen the search.
  int handoff_samples_per_round = 2;
  /// Times per round a roadmap may grow on the spot (move_growth_samples each) for a move or
  /// detour it cannot connect; more leave fewer moves unplanned, at more construction time.
  int move_growth_attempts = 3;
  /// Samples per on-the-spot growth: about half uniform, a quarter near each end of the move.
  int move_growth_samples = 30;
  /// Joint range around a move's end of the samples drawn near it [rad]; narrower fills pockets.
  double move_growth_spread = 0.5;
  /// Move speed cap, fraction of each joint's velocity limit, in (0, 1]; higher: shorter plans,
  /// less controller margin.
  double velocity_fraction = 0.6;
  /// Move acceleration cap for every joint [rad/s^2] (at most the world's
  /// safety.max_joint_acceleration is used); higher: shorter moves, larger torques.
  double max_acceleration = 4.0;
  /// Move TCP speed cap, fraction of the world's safety.tcp_speed, in (0, 1]; higher: shorter
  /// moves, less margin to the safety limit.
  double tcp_speed_fraction = 0.9;
  /// Transition sampler (P_trans) settings.
  TransitionSettings transitions;
  /// Roadmap (P_move) settings.
  RoadmapSettings roadmap;
  /// Collision checker settings.
  CollisionSettings collision;

  /// Throws std::invalid_argument naming the field when a value is out of range.
  void validate() const;
};

/// A motion vertex: a task-space vertex and a configuration of its bodies.
struct MotionVertex {
  int task_vertex = -1;
  core::ArmConfig q{};  ///< robot alone / holding: the arm configuration
  int grasp = -1;       ///< robot holding: index into graspsOf(object)
  int site = -1;        ///< object resting: ObjectSites index (start or goal)
};

/// A sampled transition hyperarc: the sample and its tail and head motion vertices.
struct MotionTransition {
  TransitionSample sample;
  std::vector<int> tail;  ///< motion vertex ids
  std::vector<int> head;
};

/// A move hyperarc: a path of one robot within one element, timed rest to rest per piece.
struct Move {
  int robot = -1;
  int object = -1;  ///< held object, or -1 for the robot alone
  int grasp = -1;
  std::vector<core::ArmConfig> path;  ///< both ends included; one point when already there
  /// Per piece: the scale of the velocity limits that keeps the TCP within its speed cap.
  std::vector<double> speed_scale;
  Millis duration = 0;
  SiteSet touches;   ///< object sites the path would touch (all of them unoccupied when planned)
  SiteSet occupied;  ///< object sites it was planned around
};

class MotionHypergraph {
 public:
  /// The references must outlive the hypergraph. Throws std::invalid_argument for bad settings
  /// and std::runtime_error when a goal region has no room (objectSites).
  MotionHypergraph(const core::LoadedWorld& world, const TaskSpaceHypergraph& task_space, std::uint64_t seed,
                   const RepresentationSettings& settings = {});
  /// The same on given object sites (objectSites(world) and, with set-aside hyperarcs in
  /// `task_space`, the set-aside sites of their objects) and, when `scene` is given, in that
  /// collision scene (built from `world` with settings.collision; built here when null).
  /// `transitions` is the transition planner P_trans (a TransitionSampler in that scene with
  /// settings.transitions when null). Throws std::invalid_argument when a set-aside hyperarc's
  /// object has no set-aside site.
  MotionHypergraph(const core::LoadedWorld& world, const TaskSpaceHypergraph& task_space, ObjectSites sites,
                   std::uint64_t seed, const RepresentationSettings& settings = {},
                   std::shared_ptr<const CollisionScene> scene = nullptr,
                   std::unique_ptr<TransitionPlanner> transitions = nullptr);
  ~MotionHypergraph();

  const core::LoadedWorld& world() const { return *world_; }
  const TaskSpaceHypergraph& taskSpace() const { return *task_space_; }
  const CollisionScene& scene() const { return *scene_; }
  const ObjectSites& sites() const { return sites_; }
  const RepresentationSettings& settings() const { return settings_; }
  const TimingLimits& timing() const { return timing_; }
  /// The limits piece i of `move` is timed with (timing() with its speed scale).
  TimingLimits pieceTiming(const Move& move, std::size_t i) const;

  /// Virtual source / target as motion vertex sets (the start and goal decomposition).
  const std::vector<int>& sourceVertices() const { return source_; }
  const std::vector<int>& targetVertices() const { return target_; }

  /// The grasps an object has been seen held in (ids are indices).
  const std::vector<Grasp>& graspsOf(int object) const { return grasps_.at(object); }

  /// Transition hyperarcs sampling task-space hyperarc `hyperarc` whose tail needs the robot to
  /// hold the object in `grasp` (place, handoff) — or any, for a pick (grasp -1). Samples on
  /// first use. Ids index transition().
  const std::vector<int>& transitionsOf(int hyperarc, int grasp);
  const MotionTransition& transition(int id) const { return transitions_.at(id); }

  /// Where `robot` waits in `pose`, gripper open: its home, or its folded configuration
  /// (foldedConfigurations: home again for a robot that cannot fold).
  const core::ArmConfig& idleConfiguration(int robot, IdlePose pose) const;

  /// The move hyperarc taking `robot` (alone when object == -1, else holding `object` in
  /// `grasp`) from `from` to `to` without touching any `occupied` site, or nullptr when the
  /// element's roadmap does not connect them yet. Cached; the pointer stays valid.
  /// With `around_idle`, the path also keeps clear of every other robot standing at its
  /// idleConfiguration in that pose with its gripper open (a sequential plan's idle robots).
  const Move* move(int robot, int object, int grasp, const core::ArmConfig& from, const core::ArmConfig& to,
                   const SiteSet& occupied, std::optional<IdlePose> around_idle = std::nullopt);

  /// `original` planned again on its roadmap, with every straight piece also passing `clear`
  /// (conflict resolution's detour around other robots), or nullptr when the roadmap has no
  /// such path. Not cached; the pointer stays valid for the hypergraph's life.
  const Move* detour(const Move& original, const Roadmap::MotionFilter& clear);

  /// `original` split at a parking configuration: a node of its roadmap passing `clear` (out
  /// of another robot's way), reached by a first move from the start and left by a second one
  /// to the end (both as move() plans them). Of the nodes passing `clear`, the `attempts` with
  /// the shortest detour (start -> node -> end, rest-to-rest time) are tried in that order;
  /// std::nullopt when none works.
  std::optional<std::pair<const Move*, const Move*>> parking(const Move& original,
                                                             const std::function<bool(const core::ArmConfig&)>& clear,
                                                             int attempts = 5);
  /// `original` split at the parking configuration `q` (taken by value: move() may add roadmap
  /// nodes), both parts as move() plans them; std::nullopt when q is one of its ends or either
  /// part has no path.
  std::optional<std::pair<const Move*, const Move*>> parkingAt(const Move& original, core::ArmConfig q);

  /// Scheduling constraints (paper: Transition-extended Hypergraph > Scheduling Constraints):
  /// pairs of transition hyperarcs whose robots conflict resolution could not order around each
  /// other. A transition history may include at most one transition of each pair. When a
  /// second pair joins samples of the same two task-space hyperarcs, the constraint holds for
  /// every pair of their samples (hyperarc-hyperarc: it is where the robots act, not the sample,
  /// that cannot be ordered). add... returns false when the pair was known already (or is one
  /// transition).
  bool addSchedulingConstraint(int transition_a, int transition_b);
  bool schedulingConflict(int transition_a, int transition_b) const;
  /// Whether `transition` is in some scheduling constraint's pair (or its hyperarc in a
  /// hyperarc constraint's): a history holding it excludes other transitions.
  bool schedulingConstrained(int transition) const;
  /// Vertex-hyperarc scheduling constraints on a robot's start (home) vertex: the transition's
  /// motion runs into `robot` standing at home, so a transition history may only include it
  /// once that robot has left home (taken a transition of its own). Promoted to the task-space
  /// hyperarc on a second sample, as above. Returns false when known already.
  bool addHomeConstraint(int transition, int robot);
  bool homeConflict(int transition, int robot) const;
  /// True when every motion of `transition` keeps clear of `robot` standing at its
  /// idleConfiguration in `pose` with its gripper open, where a sequential plan's idle robots
  /// wait, along the key curves the simulator follows. A geometric check (unlike homeConflict),
  /// made once per pair and pose.
  bool clearOfIdle(int transition, int robot, IdlePose pose);
  /// True when some motion of `transition` touches `object` resting where it says, along the
  /// key curves the simulator follows (as the sample's `touches` are found for the sites).
  bool touches(int transition, const RestingObject& object);
  std::size_t numSchedulingConstraints() const { return scheduling_constraints_.size() + home_constraints_.size(); }
  void clearSchedulingConstraints();  ///< all of them

  /// True when `object` can never be placed at its goal: no robot with a place hyperarc for it
  /// has a place sample for any grasp that robot could hold it in — one of its own pick
  /// samples' (at the start or the set-aside site, as if it could always be set aside) or,
  /// through a handoff hyperarc from a robot that could hold it, a receiver grasp
  /// of that robot's grasp (TransitionSampler::handoffGrasps), and so on. Picks and places are
  /// deterministic (sampled per grasp, not drawn) and receiver grasps a fixed list, so no later
  /// round can add one: the problem is infeasible (e.g. a box with only one face pair narrow
  /// enough for the gripper, which one robot picks and only another can place: no handoff can
  /// give the receiver a different face pair). Adds nothing to the graph.
  bool neverPlaceable(int object);
  /// True when some place hyperarc of `object` into its goal has a sample (for any grasp asked
  /// for so far).
  bool hasPlaceSample(int object) const;

  /// One more round of Alg. 3's construction: handoff samples for every grasp seen, roadmap
  /// growth. Returns the number of the round just completed (the first is 1).
  int expand();
  int rounds() const { return round_; }

  const MotionVertex& vertex(int id) const { return vertices_.at(id); }
  std::size_t numVertices() const { return vertices_.size(); }
  std::size_t numTransitions() const { return transitions_.size(); }
  std::size_t numMoves() const;  ///< moves found, all rounds
  std::size_t numRoadmaps() const { return roadmaps_.size(); }
  std::size_t numRoadmapNodes() const;
  /// The vertex map: motion vertices of a task-space vertex, in id order.
  std::vector<int> verticesOf(int task_vertex) const;

  /// Wall-clock time spent building the representation so far (sampling transitions, growing
  /// roadmaps, planning moves) [s].
  double constructionSeconds() const { return construction_seconds_; }

  /// The lowest duration of any transition sampled so far for a task-space hyperarc, or
  /// std::nullopt when none is.
  std::optional<Millis> bestDuration(int hyperarc) const;

  /// The task-space hyperarcs the search has asked for samples of (for some grasp) and that have
  /// none yet, in id order: e.g. handoffs of an object too small for two grippers.
  std::vector<int> unsampledHyperarcs() const;

 private:
  int addVertex(const MotionVertex& vertex);
  int robotVertex(int robot, const core::ArmConfig& q);
  int holdingVertex(int robot, int object, int grasp, const core::ArmConfig& q);
  int siteVertex(int site);
  int graspId(int object, const Grasp& grasp);
  void addTransition(TransitionSample sample);
  void sampleHandoffs(int hyperarc, int grasp, int round);
  Roadmap& roadmap(int robot, int object, int grasp);
  Move makeMove(int robot, int object, int grasp, std::vector<core::ArmConfig> path, const SiteSet& occupied);
  /// Per piece of `path`: the speed scale that keeps the TCP within tcp_speed_fraction of the
  /// world's safety.tcp_speed (speedScaleWithin, the TCP's rate sampled along the piece).
  std::vector<double> tcpSpeedScales(const std::vector<core::ArmConfig>& path) const;

  const core::LoadedWorld* world_;
  const TaskSpaceHypergraph* task_space_;
  std::uint64_t seed_;
  RepresentationSettings settings_;
  std::shared_ptr<const CollisionScene> scene_;
  std::unique_ptr<CollisionChecker> checker_;  // for move(..., around_idle) and clearOfIdle
  std::vector<core::ArmConfig> folded_;          // [robot] idleConfiguration(robot, kFolded)
  ObjectSites sites_;
  std::unique_ptr<TransitionPlanner> sampler_;  // P_trans
  TimingLimits timing_;
  int round_ = 1;
  double construction_seconds_ = 0.0;

  std::vector<MotionVertex> vertices_;
  std::map<std::tuple<int, int, int, core::ArmConfig>, int> vertex_ids_;  // (task vertex, grasp, site, q)
  std::vector<std::vector<Grasp>> grasps_;                                // [object]
  std::deque<MotionTransition> transitions_;  // a deque: references stay valid as it grows
  std::vector<std::optional<Millis>> best_duration_;  // [task-space hyperarc] see bestDuration()
  std::map<std::pair<int, int>, std::vector<int>> transitions_of_;        // (hyperarc, grasp)
  std::map<std::tuple<int, int, int>, Roadmap> roadmaps_;                 // (robot, object, grasp)
  std::map<std::tuple<int, int, int>, int> grown_this_round_;             // samples added by move()
  // move(..., around_idle)'s answers per roadmap and pose: (a, b) -> the straight motion keeps
  // clear of the other robots standing idle
  std::map<std::tuple<int, int, int, IdlePose>, std::map<std::pair<core::ArmConfig, core::ArmConfig>, bool>> clear_of_idle_;
  std::map<std::tuple<int, int, int, core::ArmConfig, core::ArmConfig, std::vector<bool>, std::optional<IdlePose>>, std::unique_ptr<Move>>
      moves_;  // cache of move() (null: no path)
  std::deque<Move> detours_;  // made by detour()
  std::vector<std::unique_ptr<Move>> retired_moves_;  // moves of earlier rounds (pointers to them stay valid)
  std::set<std::pair<int, int>> scheduling_constraints_;  // (lower id, higher id)
  std::map<std::pair<int, int>, int> hyperarc_pair_constraints_;  // (task-space hyperarcs) -> pairs
  std::set<std::pair<int, int>> hyperarc_constraints_;            // those with two or more
  std::set<std::pair<int, int>> home_constraints_;                // (transition, robot)
  std::map<std::pair<int, int>, int> hyperarc_home_counts_;       // (task-space hyperarc, robot) -> samples
  std::set<std::pair<int, int>> hyperarc_home_constraints_;       // those with two or more
  std::map<std::tuple<int, int, IdlePose>, bool> clear_of_idle_transition_;  // (transition, robot, pose) -> clearOfIdle
  std::vector<int> source_, target_;
};

}  // namespace dashbed::planner
