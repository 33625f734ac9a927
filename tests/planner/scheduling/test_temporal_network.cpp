// The schedule's temporal network: earliest start times, and the cycle that shows precedences
// contradicting each other.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "planner/scheduling/temporal_network.h"

using namespace dashbed::planner;

namespace {

/// The sum of the lags of `cycle` after checking that its edges close a cycle.
Millis closedCycleLag(const std::vector<TemporalEdge>& edges, const std::vector<std::size_t>& cycle) {
  REQUIRE_FALSE(cycle.empty());
  Millis lag = 0;
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    const TemporalEdge& e = edges.at(cycle[k]);
    const TemporalEdge& next = edges.at(cycle[(k + 1) % cycle.size()]);
    CHECK(e.to == next.from);
    lag += e.lag;
  }
  return lag;
}

}  // namespace

TEST_CASE("the earliest starts are the longest paths from time 0", "[planner][temporal]") {
  // 0 -> 1 (3), 1 -> 2 (4), 0 -> 2 (9), 2 -> 3 (-2: 3 at most 2 before 2), 3 -> 1 (-10)
  const std::vector<TemporalEdge> edges{{0, 1, 3}, {1, 2, 4}, {0, 2, 9}, {2, 3, -2}, {3, 1, -10}};
  std::vector<std::size_t> cycle{7};
  const std::optional<std::vector<Millis>> start = earliestStarts(5, edges, &cycle);
  REQUIRE(start);
  CHECK(*start == std::vector<Millis>{0, 3, 9, 7, 0});
  CHECK(cycle == std::vector<std::size_t>{7});  // untouched when the network holds
}

TEST_CASE("precedences that cannot all hold give the cycle that contradicts", "[planner][temporal]") {
  // a move (1, 4 ms) into a transition (2) arriving just in time; another robot's segment (3,
  // 6 ms) must start after the move starts and end before the transition starts: a cycle
  // through the arrival
  const std::vector<TemporalEdge> edges{{0, 1, 5}, {1, 2, 4}, {2, 1, -4, true}, {1, 3, 0}, {3, 2, 6}, {0, 4, 1}};
  std::vector<std::size_t> cycle;
  REQUIRE_FALSE(earliestStarts(5, edges, &cycle));
  CHECK(closedCycleLag(edges, cycle) > 0);
  CHECK(std::find(cycle.begin(), cycle.end(), std::size_t{2}) != cycle.end());  // the arrival is on it
  CHECK(std::find(cycle.begin(), cycle.end(), std::size_t{0}) == cycle.end());  // what leads to it is not
  CHECK_FALSE(earliestStarts(5, edges));  // no cycle asked for: just the answer
}

TEST_CASE("every contradicting random network gives a closed cycle of positive lag", "[planner][temporal]") {
  std::mt19937 rng(7);
  int contradicting = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = std::uniform_int_distribution<int>(2, 12)(rng);
    std::vector<TemporalEdge> edges;
    const int m = std::uniform_int_distribution<int>(1, 3 * n)(rng);
    for (int k = 0; k < m; ++k) {
      edges.push_back({std::uniform_int_distribution<int>(0, n - 1)(rng), std::uniform_int_distribution<int>(0, n - 1)(rng),
                       std::uniform_int_distribution<Millis>(-20, 10)(rng)});
    }
    std::vector<std::size_t> cycle;
    const std::optional<std::vector<Millis>> start = earliestStarts(static_cast<std::size_t>(n), edges, &cycle);
    if (start) {
      for (const TemporalEdge& e : edges) CHECK((*start)[e.to] >= (*start)[e.from] + e.lag);
      continue;
    }
    ++contradicting;
    CHECK(closedCycleLag(edges, cycle) > 0);
  }
  CHECK(contradicting > 50);  // the random networks test both answers
  CHECK(contradicting < 350);
}
