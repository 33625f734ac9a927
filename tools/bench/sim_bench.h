#pragma once
// `dashbed bench sim`: the real-time factor of headless simulation, every robot swaying its
// shoulder pan and wrist around home under PD control while the objects rest, the monitor on;
// and of real plans' executions, as `dashbed sim` runs them.

#include <string>
#include <vector>

#include "tools/bench/bench_table.h"

namespace dashbed::tools {

struct SimBenchOptions {
  std::vector<std::string> worlds;  ///< world files; empty: the generated 2-robot sorting worlds
  std::vector<int> cubes{4, 20};    ///< cube counts of those generated worlds
  double seconds = 10.0;            ///< simulated time per world [s]
  /// Worlds whose Greedy plan (seed 1) is executed as `dashbed sim` does (settling, the plan,
  /// the tail, the monitor, the readiness check); the planning is not timed.
  std::vector<std::string> plan_worlds;
};

/// One row per world and per plan world: robots, objects, simulated and wall time, real-time
/// factor by wall clock and by process CPU time, CPU time per step. Throws core::WorldError
/// for a bad world file, tools::PlanningFailed when a plan world has no plan.
BenchTable benchSimulation(const SimBenchOptions& options);

}  // namespace dashbed::tools
