#pragma once
// `dashbed bench collision`: the time per query of the planner's collision checker
// (planner/collision/collision_checker.h) on a world's scene:
//   robotFree   one robot against fixtures, resting objects (start poses) and itself, at
//               configurations drawn uniformly within the joint limits, also holding a cube;
//   robotsFree  robot 0 against robot 1 at pairs of such configurations, and at pairs reaching
//               over the table centre (IK), where they often meet;
//   motionFree  straight motions from a free configuration by up to +-0.5 rad per arm joint.
// Each split by outcome; median, mean and 95th percentile of individually timed calls, and the
// process CPU time per call over the whole loop (robust to other processes' load).

#include <cstdint>
#include <string>

#include "tools/bench/bench_table.h"

namespace dashbed::tools {

struct CollisionBenchOptions {
  std::string world;        ///< world file; empty: worlds/default.yaml
  int checks = 100000;      ///< configurations (and pairs) per robotFree / robotsFree row
  int motions = 2000;       ///< motions of the motionFree rows
  std::uint64_t seed = 1;   ///< seed of the drawn configurations
};

/// Throws std::invalid_argument for checks <= 0, motions < 0 or a world without robots, and
/// core::WorldError for a bad world file.
BenchTable benchCollision(const CollisionBenchOptions& options);

}  // namespace dashbed::tools
