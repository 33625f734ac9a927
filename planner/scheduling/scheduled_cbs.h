#pragma once
// Conflict resolution (paper: Method > Conflict Resolution; Method Variants > Conflict
// Resolution): a scheduled variant of conflict-based search that turns the optimistic schedule
// of a transition history into one where no two robots collide.
//
// Each robot's part of the history becomes a sequence of segments (a move along its roadmap
// path, then its part of a transition, ...; finally the move home, or folded and home), with the robot standing
// still between segments. Segment start times S are the unknowns of a simple temporal network:
//  - a robot's segments run in order (S_next >= S + duration), and a move into a transition
//    ends as the transition starts (the robot waits before the move, where it was, rather
//    than in front of the transition, where it may block the robot it waits for);
//  - both robots of a handoff start its transition together;
//  - scheduling constraints from the object sites: a motion through an object's start site
//    starts after that object's pick is over; a motion through its goal site ends before its
//    place begins; an object set aside is taken up again after it has been set down, and a
//    motion through its set-aside site runs before it is set down or after it is taken up
//    again, as in the history;
//  - a sequential history (TransitionHistory::sequential) with its steps one after another
//    (SequentialSteps): every segment of a step's phase (ScheduleSegment::phase) starts after
//    every segment of the phase before has ended, so the robots of one step move while the
//    others stand at home or folded (or hold the object the step passes on); with idle robots
//    folded, the robots fold before the first step and unfold after the last;
//  - the constraints added by the high level.
// The earliest schedule is the longest-path solution (temporal_network.h; a cycle of positive lag
// means the constraints cannot all hold).
//
// High level: best-first over constraint sets by makespan, as a focal search (ECBS's high level):
// of the open nodes at most focal_weight times as long as the shortest, the one free of conflicts
// for longest (ties: shorter, fewer constraints, created first); with focal_weight 1 the shortest
// first, of equally short ones the one free for longest. Or along time, or depth first (NodeOrder).
// With a bound (makespan_below) nodes not shorter than it are dropped. A node's schedule is checked
// robot against robot, continuously in time (robot_conflicts.h). At the earliest conflict, between
// item A of robot a and item B of robot b (an item is a segment, or the robot standing still
// between two segments), the node branches into "A ends before B starts" and "B ends before A
// starts" — each a precedence (hyperarc-hyperarc or vertex-hyperarc scheduling constraint) on the
// segment starts. An order that cannot hold for a move arriving just in time on the cycle (A's
// own, or another robot's, which then cannot both wait where it was and make room in time) holds
// with that move arriving early and waiting in front of its transition; with A's own that is an
// order, with another's only one more child beside the reroutes below. When neither order can
// hold (a cycle with the schedule's own precedences), the low level changes a robot's route on
// its roadmap instead (at most max_reroutes roadmap searches per call, and as many again below a
// folded robot, see below; a reroute asked again, the same move around the same states, in
// another node gets the answer found before):
//  - a detour: the move A (or B) planned again so that it keeps clear of where the other robot
//    stands or passes meanwhile (its states every 100 ms of the move's window);
//  - a parking: a robot standing before a move, in the other's way, goes early to a roadmap
//    configuration clear of the other's item and waits there; the move is split in two. The
//    way to a parking is not parked again (a chain of parkings stays in the other's way). A
//    robot with empty hands also gets a second child where it folds back over its base to
//    wait (MotionHypergraph::idleConfiguration, IdlePose::kFolded), out of the shared
//    workspace, where the next robot coming through does not meet it either.
// A child repeats its parent's schedule up to their first difference, so the check starts at
// the earlier of that and the parent's conflict. Conflicts that no order resolves are reported
// back (ConflictResult::unordered) for the task search to avoid.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "planner/motion/motion_hypergraph.h"
#include "planner/scheduling/schedule.h"
#include "planner/search/transition_history.h"

namespace dashbed::planner {

/// The order in which the high level expands its nodes.
enum class NodeOrder {
  /// best first: the shortest schedule first, or any within focal_weight of it that is free of
  /// conflicts for longer
  kMakespan,
  /// along time: the node free of conflicts for longest first (ties: the shortest); fewer nodes
  /// where any schedule below a bound will do, not the shortest.
  kAlongTime,
  /// depth first: the children of the node whose conflict lies latest first, backtracking to the
  /// next latest (ties as kAlongTime); gets through crowded schedules, to longer ones.
  kDepthFirst,
};

struct ConflictResolutionBudget {
  /// High-level nodes one call may expand before it returns kBudget.
  int max_nodes = 2000;
  /// Node order of the high level: best first (focal), along time, or depth first.
  NodeOrder order = NodeOrder::kMakespan;
  /// kMakespan's focal weight (>= 1): nodes up to this factor longer than the shortest open one
  /// come first when free of conflicts for longer; above 1, fewer nodes, longer schedules.
  double focal_weight = 1.0;
  /// Nodes whose makespan reaches this are dropped (none: every node is kept).
  std::optional<Millis> makespan_below;
  /// Detours and parkings searched for (repeats are not searched again); the nodes below a
  /// folded robot have as many of their own.
  int max_reroutes = 24;
  std::function<bool()> stop;  ///< true when time is up (may be empty)
};

enum class ConflictStatus { kResolved, kUnresolvable, kBudget };

struct ConflictResult {
  ConflictStatus status = ConflictStatus::kUnresolvable;
  std::optional<Schedule> schedule;
  /// The makespan with no robot-robot conflict resolved yet (the high level's root; 0 when the
  /// schedule's own precedences contradict each other).
  Millis unresolved_makespan = 0;
  int nodes = 0;            ///< high-level nodes expanded
  int constraints = 0;      ///< precedences, detours and parkings in the solution
  /// for kUnresolvable / kBudget: the last conflict found, or why no schedule could start
  /// (contradicting precedences, none shorter than makespan_below)
  std::string reason;
  /// Conflicts that no order of the two items could resolve, as the pair of transitions
  /// (MotionTransition ids) the items belong to, in the order found, without repeats: the
  /// hyperarc-hyperarc scheduling constraints to feed back to the task search. An item belongs
  /// to its step's transition (a move to the transition it leads into; standing still, to the
  /// segment before); items of no transition (before the first, the move home) give none.
  std::vector<std::pair<int, int>> unordered;
  /// Conflicts that no order could resolve between a transition (its item, as above) and a
  /// robot standing at home before its first segment (or idle all along): the vertex-hyperarc
  /// scheduling constraints (transition, robot) to feed back.
  std::vector<std::pair<int, int>> home_blocked;
};

/// How the steps of a sequential history are timed (a direct history ignores it).
enum class SequentialSteps {
  kOneAfterAnother,  ///< each step's phase after the one before, as described above
  /// without the phases' order: each robot still waits at home (or folded) between its steps,
  /// but the steps of different robots run at once wherever the high level finds them clear of
  /// each other (or orders them where not)
  kOverlapping,
};

/// Resolves the robot-robot conflicts of a complete history (with its final moves).
ConflictResult resolveConflicts(MotionHypergraph& graph, const TransitionHistory& history,
                                const ConflictResolutionBudget& budget,
                                SequentialSteps steps = SequentialSteps::kOneAfterAnother);

}  // namespace dashbed::planner
