#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "planner/task_space/representation_analysis.h"

using namespace dashbed::planner;
using Catch::Matchers::Contains;

namespace {

std::uint64_t choose(std::uint64_t n, std::uint64_t k) {
  if (k > n) return 0;
  std::uint64_t r = 1;
  for (std::uint64_t i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

std::uint64_t falling(std::uint64_t n, std::uint64_t k) {
  if (k > n) return 0;
  std::uint64_t r = 1;
  for (std::uint64_t i = 0; i < k; ++i) r *= n - i;
  return r;
}

// the printed Eq. (CountPickPlaceHandoff) read literally: "-1" inside G, once per (l, h)
std::uint64_t literalPrintedTransitions(std::uint64_t n, std::uint64_t m) {
  std::uint64_t total = 0;
  for (std::uint64_t p = 0; p <= std::min(m, n); ++p) {
    std::uint64_t L = 0;
    for (std::uint64_t l = 0; l <= p; ++l) {
      std::uint64_t H = 0;
      for (std::uint64_t h = 0; h <= std::min(p - l, n - p); ++h) {
        std::uint64_t G = 0;
        for (std::uint64_t g = 0; g <= std::min(m - p, n - p - h); ++g) G += choose(m - p, g) * falling(n - p - h, g);
        H += choose(p - l, h) * falling(n - p, h) * (G - 1);
      }
      L += choose(p, l) * H;
    }
    total += choose(m, p) * falling(n, p) * L;
  }
  return total;
}

struct TableRow {
  int robots;
  int objects;
  RepresentationSize hypergraph;
  RepresentationSize graph;
};

// paper Fig. 2(b)
const std::vector<TableRow> kPaperTable = {
    {2, 4, {14, 24}, {21, 120}},
    {2, 8, {26, 48}, {73, 496}},
    {4, 4, {24, 80}, {209, 8672}},
    {4, 8, {44, 160}, {3393, 213184}},
};

}  // namespace

TEST_CASE("closed forms reproduce the paper's Fig. 2b table", "[planner][representation]") {
  for (const TableRow& row : kPaperTable) {
    INFO(row.robots << " robots, " << row.objects << " objects");
    CHECK(hypergraphSize(row.robots, row.objects) == row.hypergraph);
    CHECK(compositeGraphSize(row.robots, row.objects) == row.graph);
    CHECK(compositeGraphVertices(row.robots, row.objects) == row.graph.vertices);
    CHECK(compositeGraphTransitions(row.robots, row.objects) == row.graph.transitions);
  }
}

TEST_CASE("brute-force composite graph reproduces the paper's Fig. 2b table", "[planner][representation]") {
  for (const TableRow& row : kPaperTable) {
    INFO(row.robots << " robots, " << row.objects << " objects");
    const CompositeTaskGraph dut = enumerateCompositeTaskGraph(row.robots, row.objects);
    CHECK(dut.size() == row.graph);
  }
}

TEST_CASE("closed forms equal the brute-force enumeration for small problems", "[planner][representation]") {
  for (int n = 0; n <= 4; ++n) {
    for (int m = 0; m <= 5; ++m) {
      INFO(n << " robots, " << m << " objects");
      const CompositeTaskGraph dut = enumerateCompositeTaskGraph(n, m);
      REQUIRE(dut.size() == compositeGraphSize(n, m));

      // per element: out-degree is L(m, n, p) for its number p of held objects
      std::vector<std::uint64_t> out_degree(dut.elements.size(), 0);
      for (const auto& [from, to] : dut.transitions) ++out_degree[from];
      for (std::size_t e = 0; e < dut.elements.size(); ++e) {
        const auto& holder = dut.elements[e];
        const int held = static_cast<int>(std::count_if(holder.begin(), holder.end(), [](int h) { return h >= 0; }));
        REQUIRE(out_degree[e] == compositeTransitionsFrom(n, m, held));
      }
    }
  }
}

TEST_CASE("the enumerated transitions are exactly the pairs isCompositeTransition accepts", "[planner][representation]") {
  const CompositeTaskGraph dut = enumerateCompositeTaskGraph(3, 3);
  const std::set<std::pair<int, int>> transitions(dut.transitions.begin(), dut.transitions.end());
  CHECK(transitions.size() == dut.transitions.size());
  CHECK(std::is_sorted(dut.transitions.begin(), dut.transitions.end()));
  for (std::size_t a = 0; a < dut.elements.size(); ++a) {
    for (std::size_t b = 0; b < dut.elements.size(); ++b) {
      REQUIRE(transitions.count({static_cast<int>(a), static_cast<int>(b)}) ==
              (isCompositeTransition(dut.elements[a], dut.elements[b]) ? 1u : 0u));
    }
  }
}

TEST_CASE("brute-force elements are exactly the admissible allocations", "[planner][representation]") {
  const CompositeTaskGraph dut = enumerateCompositeTaskGraph(3, 4);
  std::set<std::vector<int>> unique(dut.elements.begin(), dut.elements.end());
  CHECK(unique.size() == dut.elements.size());
  CHECK(std::is_sorted(dut.elements.begin(), dut.elements.end()));
  for (const auto& holder : dut.elements) {
    REQUIRE(holder.size() == 4);
    std::set<int> holders;
    for (const int h : holder) {
      REQUIRE(h >= CompositeTaskGraph::kResting);
      REQUIRE(h < 3);
      if (h >= 0) REQUIRE(holders.insert(h).second);  // no robot holds two objects
    }
  }
}

TEST_CASE("composite transitions come in pairs: Fig. 2a counts 120 directed, 60 bi-directional",
          "[planner][representation]") {
  const CompositeTaskGraph dut = enumerateCompositeTaskGraph(2, 4);
  const std::set<std::pair<int, int>> directed(dut.transitions.begin(), dut.transitions.end());
  for (const auto& [from, to] : directed) REQUIRE(directed.count({to, from}) == 1);
  CHECK(directed.size() == 120);
  CHECK(directed.size() / 2 == 60);
  CHECK(std::none_of(dut.transitions.begin(), dut.transitions.end(), [](const auto& t) { return t.first == t.second; }));
}

TEST_CASE("single transitions between composite elements follow the action rules", "[planner][representation]") {
  constexpr int R = CompositeTaskGraph::kResting;
  // objects o0, o1; robots 0, 1, 2
  CHECK(isCompositeTransition({R, R}, {0, R}));      // pick
  CHECK(isCompositeTransition({0, R}, {R, R}));      // place
  CHECK(isCompositeTransition({0, R}, {1, R}));      // handoff to an empty-handed robot
  CHECK(isCompositeTransition({R, R}, {0, 1}));      // two simultaneous picks
  CHECK(isCompositeTransition({0, R}, {R, 1}));      // place by 0 while 1 picks
  CHECK(isCompositeTransition({0, 1}, {2, R}));      // 0 hands o0 to 2 while 1 places o1
  CHECK_FALSE(isCompositeTransition({0, 1}, {1, R}));  // 1 places o1 and receives o0
  CHECK_FALSE(isCompositeTransition({R, R}, {R, R}));  // no action
  CHECK_FALSE(isCompositeTransition({0, R}, {R, 0}));  // 0 places o0 and picks o1: two actions
  CHECK_FALSE(isCompositeTransition({0, 1}, {1, 0}));  // swap: each robot gives and receives
  CHECK_FALSE(isCompositeTransition({0, 1}, {1, 2}));  // chain: 1 gives o1 and receives o0
  CHECK_FALSE(isCompositeTransition({0, R}, {1, 0}));  // 0 hands off o0 and picks o1
  CHECK_THROWS_AS(isCompositeTransition({R}, {R, R}), std::invalid_argument);
}

TEST_CASE("graph and hypergraph transitions agree with a single robot or a single object",
          "[planner][representation]") {
  // paper, Comparison: equal transition counts when either quantity is one
  for (int k = 1; k <= 12; ++k) {
    INFO("k = " << k);
    CHECK(compositeGraphTransitions(1, k) == hypergraphSize(1, k).transitions);
    CHECK(compositeGraphTransitions(k, 1) == hypergraphSize(k, 1).transitions);
    CHECK(compositeGraphVertices(1, k) == static_cast<std::uint64_t>(k) + 1);
    CHECK(compositeGraphVertices(k, 1) == static_cast<std::uint64_t>(k) + 1);
  }
  // and the graph is larger as soon as both exceed one
  CHECK(compositeGraphTransitions(2, 2) > hypergraphSize(2, 2).transitions);
}

TEST_CASE("hypergraph closed form: mn + m + n vertices, mn^2 + mn hyperarcs", "[planner][representation]") {
  for (int n = 0; n <= 10; ++n) {
    for (int m = 0; m <= 10; ++m) {
      const auto N = static_cast<std::uint64_t>(n), M = static_cast<std::uint64_t>(m);
      const RepresentationSize dut = hypergraphSize(n, m);
      REQUIRE(dut.vertices == M * N + M + N);
      REQUIRE(dut.transitions == 2 * M * N + M * N * (N == 0 ? 0 : N - 1));
      REQUIRE(dut.transitions == M * N * N + M * N);
    }
  }
}

TEST_CASE("the printed Eq. CountPickPlaceHandoff read literally does not reproduce the table",
          "[planner][representation]") {
  // documents why compositeTransitionsFrom subtracts the empty action set once per element
  CHECK(literalPrintedTransitions(2, 4) == 68);
  for (const TableRow& row : kPaperTable) {
    CHECK(literalPrintedTransitions(static_cast<std::uint64_t>(row.robots), static_cast<std::uint64_t>(row.objects)) !=
          row.graph.transitions);
  }
}

TEST_CASE("representation analysis rejects bad counts and reports overflow", "[planner][representation]") {
  CHECK_THROWS_WITH(compositeGraphSize(-1, 3), Contains("must be >= 0"));
  CHECK_THROWS_WITH(hypergraphSize(2, -3), Contains("must be >= 0"));
  CHECK_THROWS_WITH(compositeTransitionsFrom(2, 4, 3), Contains("3 held objects is impossible"));
  CHECK_THROWS_AS(compositeGraphSize(40, 80), std::overflow_error);
  CHECK_THROWS_WITH(enumerateCompositeTaskGraph(6, 12), Contains("exceed the limit"));
  // large but finite: the hypergraph stays small
  CHECK(hypergraphSize(40, 80) == RepresentationSize{80 * 40 + 80 + 40, 80 * 40 * 40 + 80 * 40});
  // empty problems
  CHECK(compositeGraphSize(0, 0) == RepresentationSize{1, 0});
  CHECK(compositeGraphSize(3, 0) == RepresentationSize{1, 0});
  CHECK(compositeGraphSize(0, 3) == RepresentationSize{1, 0});
}
