// dashbed plan [WORLD] -o plan.json: the DaSH planner on a world (the built-in default when
// none is given). Exit 0 solved, 4 infeasible, 5 timeout, 3 bad world, 2 bad options.

#include <iostream>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/planner_options.h"
#include "tools/cli/number_checks.h"
#include "tools/planning/run_planner.h"

namespace dashbed::tools {
namespace {

struct PlanOptions {
  std::string world_file;
  std::string output;
  PlannerChoice choice;
  bool json = false;
};

void planJob(const PlanOptions& options) {
  const std::filesystem::path file = worldFileOrDefault(options.world_file);
  const core::LoadedWorld world = core::loadWorld(file);
  const planner::PlanResult result = planWorld(world, options.choice);
  if (result.plan && !options.output.empty()) core::writeFile(options.output, core::writePlanJson(*result.plan));
  if (options.json) {
    std::cout << jsonText(planResultJson(result)) << "\n";
  } else {
    std::cout << "world " << world.world->name << " (" << file.string() << "), method " << options.choice.method
              << ", seed " << options.choice.seed << "\n"
              << describePlanResult(result);
    if (result.plan && !options.output.empty()) std::cout << "wrote " << options.output << "\n";
  }
  if (const int code = exitCodeOf(result.status); code != kExitOk) throw CLI::RuntimeError(code);
}

}  // namespace

void addPlanCommand(CLI::App& app) {
  auto options = std::make_shared<PlanOptions>();
  CLI::App* plan = app.add_subcommand(
      "plan", "Plan a world with DaSH and write the timed plan (default world: worlds/default.yaml). Exit 0 "
              "solved, 4 infeasible, 5 timeout, 3 bad world file.");
  plan->add_option("world", options->world_file, "world file (YAML)");
  plan->add_option("-o,--output", options->output, "write the plan here (JSON)");
  addPlannerOptions(*plan, options->choice);
  plan->add_flag("--json", options->json, "print the status and statistics as JSON");
  plan->callback([options] { runGuarded("plan", [&] { planJob(*options); }); });
}

void addPlannerOptions(CLI::App& command, PlannerChoice& choice) {
  command.add_option("--method", choice.method, "greedy (Greedy-MM-DaSH) or optimal (MM-DaSH)")
      ->check(CLI::IsMember({"greedy", "optimal"}))
      ->capture_default_str();
  command.add_option("--seed", choice.seed, "sampling seed")->check(unsigned64())->capture_default_str();
  command.add_option("--time-budget", choice.time_budget, "wall-clock budget [s]")
      ->check(positiveNumber())
      ->capture_default_str();
  command.add_option("--max-rounds", choice.max_rounds, "representation expansion rounds")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  command.add_option("--fallback-rounds", choice.fallback_rounds, kFallbackRoundsHelp)
      ->check(integerIn(0, std::numeric_limits<int>::max()))
      ->capture_default_str();
  command.add_option("--conflict-focal", choice.conflict_focal,
                     "focal weight of the greedy queries' conflict resolution (>= 1): a node up to this factor longer "
                     "than the shortest comes first when free of conflicts for longer (1: the shortest first; "
                     "optimal's Next-Best Search always takes the shortest first)")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  command.add_flag("--no-set-aside{false}", choice.set_aside,
                   "never set an object down anywhere but at its goal (by default an object standing where another's "
                   "every pick reaches over it may be set aside for a while)");
  command.add_flag("--verbose", choice.verbose, "print the planner's progress (queries, conflict resolutions) on stderr");
}

int exitCodeOf(planner::PlannerStatus status) {
  switch (status) {
    case planner::PlannerStatus::kSolved:
      return kExitOk;
    case planner::PlannerStatus::kInfeasible:
      return kExitInfeasible;
    case planner::PlannerStatus::kTimeout:
      break;
  }
  return kExitTimeout;
}

}  // namespace dashbed::tools
