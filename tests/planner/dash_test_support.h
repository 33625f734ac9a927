#pragma once
// What the DaSH planner tests share: world paths and planner settings with iteration caps.

#include <string>

#include "planner/dash_planner.h"

namespace dashbed::planner::testing {

inline std::string worldPath(const std::string& name) { return std::string(DASHBED_SOURCE_ROOT) + "/worlds/" + name; }
/// A world of the planner tests (tests/planner/worlds/).
inline std::string testWorldPath(const std::string& name) {
  return std::string(DASHBED_SOURCE_ROOT) + "/tests/planner/worlds/" + name;
}

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
