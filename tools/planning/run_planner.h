#pragma once
// The planner behind `dashbed plan`, `dashbed run` and `dashbed stress --replan`: one entry
// point, so that every command plans the same way for the same world, method and seed.

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/plan.h"
#include "core/world_loader.h"
#include "planner/dash_planner.h"

namespace dashbed::tools {

/// Why planning produced no plan.
enum class PlanningStatus { kInfeasible, kTimeout };

/// Planning ended without a plan. what() gives the reason (naming the object, robot or
/// region concerned).
struct PlanningFailed : std::runtime_error {
  PlanningFailed(PlanningStatus status_, const std::string& reason) : std::runtime_error(reason), status(status_) {}
  PlanningStatus status;
};

/// The longest planning budget taken [s] (about 11.6 days): beyond it the deadline's clock
/// arithmetic would overflow.
inline constexpr double kMaxTimeBudget = 1e6;

struct PlannerChoice {
  std::string method = "greedy";  ///< "greedy" (Greedy-MM-DaSH) or "optimal" (MM-DaSH)
  std::uint64_t seed = 1;         ///< sampling seed: same world, method and seed give the same plan
  double time_budget = 120.0;     ///< wall-clock budget [s]; status timeout beyond it
  int max_rounds = 30;            ///< representation expansion rounds before giving up (timeout)
  /// rounds a sequential plan (one object at a time) waits for one whose robots work side by side
  int fallback_rounds = planner::PlannerSettings{}.sequential_fallback_rounds;
  bool verbose = false;           ///< the planner's progress on stderr
  bool set_aside = true;          ///< objects in the way of another's every pick may be set aside
  /// the greedy queries' conflict-resolution focal weight (>= 1)
  double conflict_focal = planner::PlannerSettings{}.conflict_focal_weight;
};

/// The planner settings of a choice. Throws std::invalid_argument for a bad choice (unknown
/// method, non-positive budget or rounds).
planner::PlannerSettings plannerSettings(const PlannerChoice& choice);

/// Runs the DaSH planner on `world` (planner::solve; `checked_scene` as there). Throws
/// std::invalid_argument for a bad choice (plannerSettings; the planner's own for negative
/// fallback rounds).
planner::PlanResult planWorld(const core::LoadedWorld& world, const PlannerChoice& choice,
                              std::shared_ptr<const planner::CollisionScene> checked_scene = nullptr);

/// A few lines for people: status (and reason), stage times, representation sizes, makespan.
std::string describePlanResult(const planner::PlanResult& result);

/// The same as JSON, with the wall-clock times (which plan files leave out).
nlohmann::json planResultJson(const planner::PlanResult& result);

/// planWorld, returning the plan; throws PlanningFailed when there is none.
core::Plan planForRun(const core::LoadedWorld& world, const PlannerChoice& choice);

}  // namespace dashbed::tools
