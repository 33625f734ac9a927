#include "planner/scheduling/temporal_network.h"

#include <algorithm>

namespace dashbed::planner {

std::optional<std::vector<Millis>> earliestStarts(std::size_t count, const std::vector<TemporalEdge>& edges,
                                                  std::vector<std::size_t>* cycle) {
  std::vector<Millis> start(count, 0);
  std::vector<std::size_t> raised_by(count, edges.size());  // the edge that last raised a start
  int raised = -1;                                          // a start raised in this round
  for (std::size_t round = 0; round <= count; ++round) {
    raised = -1;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const TemporalEdge& e = edges[i];
      if (start[e.from] + e.lag > start[e.to]) {
        start[e.to] = start[e.from] + e.lag;
        raised_by[e.to] = i;
        raised = e.to;
      }
    }
    if (raised < 0) return start;
  }
  if (cycle == nullptr) return std::nullopt;
  // still raised after count + 1 rounds (count segments and time 0): going back as many edges
  // from the segment last raised lands on a cycle of the edges that raised each start last
  cycle->clear();
  int v = raised;
  for (std::size_t k = 0; k <= count; ++k) v = edges[raised_by[v]].from;
  for (int u = v; cycle->empty() || u != v; u = edges[raised_by[u]].from) cycle->push_back(raised_by[u]);
  std::reverse(cycle->begin(), cycle->end());
  return std::nullopt;
}

}  // namespace dashbed::planner
