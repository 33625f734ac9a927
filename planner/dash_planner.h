#pragma once
// The DaSH planner for multi-manipulator rearrangement (paper: Method > Overview, Alg. 1):
// build the task-space hypergraph (Alg. 2) and the motion hypergraph (Alg. 3), query a task
// plan on the transition-extended hypergraph (Alg. 4), resolve conflicts (scheduled CBS), and
// expand the representation by a round when that fails. A conflict that conflict resolution
// cannot order becomes a scheduling constraint on the pair of transitions involved, and the
// query runs again on the same representation (paper: Transition-extended Hypergraph >
// Scheduling Constraints). The constraints steer the search; a pair that could not be ordered
// in one history may be in another, so when they leave no task plan they are dropped.
//
//  Method::kGreedy   Greedy-MM-DaSH: one greedy hyperpath query per round; the first plan whose
//                    conflicts resolve is returned (earlyTermination from the start), unless
//                    it is a fallback (sequential, or parked out of every transition's way):
//                    then the direct queries go on for sequential_fallback_rounds more rounds.
//  Method::kOptimal  MM-DaSH: Greedy's rounds until they have a plan, then Next-Best Search
//                    (Alg. 5) with the A*-like hyperpath query on that round's representation,
//                    starting from the greedy plan as the upper bound (so it is never worse),
//                    until the next task plan's optimistic makespan is no better than the best
//                    resolved plan. With a deadline it is anytime: the best plan so far is
//                    returned when time is up.
//
// One entry point, solve(); infeasible problems and timeouts are statuses, not exceptions. The
// one world error only the collision model can see, a robot colliding at home, throws
// core::WorldError (home_check.h), like the errors core::loadWorld throws.
// The plan is deterministic for a world, settings and seed; wall-clock times are reported in
// PlannerStats only, never in the plan.

#include <memory>
#include <optional>
#include <string>

#include "core/plan.h"
#include "core/world_loader.h"
#include "planner/planner_settings.h"

namespace dashbed::planner {

enum class PlannerStatus { kSolved, kInfeasible, kTimeout };

struct PlanResult {
  PlannerStatus status = PlannerStatus::kInfeasible;
  std::string reason;  ///< why not solved (names the object, robot or region)
  std::optional<core::Plan> plan;
  PlannerStats stats;
};

/// The collision scene the planner plans `world` in under `settings`, after checking that every
/// robot is free at home (throws core::WorldError naming robots[i].home otherwise).
std::shared_ptr<const CollisionScene> checkedScene(const core::LoadedWorld& world, const PlannerSettings& settings);

/// Plans `world`. `checked_scene`: checkedScene(world, settings), for a caller that validated
/// the world before; built and checked here when null.
PlanResult solve(const core::LoadedWorld& world, const PlannerSettings& settings, const PlannerBudget& budget = {},
                 std::shared_ptr<const CollisionScene> checked_scene = nullptr);

const char* toString(PlannerStatus status);

}  // namespace dashbed::planner
