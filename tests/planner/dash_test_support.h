#pragma once
// What the DaSH planner tests share: world paths, a world with its hypergraphs, and planner
// settings with iteration caps.

#include <cstdint>
#include <string>
#include <utility>

#include "planner/dash_planner.h"

namespace dashbed::planner::testing {

inline std::string worldPath(const std::string& name) { return std::string(DASHBED_SOURCE_ROOT) + "/worlds/" + name; }
/// A world of the planner tests (tests/planner/worlds/).
inline std::string testWorldPath(const std::string& name) {
  return std::string(DASHBED_SOURCE_ROOT) + "/tests/planner/worlds/" + name;
}

/// A world with its task-space and motion hypergraphs.
struct WorldGraph {
  core::LoadedWorld world;
  TaskSpaceHypergraph task_space;
  MotionHypergraph graph;
  explicit WorldGraph(const std::string& path, std::uint64_t seed = 7) : WorldGraph(core::loadWorld(path), seed) {}
  WorldGraph(core::LoadedWorld loaded, std::uint64_t seed)
      : world(std::move(loaded)),
        task_space(TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach)),
        graph(world, task_space, seed) {}
};

inline PlannerSettings testSettings(Method method = Method::kGreedy) {
  PlannerSettings settings;
  settings.method = method;
  settings.seed = 7;
  settings.max_rounds = 8;
  settings.search_expansions = 5000;
  settings.conflict_nodes = 300;
  return settings;
}

}  // namespace dashbed::planner::testing
