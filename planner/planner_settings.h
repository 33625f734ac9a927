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

/// Default of PlannerSettings::conflict_focal_weight: resolves in fewer nodes than best first
/// (1), for slightly longer schedules.
inline constexpr double kGreedyConflictFocalWeight = 1.1;

struct PlannerSettings {
  /// Greedy-MM-DaSH (kGreedy: first resolved plan) or MM-DaSH (kOptimal: Next-Best Search from
  /// Greedy's plan; never longer, several times slower).
  Method method = Method::kGreedy;
  /// Seed of handoff draws and roadmap sampling; the plan is a function of world, settings and seed.
  std::uint64_t seed = 1;
  /// Rounds of representation expansion before solve() stops with a timeout (>= 1); more can
  /// solve harder worlds but take longer to report failure.
  int max_rounds = 30;
  /// Histories one hyperpath query may expand without scheduling constraints (Next-Best Search:
  /// per task plan it takes); also caps constrained_search_expansions. Higher backtracks further,
  /// slower.
  std::uint64_t search_expansions = 20000;
  /// Round-1 expansion cap of greedy queries under scheduling constraints or keeping clear of idle
  /// robots; doubles per round, >= 2x the last unconstrained query, <= search_expansions.
  std::uint64_t constrained_search_expansions = 1000;
  /// High-level nodes per conflict resolution (all but the second try's along-time and depth-first
  /// passes); more resolve more plans but spend longer on each that fails.
  int conflict_nodes = 500;
  /// High-level nodes of the second try's along-time pass (NodeOrder::kAlongTime); it resolves
  /// conflicts one after another, so crowded plans need many nodes. More: slower failures.
  int conflict_nodes_along_time = 2000;
  /// High-level nodes of the second try's depth-first pass (NodeOrder::kDepthFirst), run on the
  /// shortest failed direct plan after best first and along time; more: slower failures.
  int conflict_nodes_depth_first = 4000;
  /// Focal weight (>= 1) of the conflict resolution of greedy task plans; Next-Best Search uses 1.
  /// Above 1: fewer nodes, schedules up to that factor longer than the shortest open node.
  double conflict_focal_weight = kGreedyConflictFocalWeight;
  /// Detour and parking roadmap searches per conflict resolution (as many again below a fold);
  /// fewer hand hard conflicts back to the task search sooner, more rescue long schedules.
  int conflict_reroutes = 24;
  /// Re-routes of the second try: with a fallback plan in hand, a round's 3 shortest failed direct
  /// plans are resolved again below its makespan (<= conflict_reroutes: no second try).
  int conflict_reroutes_retry = 96;
  /// Task plans Next-Best Search takes from one A*-like query (a new query after a scheduling
  /// constraint counts afresh); more approach the representation's best plan, slower.
  int next_best_plans = 20;
  /// Scheduling constraints fed back per round (and per sequential query mode), each followed by
  /// a new query; more steer the search further, at a query and conflict resolution each.
  int scheduling_constraints_per_round = 6;
  /// Rounds the direct queries go on after a fallback plan (sequential or parked clear of homes);
  /// a shorter direct plan replaces it. More: shorter plans on crowded worlds, longer planning.
  int sequential_fallback_rounds = 2;
  /// With a deadline and no plan yet: share of the time, in (0, 1], the direct queries may use
  /// before the sequential query; lower secures the fallback, higher favours direct plans.
  double direct_time_share = 0.5;
  /// Give set-aside sites to objects standing where another object's every pick reaches over
  /// them; off keeps the representation smaller but may leave such worlds without a plan.
  bool set_aside = true;
  /// Construction of the task-space and motion hypergraphs (sampling, roadmaps, timing, collision).
  RepresentationSettings representation;
};

/// A wall-clock deadline (std::nullopt: none; iteration caps still apply), and where to report
/// progress (each query, conflict resolution and round, one line each; may be empty).
struct PlannerBudget {
  /// Wall-clock deadline of solve() (none: only the iteration caps apply); when it passes, the
  /// best plan so far is returned (MM-DaSH's anytime plan, or Greedy's fallback).
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// Receives one line per query, conflict resolution and round (may be empty).
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
