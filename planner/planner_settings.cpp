#include "planner/planner_settings.h"

#include <algorithm>
#include <stdexcept>

namespace dashbed::planner {

const char* toString(Method method) { return method == Method::kGreedy ? "greedy" : "optimal"; }

std::uint64_t constrainedSearchExpansions(const PlannerSettings& settings, int round, std::uint64_t unconstrained) {
  std::uint64_t grown = settings.constrained_search_expansions;
  for (int r = 1; r < round && grown < settings.search_expansions; ++r) grown *= 2;
  return std::min(settings.search_expansions, std::max(grown, 2 * unconstrained));
}

std::uint64_t greedySearchExpansions(const PlannerSettings& settings, QueryMode mode, bool constrained, int round,
                                     std::uint64_t unconstrained) {
  if (!constrained && !keepsClearOfIdle(mode)) return settings.search_expansions;
  return constrainedSearchExpansions(settings, round, unconstrained);
}

void validate(const PlannerSettings& settings) {
  if (settings.max_rounds < 1) throw std::invalid_argument("planner settings: max_rounds: must be >= 1");
  if (settings.search_expansions < 1 || settings.constrained_search_expansions < 1) {
    throw std::invalid_argument("planner settings: search_expansions, constrained_search_expansions: must be >= 1");
  }
  if (settings.next_best_plans < 1) throw std::invalid_argument("planner settings: next_best_plans: must be >= 1");
  if (settings.scheduling_constraints_per_round < 0) {
    throw std::invalid_argument("planner settings: scheduling_constraints_per_round: must be >= 0");
  }
  if (settings.sequential_fallback_rounds < 0) {
    throw std::invalid_argument("planner settings: sequential_fallback_rounds: must be >= 0");
  }
  if (!(settings.conflict_focal_weight >= 1.0)) {
    throw std::invalid_argument("planner settings: conflict_focal_weight: must be >= 1");
  }
  if (settings.conflict_nodes < 1 || settings.conflict_nodes_along_time < 1 ||
      settings.conflict_nodes_depth_first < 1) {
    throw std::invalid_argument(
        "planner settings: conflict_nodes, conflict_nodes_along_time, conflict_nodes_depth_first: must be >= 1");
  }
  if (settings.conflict_reroutes < 0 || settings.conflict_reroutes_retry < 0) {
    throw std::invalid_argument("planner settings: conflict_reroutes, conflict_reroutes_retry: must be >= 0");
  }
  if (!(settings.direct_time_share > 0.0 && settings.direct_time_share <= 1.0)) {
    throw std::invalid_argument("planner settings: direct_time_share: must be in (0, 1]");
  }
}

}  // namespace dashbed::planner
