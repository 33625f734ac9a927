#pragma once
// The planner behind `dashbed run`, `dashbed plan` and `dashbed stress --replan`: one entry
// point, so that every command plans the same way for the same world, method and seed.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/plan.h"
#include "core/world_loader.h"

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
  double time_budget = 120.0;     ///< wall-clock budget [s]; PlanningFailed(kTimeout) beyond it
  int max_rounds = 50;            ///< representation expansion rounds before giving up (kTimeout)
};

/// Plans `world`. Throws PlanningFailed when no plan is found, std::invalid_argument for a bad
/// choice (unknown method, non-positive budget).
core::Plan planForRun(const core::LoadedWorld& world, const PlannerChoice& choice);

}  // namespace dashbed::tools
