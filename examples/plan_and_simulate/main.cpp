// Plan a world with DaSH, execute the plan in simulation and print each action's verdict:
// dashbed as a library, through its installed CMake package.
//
//   plan_and_simulate [WORLD.yaml]     (default: the installed worlds/default.yaml)
//
// Exit 0 when every check passes, 1 when one fails, 2 when there is no plan, 3 for a bad world.

#include <iostream>

#include "core/asset_paths.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "planner/dash_planner.h"
#include "sim/run_plan.h"

int main(int argc, char** argv) {
  using namespace dashbed;
  try {
    const core::LoadedWorld world = core::loadWorld(argc > 1 ? argv[1] : core::defaultWorldPath());

    planner::PlannerSettings settings;  // Greedy-MM-DaSH, seed 1
    const planner::PlanResult planned = planner::solve(world, settings);
    if (!planned.plan) {
      std::cout << "no plan: " << planner::toString(planned.status) << " (" << planned.reason << ")\n";
      return 2;
    }
    std::cout << "plan: " << planned.plan->actions.size() << " actions, makespan " << planned.stats.makespan << " s\n";

    core::validatePlanForWorld(*planned.plan, *world.world, *world.robots, "plan");
    const sim::Report report = sim::runPlan(*world.world, *world.robots, *planned.plan, "plan");
    for (const sim::ActionReport& action : report.actions) {
      std::cout << (action.verdict == sim::Verdict::kPassed ? "PASS " : "FAIL ") << action.id;
      if (action.verdict == sim::Verdict::kFailed) std::cout << ": " << action.failure;
      std::cout << "\n";
    }
    std::cout << (report.passed() ? "PASSED" : "FAILED") << "\n";
    return report.passed() ? 0 : 1;
  } catch (const core::WorldError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
}
