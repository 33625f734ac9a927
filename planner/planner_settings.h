#pragma once
// What the DaSH planner is asked to do and what it reports besides the plan: its method and
// settings, its budget, and the statistics of a solve (paper: Method > Method Variants).

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "planner/motion/motion_hypergraph.h"
#include "planner/search/hyperpath_search.h"

namespace dashbed::planner {

enum class Method { kGreedy, kOptimal };

/// The greedy queries' conflict-resolution focal weight (ConflictResolutionBudget::focal_weight):
/// Greedy plans 2-7 times faster on the paper's 4-robot worlds than with best first (1), its
/// makespans 1.5 % longer on average (README, Greedy's conflict resolution).
inline constexpr double kGreedyConflictFocalWeight = 1.1;

struct PlannerSettings {
  Method method = Method::kGreedy;
  std::uint64_t seed = 1;
  int max_rounds = 30;                        ///< representation expansions before giving up
  std::uint64_t search_expansions = 20000;    ///< per hyperpath query
  /// per greedy query while scheduling constraints are in force, and per query keeping clear
  /// of the robots waiting at home (sequential, QueryMode::kParkClearOfHomes), in round 1,
  /// doubling every round up to search_expansions (or twice what the last query without
  /// constraints took, when more): a depth-first search they (or the robots waiting) steer into
  /// a corner backtracks long, and the next round may do without them; but a round that drops
  /// them meets the same conflicts again, so each round lets the constrained search look
  /// further
  std::uint64_t constrained_search_expansions = 1000;
  /// per conflict resolution (a sequential plan gets up to three: its steps one after
  /// another, then overlapping in the task plan's order and depth first along time)
  int conflict_nodes = 500;
  /// per conflict resolution of the second try's depth first along time (see
  /// conflict_reroutes_retry): it resolves the schedule's conflicts one after another along
  /// time, so a crowded plan needs more nodes, not a wider search (a ring of 6 robots with 18
  /// random cubes: with 500 none of its tries got further than 158 s along its schedule, and
  /// the sequential plan of 259 s was returned; with 2000 round 2 resolves one in 958 nodes,
  /// 172 s)
  int conflict_nodes_along_time = 2000;
  /// per conflict resolution of the second try's depth-first pass (NodeOrder::kDepthFirst), on
  /// the shortest of the round's failed direct task plans once best first and along time
  /// failed on it (see conflict_reroutes_retry)
  int conflict_nodes_depth_first = 4000;
  /// The focal weight (ConflictResolutionBudget::focal_weight, >= 1) of the conflict
  /// resolution of the greedy queries' task plans (Greedy's, and MM-DaSH's until it has
  /// Greedy's plan); Next-Best Search's are resolved best first (1: the shortest first).
  double conflict_focal_weight = kGreedyConflictFocalWeight;
  /// Detours and parkings each conflict resolution may search its roadmaps for
  /// (ConflictResolutionBudget::max_reroutes). Few: a task plan whose robots only get past each
  /// other by many reroutes has a long schedule, and its failure feeds a scheduling constraint
  /// back to the task search, which often finds a better plan.
  int conflict_reroutes = 24;
  /// In the rounds after a fallback plan was found (sequential_fallback_rounds), when none
  /// of a round's direct task plans resolves, the three of them with the shortest optimistic
  /// makespans are resolved again with this many reroutes, for a schedule shorter than the
  /// fallback's (no constraints fed back; not above conflict_reroutes: no second try):
  /// each best first and, where that fails, along time (NodeOrder::kAlongTime, with
  /// conflict_nodes_along_time nodes), the shortest then also depth first
  /// (conflict_nodes_depth_first) before the next is tried.
  /// Not before: a plan resolved with many reroutes may be longer than the sequential one.
  int conflict_reroutes_retry = 96;
  int next_best_plans = 20;                   ///< task plans tried per round by Next-Best Search
  /// Scheduling constraints fed back from failed conflict resolutions per round, each followed
  /// by a new query on the same representation.
  int scheduling_constraints_per_round = 6;
  /// A plan moving one object at a time (the last resort of a round whose other queries all
  /// failed), or one with the robots parked at home out of every transition's way
  /// (QueryMode::kParkClearOfHomes), is kept as a fallback: the direct queries go on for this
  /// many more rounds of expansion, and a plan they find replaces it when shorter.
  int sequential_fallback_rounds = 2;
  /// With a deadline: while there is no plan yet, the direct queries (those before a round's
  /// sequential one) stop once this share of the time from solve()'s start to the deadline is
  /// used, leaving the rest to the sequential query (without the scheduling constraints they
  /// left in force), so that a world too crowded for the direct queries to find a plan in
  /// time still gets its sequential plan (in (0, 1]; plans found after the cut depend on the
  /// machine's speed, as any plan at the deadline does).
  double direct_time_share = 0.5;
  /// Objects standing where another object's every pick reaches over them get set-aside sites
  /// (ObjectSites::aside), so that they may be set down there for a while: needed where that
  /// object must go in before them (a shelf item behind one that goes into the slot in front).
  bool set_aside = true;
  RepresentationSettings representation;
};

/// A wall-clock deadline (std::nullopt: none; iteration caps still apply), and where to report
/// progress (each query, conflict resolution and round, one line each; may be empty).
struct PlannerBudget {
  std::optional<std::chrono::steady_clock::time_point> deadline;
  std::function<void(const std::string&)> progress;
};

struct PlannerStats {
  double construction_seconds = 0.0;  ///< task-space + motion hypergraph (sampling, roadmaps, moves)
  double search_seconds = 0.0;        ///< hyperpath queries (excluding the construction they trigger)
  double conflict_seconds = 0.0;      ///< conflict resolution
  int rounds = 0;
  std::size_t task_vertices = 0, task_hyperarcs = 0;
  int set_aside_sites = 0;  ///< objects given a set-aside site (in the way of another's every pick)
  std::size_t motion_vertices = 0, motion_transitions = 0, motion_moves = 0;
  std::size_t roadmaps = 0, roadmap_nodes = 0;
  std::uint64_t expansions = 0;  ///< hyperpath-search expansions, all rounds
  int task_plans = 0;            ///< task plans given to conflict resolution
  int conflict_nodes = 0;        ///< conflict-resolution nodes, all task plans
  int scheduling_constraints = 0;  ///< fed back from conflict resolution to the task search, all rounds
  int conflict_constraints = 0;    ///< precedences, detours and parkings of the plan's conflict resolution
  /// of the task plan returned, timed before any robot-robot conflict is resolved
  /// (ConflictResult::unresolved_makespan; the task plan's optimistic makespan for a direct
  /// plan, below it where a sequential plan's steps overlap) [s]
  double unresolved_makespan = 0.0;
  double makespan = 0.0;             ///< of the plan [s]
  /// the plan is the last resort, a sequential task plan (TransitionHistory::sequential): one
  /// object at a time, each robot waiting at home or folded between its steps
  bool sequential = false;
};

/// Expansion budget of a greedy query with scheduling constraints in force, in round `round`
/// (from 1), when the last query without them took `unconstrained` expansions (see
/// PlannerSettings::constrained_search_expansions).
std::uint64_t constrainedSearchExpansions(const PlannerSettings& settings, int round, std::uint64_t unconstrained);

/// Expansion budget of a greedy query in `mode` in round `round`: search_expansions, but
/// constrainedSearchExpansions for a query keeping clear of the robots standing idle (the
/// sequential ones, kParkClearOfHomes: keepsClearOfIdle) and for any query while scheduling
/// constraints are in force (`constrained`).
std::uint64_t greedySearchExpansions(const PlannerSettings& settings, QueryMode mode, bool constrained, int round,
                                     std::uint64_t unconstrained);

/// Throws std::invalid_argument naming the first field out of its range.
void validate(const PlannerSettings& settings);

const char* toString(Method method);

}  // namespace dashbed::planner
