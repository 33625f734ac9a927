#pragma once
// The planner's command-line options, shared by plan, run, bench plan and stress.

#include "planner/dash_planner.h"
#include "tools/cli/cli_fwd.h"
#include "tools/planning/run_planner.h"

namespace dashbed::tools {

/// The help text of --fallback-rounds (plan, run, bench plan, stress).
inline constexpr const char* kFallbackRoundsHelp =
    "rounds of representation expansion a sequential plan (one object at a time) waits for a plan whose robots "
    "work side by side; more find shorter plans on crowded worlds, taking longer";

/// Adds --method, --seed, --time-budget, --max-rounds, --fallback-rounds, --conflict-focal,
/// --no-set-aside and --verbose to a command.
void addPlannerOptions(CLI::App& command, PlannerChoice& choice);

/// The exit code of a planning status (0 solved, kExitInfeasible, kExitTimeout).
int exitCodeOf(planner::PlannerStatus status);

}  // namespace dashbed::tools
