#pragma once
// The task-space hypergraph H_T = (V_T, E_T) of the decoupled MM-DaSH representation
// (paper: Method > Task Space Hypergraph, Alg. 2; Application to Multi-Manipulator
// Rearrangement > Decoupled Representation; Representation Analysis > Hypergraph
// Representation).
//
// Vertices are task-space elements whose bodies cannot be split without relaxing a grasp
// constraint: a robot alone, an object resting on a stable surface, a robot holding an object.
// Hyperarcs are transition hyperarcs (the decoupled representation has no composition
// hyperarcs), one per allowed pick, place and handoff action:
//   pick    {r alone, o resting}      -> {r holding o}
//   place   {r holding o}             -> {r alone, o resting}
//   handoff {r1 holding o, r2 alone}  -> {r1 alone, r2 holding o}
//
// Resting at start vs. at goal. The paper has one vertex per object for "resting on a stable
// surface": the element's constraint is "on some stable surface", its configuration space holds
// every stable pose, and which pose is occupied is fixed only by the motion layer's vertices
// (task-space vertex + configuration). We keep that single vertex (so the sizes are the paper's
// mn + m + n and mn^2 + mn) and put the pose on the hyperarc instead: a pick takes the object
// from its start pose, a place puts it into its goal region (TransitionHyperarc::rest_pose).
// Hence a pick hyperarc exists only for robots reaching the object's start and a place hyperarc
// only for robots reaching its goal. An object may also have a set-aside site (an intermediate
// placement, ObjectSites::aside): then a robot that can hold it and reaches that site has a
// place hyperarc setting it aside and a pick hyperarc taking it up again, both with
// RestPose::kAside and the same two vertices (the object resting, the robot holding it).
// Regrasps are not part of this action space.
//
// Construction follows Alg. 2: Decompose(T_init) gives every robot alone and every object
// resting; ExpandHypergraph (breadth first) then adds every allowed transition whose tail
// vertices exist, with its head vertices, until a round adds no hyperarc. So only obtainable
// elements become vertices: "r holding o" exists only if r can pick o at its start or receive
// it in a handoff from a robot that can hold it. Vertex and hyperarc ids are then assigned in a
// canonical order (below), independent of the expansion order.

#include <string>
#include <vector>

#include "core/reach.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::planner {

/// Kind of a task-space element (vertex of H_T).
enum class TaskElementKind {
  kRobotAlone,    ///< one robot, holding nothing
  kObjectResting, ///< one object, resting on a stable surface
  kRobotHolding,  ///< one robot and the object it grasps
};

/// A vertex of the task-space hypergraph. `robot` is -1 for kObjectResting, `object` is -1
/// for kRobotAlone.
struct TaskSpaceVertex {
  TaskElementKind kind = TaskElementKind::kRobotAlone;
  int robot = -1;
  int object = -1;
  bool operator==(const TaskSpaceVertex&) const = default;
};

/// Kind of a transition hyperarc (the action it stands for).
enum class TransitionKind { kPick, kPlace, kHandoff };

/// The stable pose a pick or place acts on; kNone for handoffs (held in the air).
enum class RestPose { kNone, kStart, kGoal, kAside };

/// A transition hyperarc <Tail, Head>. Tail and head hold vertex ids in ascending order.
struct TransitionHyperarc {
  TransitionKind kind = TransitionKind::kPick;
  std::vector<int> tail;
  std::vector<int> head;
  int object = -1;
  int robot = -1;     ///< the robot picking or placing; the giver of a handoff
  int receiver = -1;  ///< the receiving robot of a handoff, else -1
  RestPose rest_pose = RestPose::kNone;
};

/// The allowed transitions A of Alg. 2 for pick/place/handoff rearrangement.
struct AllowedTransitions {
  int robots = 0;
  int objects = 0;
  /// reach.start[o]: robots that may pick object o at its start pose; reach.goal[o]: robots that
  /// may place it in its goal region. Both sized `objects`, robot indices in [0, robots).
  core::ReachMap reach;
  /// handoff[giver][receiver]: the two robots' workspaces overlap (robots x robots, diagonal
  /// ignored).
  std::vector<std::vector<bool>> handoff;
  /// aside[o]: robots that may set object o aside at its set-aside site and pick it up there
  /// again (those of them that can hold it). Empty (no set-aside sites) or sized `objects`.
  std::vector<std::vector<int>> aside;

  /// Everything reachable and every pair of robots overlapping (the Representation Analysis
  /// upper bound).
  static AllowedTransitions everything(int robots, int objects);

  /// Throws std::invalid_argument naming the first inconsistency (negative counts, wrong sizes,
  /// robot index out of range or repeated).
  void validate() const;
};

