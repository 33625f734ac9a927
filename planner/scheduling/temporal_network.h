#pragma once
// The simple temporal network of a schedule (scheduled_cbs.h): segment start times S bound by
// precedences S[to] >= S[from] + lag. Its earliest solution is the longest path from time 0;
// a cycle of precedences whose lags sum above zero means they cannot all hold.

#include <cstddef>
#include <optional>
#include <vector>

#include "planner/sampling/timing.h"

namespace dashbed::planner {

/// A precedence S[to] >= S[from] + lag [ms].
struct TemporalEdge {
  int from = -1, to = -1;
  Millis lag = 0;
  /// a move into a transition arriving just in time (to: the move, from: the transition),
  /// which conflict resolution may give up (ScheduleSegment::early)
  bool arrival = false;
};

/// The earliest start times (none before 0) of `count` segments that satisfy `edges`
/// (Bellman-Ford), or std::nullopt when they cannot all hold: then, when `cycle` is given, it
/// holds the edges (indices into `edges`, each one's `to` the `from` of the next, the last
/// one's `to` the first one's `from`) of a cycle whose lags sum above zero.
std::optional<std::vector<Millis>> earliestStarts(std::size_t count, const std::vector<TemporalEdge>& edges,
                                                  std::vector<std::size_t>* cycle = nullptr);

}  // namespace dashbed::planner
