#pragma once
// The planner behind `dashbed plan`, `dashbed run` and `dashbed stress --replan`: one entry
// point, so that every command plans the same way for the same world, method and seed.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/plan.h"
#include "core/world_loader.h"
#include "planner/dash_planner.h"
#include "tools/cli_fwd.h"

namespace dashbed::tools {

/// Why planning produced no plan.
enum class PlanningStatus { kInfeasible, kTimeout };

/// Planning ended without a plan. what() gives the reason (naming the object, robot or
/// region concerned).
struct PlanningFailed : std::runtime_error {
  PlanningFailed(PlanningStatus status_, const std::string& reason) : std::runtime_error(reason), status(status_) {}
  PlanningStatus status;
};

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

/// The help text of --fallback-rounds (plan, run, bench plan, stress).
inline constexpr const char* kFallbackRoundsHelp =
    "rounds of representation expansion a sequential plan (one object at a time) waits for a plan whose robots "
    "work side by side; more find shorter plans on crowded worlds, taking longer";

/// Adds --method, --seed, --time-budget, --max-rounds, --fallback-rounds, --conflict-focal,
/// --no-set-aside and --verbose to a command.
void addPlannerOptions(CLI::App& command, PlannerChoice& choice);

/// Runs the DaSH planner on `world`. Throws std::invalid_argument for a bad choice (unknown
/// method, non-positive budget or rounds; the planner's own for negative fallback rounds).
planner::PlanResult planWorld(const core::LoadedWorld& world, const PlannerChoice& choice);

/// A few lines for people: status (and reason), stage times, representation sizes, makespan.
std::string describePlanResult(const planner::PlanResult& result);

/// The same as JSON, with the wall-clock times (which plan files leave out).
nlohmann::json planResultJson(const planner::PlanResult& result);

/// The exit code of a planning status (0 solved, kExitInfeasible, kExitTimeout).
int exitCodeOf(planner::PlannerStatus status);

/// planWorld, returning the plan; throws PlanningFailed when there is none.
core::Plan planForRun(const core::LoadedWorld& world, const PlannerChoice& choice);

}  // namespace dashbed::tools