class TaskSpaceHypergraph {
 public:
  /// Builds H_T by Alg. 2 from the allowed transitions. Robots are named r0, r1, ... and
  /// objects o0, o1, ... Throws std::invalid_argument when `allowed` is inconsistent.
  explicit TaskSpaceHypergraph(const AllowedTransitions& allowed);

  /// The same from its parts: per-object reach sets and the handoff (overlap) matrix.
  TaskSpaceHypergraph(int robots, int objects, const core::ReachMap& reach,
                      const std::vector<std::vector<bool>>& overlap);

  /// The hypergraph of a world: robot and object names from the world, picks and places from
  /// `reach` (the planner passes placementReach: places by the robots reaching each object's
  /// goal slot), handoffs between robots that have a handoff zone (core::handoffZone, symmetric:
  /// asked once per pair). Throws
  /// std::invalid_argument when `reach` does not match the world.
  static TaskSpaceHypergraph fromWorld(const core::World& world, const core::RobotSet& robots,
                                       const core::ReachMap& reach);
  /// The same with set-aside hyperarcs: aside[o] the robots reaching object o's set-aside site.
  static TaskSpaceHypergraph fromWorld(const core::World& world, const core::RobotSet& robots,
                                       const core::ReachMap& reach, const std::vector<std::vector<int>>& aside);

  int numRobots() const { return allowed_.robots; }
  int numObjects() const { return allowed_.objects; }
  const AllowedTransitions& allowed() const { return allowed_; }

  /// Vertices in canonical order: robots alone (by robot), objects resting (by object), then
  /// the obtainable robot-holding-object elements ordered by (robot, object).
  const std::vector<TaskSpaceVertex>& vertices() const { return vertices_; }
  /// Hyperarcs in canonical order: picks by (robot, object), places by (robot, object),
  /// handoffs by (object, giver, receiver), then set-asides and pick-ups from there by (robot,
  /// object).
  const std::vector<TransitionHyperarc>& hyperarcs() const { return hyperarcs_; }

  std::size_t numVertices() const { return vertices_.size(); }
  std::size_t numHyperarcs() const { return hyperarcs_.size(); }
  std::size_t countVertices(TaskElementKind kind) const;
  std::size_t countHyperarcs(TransitionKind kind) const;

  /// Vertex id of robot r alone / object o resting (always present).
  int robotAloneVertex(int robot) const;
  int objectRestingVertex(int object) const;
  /// Vertex id of "robot holding object", or -1 when that element is not obtainable.
  int holdingVertex(int robot, int object) const;

  /// Hyperarcs whose tail / head contains vertex v, in ascending id order.
  const std::vector<int>& outgoing(int vertex) const { return outgoing_.at(vertex); }
  const std::vector<int>& incoming(int vertex) const { return incoming_.at(vertex); }

  /// D(T_init): the decomposition of the start element, every robot alone and every object
  /// resting at its start (vertex ids, ascending).
  std::vector<int> initialElements() const;

  /// Rounds of ExpandHypergraph that added hyperarcs (Alg. 2's loop, breadth first).
  int expansionRounds() const { return expansion_rounds_; }

  const std::string& robotName(int robot) const { return robot_names_.at(robot); }
  const std::string& objectName(int object) const { return object_names_.at(object); }

  /// "r0", "o1" (resting), "r0:o1" (r0 holding o1).
  std::string vertexName(int vertex) const;
  /// "pick(r0,o1)", "place(r1,o1)", "handoff(r0,r1,o1)" (giver, receiver, object);
  /// "place(r1,o1,aside)", "pick(r0,o1,aside)" at the set-aside site.
  std::string hyperarcName(int hyperarc) const;

 private:
  TaskSpaceHypergraph(const AllowedTransitions& allowed, std::vector<std::string> robot_names,
                      std::vector<std::string> object_names);
  void build();

  AllowedTransitions allowed_;
  std::vector<std::string> robot_names_;
  std::vector<std::string> object_names_;
  std::vector<TaskSpaceVertex> vertices_;
  std::vector<TransitionHyperarc> hyperarcs_;
  std::vector<int> holding_vertex_;  // [robot * objects + object] -> vertex id or -1
  std::vector<std::vector<int>> outgoing_;
  std::vector<std::vector<int>> incoming_;
  int expansion_rounds_ = 0;
};

/// Name of a kind, for output: "robot", "object", "holding" / "pick", "place", "handoff".
const char* toString(TaskElementKind kind);
const char* toString(TransitionKind kind);

/// "pick cube_0 by r1", "handoff cube_0 by r0 to r1": a task-space hyperarc in words.
std::string describeHyperarc(const core::World& world, const TaskSpaceHypergraph& task_space, int hyperarc);

}  // namespace dashbed::planner
