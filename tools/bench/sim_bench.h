#pragma once
// `dashbed bench sim`: the real-time factor of headless simulation, every robot swaying its
// shoulder pan and wrist around home under PD control while the objects rest, the monitor on.

#include <string>
#include <vector>

#include "tools/bench/bench_table.h"

namespace dashbed::tools {

struct SimBenchOptions {
  std::vector<std::string> worlds;  ///< world files; empty: the generated 2-robot sorting worlds
  std::vector<int> cubes{4, 20};    ///< cube counts of those generated worlds
  double seconds = 10.0;            ///< simulated time per world [s]
};

/// One row per world: robots, objects, simulated and wall time, real-time factor by wall clock
/// and by process CPU time, CPU time per step. Throws core::WorldError for a bad world file.
BenchTable benchSimulation(const SimBenchOptions& options);

}  // namespace dashbed::tools
