#include "tools/run_planner.h"

#include "tools/sequential_plan.h"

namespace dashbed::tools {

core::Plan planForRun(const core::LoadedWorld& world, const PlannerChoice& choice) {
  if (choice.method != "greedy" && choice.method != "optimal") {
    throw std::invalid_argument("unknown planning method '" + choice.method + "' (greedy or optimal)");
  }
  if (!(choice.time_budget > 0.0)) throw std::invalid_argument("the time budget must be positive");
  try {
    core::Plan plan = sequentialPlan(world);
    plan.seed = choice.seed;
    return plan;
  } catch (const std::runtime_error& e) {
    throw PlanningFailed(PlanningStatus::kInfeasible, e.what());
  }
}

}  // namespace dashbed::tools
