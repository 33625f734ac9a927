#pragma once
// How the planner names things in its progress lines and in the reasons it gives.

#include <string>
#include <vector>

#include "planner/motion/motion_hypergraph.h"
#include "planner/search/transition_history.h"

namespace dashbed::planner {

/// "12.34 s"
std::string secondsText(Millis t);

/// " (12 nodes)": a conflict resolution's size, as the progress lines give it.
std::string nodesText(int nodes);

/// "place green_1 by r1 (transition 63)"
std::string describeTransition(const MotionHypergraph& graph, int id);

/// "blue_0 and blue_3", "a, b and c"
std::string objectList(const core::World& world, const std::vector<int>& objects);

/// The first `limit` items joined by `separator`, then " and N more<what>" for the rest:
/// reasons name a few of many things.
std::string firstFew(const std::vector<std::string>& items, std::size_t limit, const std::string& separator,
                     const std::string& what = "");

/// "; the furthest task plan tried placed 11 of 12 objects, not blue_5 (held by r1)": how far
/// a greedy query without a plan got, and what it left (at most 4 objects named).
std::string furthestText(const MotionHypergraph& graph, const TransitionHistory& furthest);

}  // namespace dashbed::planner
