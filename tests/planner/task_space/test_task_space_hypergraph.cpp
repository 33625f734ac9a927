#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/world_loader.h"
#include "planner/motion/hypergraph_dot.h"
#include "planner/task_space/representation_analysis.h"
#include "planner/task_space/task_space_hypergraph.h"

using namespace dashbed::planner;
using Catch::Matchers::Contains;

namespace {

// the moveable bodies of a vertex: robots as 0..n-1, objects as n..n+m-1
std::set<int> bodiesOf(const TaskSpaceHypergraph& graph, int vertex) {
  const TaskSpaceVertex& v = graph.vertices()[vertex];
  std::set<int> bodies;
  if (v.robot >= 0) bodies.insert(v.robot);
  if (v.object >= 0) bodies.insert(graph.numRobots() + v.object);
  return bodies;
}

// the union of the bodies of a vertex set, and whether no two vertices share a body
std::pair<std::set<int>, bool> bodiesOfSet(const TaskSpaceHypergraph& graph, const std::vector<int>& vertices) {
  std::set<int> all;
  bool independent = true;
  for (const int v : vertices) {
    for (const int b : bodiesOf(graph, v)) independent = all.insert(b).second && independent;
  }
  return {all, independent};
}

// invariants of every task-space hypergraph (paper, Task Space Hypergraph): tail and head are
// independent sets of elements with the same moveable bodies; ids and names are consistent
void checkInvariants(const TaskSpaceHypergraph& dut) {
  std::set<std::string> vertex_names, hyperarc_names;
  for (std::size_t v = 0; v < dut.numVertices(); ++v) REQUIRE(vertex_names.insert(dut.vertexName(static_cast<int>(v))).second);
  for (std::size_t e = 0; e < dut.numHyperarcs(); ++e) {
    const TransitionHyperarc& arc = dut.hyperarcs()[e];
    REQUIRE(hyperarc_names.insert(dut.hyperarcName(static_cast<int>(e))).second);
    REQUIRE(std::is_sorted(arc.tail.begin(), arc.tail.end()));
    REQUIRE(std::is_sorted(arc.head.begin(), arc.head.end()));
    const auto [tail_bodies, tail_independent] = bodiesOfSet(dut, arc.tail);
    const auto [head_bodies, head_independent] = bodiesOfSet(dut, arc.head);
    REQUIRE(tail_independent);
    REQUIRE(head_independent);
    REQUIRE(tail_bodies == head_bodies);
    for (const int v : arc.tail) {
      const auto& out = dut.outgoing(v);
      REQUIRE(std::find(out.begin(), out.end(), static_cast<int>(e)) != out.end());
    }
    for (const int v : arc.head) {
      const auto& in = dut.incoming(v);
      REQUIRE(std::find(in.begin(), in.end(), static_cast<int>(e)) != in.end());
    }
  }
  for (int r = 0; r < dut.numRobots(); ++r) {
    for (int o = 0; o < dut.numObjects(); ++o) {
      const int v = dut.holdingVertex(r, o);
      if (v < 0) continue;
      REQUIRE(dut.vertices()[v] == TaskSpaceVertex{TaskElementKind::kRobotHolding, r, o});
      REQUIRE_FALSE(dut.incoming(v).empty());  // obtainable: some transition reaches it
    }
  }
}

dashbed::core::ReachMap reachMap(std::vector<std::vector<int>> start, std::vector<std::vector<int>> goal) {
  dashbed::core::ReachMap reach;
  reach.start = std::move(start);
  reach.goal = std::move(goal);
  return reach;
}

std::vector<std::vector<bool>> overlapMatrix(int robots, bool value) {
  return std::vector<std::vector<bool>>(static_cast<std::size_t>(robots),
                                        std::vector<bool>(static_cast<std::size_t>(robots), value));
}

}  // namespace

TEST_CASE("task-space hypergraph with everything reachable has mn+m+n vertices and mn^2+mn hyperarcs",
          "[planner][task_space]") {
  for (int n = 1; n <= 5; ++n) {
    for (int m = 1; m <= 8; ++m) {
      INFO(n << " robots, " << m << " objects");
      const TaskSpaceHypergraph dut(AllowedTransitions::everything(n, m));
      const RepresentationSize expected = hypergraphSize(n, m);
      REQUIRE(dut.numVertices() == expected.vertices);
      REQUIRE(dut.numHyperarcs() == expected.transitions);
      REQUIRE(dut.numVertices() == static_cast<std::size_t>(m * n + m + n));
      REQUIRE(dut.numHyperarcs() == static_cast<std::size_t>(m * n * n + m * n));
      CHECK(dut.countVertices(TaskElementKind::kRobotAlone) == static_cast<std::size_t>(n));
      CHECK(dut.countVertices(TaskElementKind::kObjectResting) == static_cast<std::size_t>(m));
      CHECK(dut.countVertices(TaskElementKind::kRobotHolding) == static_cast<std::size_t>(m * n));
      CHECK(dut.countHyperarcs(TransitionKind::kPick) == static_cast<std::size_t>(m * n));
      CHECK(dut.countHyperarcs(TransitionKind::kPlace) == static_cast<std::size_t>(m * n));
      CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == static_cast<std::size_t>(m * n * (n - 1)));
      // Alg. 2: picks in the first expansion round, places and handoffs in the second
      CHECK(dut.expansionRounds() == 2);
      checkInvariants(dut);
    }
  }
}

TEST_CASE("the paper's Fig. 2b hypergraph rows are reproduced by construction", "[planner][task_space]") {
  for (const auto& [n, m, vertices, hyperarcs] :
       std::vector<std::tuple<int, int, std::size_t, std::size_t>>{{2, 4, 14, 24}, {2, 8, 26, 48}, {4, 4, 24, 80}, {4, 8, 44, 160}}) {
    const TaskSpaceHypergraph dut(AllowedTransitions::everything(n, m));
    CHECK(dut.numVertices() == vertices);
    CHECK(dut.numHyperarcs() == hyperarcs);
  }
}

TEST_CASE("pick, place and handoff hyperarcs have the paper's tail and head sets", "[planner][task_space]") {
  // Fig. 4 of the paper: two robots, one object
  const TaskSpaceHypergraph dut(AllowedTransitions::everything(2, 1));
  REQUIRE(dut.numVertices() == 5);
  REQUIRE(dut.numHyperarcs() == 6);
  const int r0 = dut.robotAloneVertex(0), r1 = dut.robotAloneVertex(1), o0 = dut.objectRestingVertex(0);
  const int r0o0 = dut.holdingVertex(0, 0), r1o0 = dut.holdingVertex(1, 0);
  CHECK(std::vector<int>{r0, r1, o0, r0o0, r1o0} == std::vector<int>{0, 1, 2, 3, 4});
  CHECK(dut.vertexName(r0) == "r0");
  CHECK(dut.vertexName(o0) == "o0");
  CHECK(dut.vertexName(r1o0) == "r1:o0");

  std::vector<std::string> names;
  for (int e = 0; e < 6; ++e) names.push_back(dut.hyperarcName(e));
  CHECK(names == std::vector<std::string>{"pick(r0,o0)", "pick(r1,o0)", "place(r0,o0)", "place(r1,o0)",
                                          "handoff(r0,r1,o0)", "handoff(r1,r0,o0)"});

  const TransitionHyperarc& pick = dut.hyperarcs()[0];
  CHECK(pick.kind == TransitionKind::kPick);
  CHECK(pick.tail == std::vector<int>{r0, o0});
  CHECK(pick.head == std::vector<int>{r0o0});
  CHECK(pick.rest_pose == RestPose::kStart);

  const TransitionHyperarc& place = dut.hyperarcs()[3];
  CHECK(place.kind == TransitionKind::kPlace);
  CHECK(place.tail == std::vector<int>{r1o0});
  CHECK(place.head == std::vector<int>{r1, o0});
  CHECK(place.rest_pose == RestPose::kGoal);

  const TransitionHyperarc& handoff = dut.hyperarcs()[4];
  CHECK(handoff.kind == TransitionKind::kHandoff);
  CHECK(handoff.robot == 0);
  CHECK(handoff.receiver == 1);
  CHECK(handoff.tail == std::vector<int>{r1, r0o0});
  CHECK(handoff.head == std::vector<int>{r0, r1o0});
  CHECK(handoff.rest_pose == RestPose::kNone);

  CHECK(dut.initialElements() == std::vector<int>{r0, r1, o0});
  CHECK(dut.outgoing(r0o0) == std::vector<int>{2, 4});  // place by r0, handoff r0 -> r1
  CHECK(dut.incoming(r0o0) == std::vector<int>{0, 5});  // pick by r0, handoff r1 -> r0
}

TEST_CASE("a robot that cannot reach some objects gets fewer picks and places", "[planner][task_space]") {
  // 2 robots, 3 objects; r1 reaches only o2 (start and goal); no handoffs
  const auto reach = reachMap({{0}, {0}, {0, 1}}, {{0}, {0}, {0, 1}});
  const TaskSpaceHypergraph dut(2, 3, reach, overlapMatrix(2, false));
  checkInvariants(dut);
  CHECK(dut.countHyperarcs(TransitionKind::kPick) == 4);
  CHECK(dut.countHyperarcs(TransitionKind::kPlace) == 4);
  CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == 0);
  // r1 can never hold o0 or o1: those elements are not obtainable (Alg. 2)
  CHECK(dut.holdingVertex(1, 0) == -1);
  CHECK(dut.holdingVertex(1, 1) == -1);
  CHECK(dut.holdingVertex(1, 2) >= 0);
  CHECK(dut.numVertices() == 2 + 3 + 4);
}

TEST_CASE("a robot reaching nothing can still hold objects through handoffs", "[planner][task_space]") {
  const int m = 3;
  const auto reach = reachMap({{0}, {0}, {0}}, {{0}, {0}, {0}});

  SECTION("without overlap it stays alone") {
    const TaskSpaceHypergraph dut(2, m, reach, overlapMatrix(2, false));
    checkInvariants(dut);
    CHECK(dut.numVertices() == 2 + m + m);
    CHECK(dut.numHyperarcs() == 2 * m);
    CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == 0);
    for (int o = 0; o < m; ++o) CHECK(dut.holdingVertex(1, o) == -1);
    CHECK(dut.outgoing(dut.robotAloneVertex(1)).empty());
  }

  SECTION("with overlap it receives and hands back") {
    const TaskSpaceHypergraph dut(2, m, reach, overlapMatrix(2, true));
    checkInvariants(dut);
    CHECK(dut.numVertices() == 2 * m + m + 2);
    CHECK(dut.countHyperarcs(TransitionKind::kPick) == m);
    CHECK(dut.countHyperarcs(TransitionKind::kPlace) == m);
    CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == 2 * m);
    // picks; then places and handoffs r0 -> r1; then handoffs r1 -> r0 (tail r1:o now exists)
    CHECK(dut.expansionRounds() == 3);
  }
}

TEST_CASE("set-aside hyperarcs: a place there and a pick again per robot that can hold the object",
          "[planner][task_space]") {
  // o0: picked by r0 only, placed by r1 only; o1 without a set-aside site
  AllowedTransitions allowed;
  allowed.robots = 2;
  allowed.objects = 2;
  allowed.reach = reachMap({{0}, {0, 1}}, {{1}, {0, 1}});
  allowed.aside = {{0, 1}, {}};
  SECTION("both robots hold o0 (handoffs): four set-aside hyperarcs, no new vertex") {
    allowed.handoff = overlapMatrix(2, true);
    AllowedTransitions without = allowed;
    without.aside.clear();
    const TaskSpaceHypergraph plain(without);
    const TaskSpaceHypergraph dut(allowed);
    checkInvariants(dut);
    CHECK(dut.numVertices() == plain.numVertices());
    REQUIRE(dut.numHyperarcs() == plain.numHyperarcs() + 4);
    for (std::size_t e = 0; e < plain.numHyperarcs(); ++e) {  // the others keep their ids
      CHECK(dut.hyperarcName(static_cast<int>(e)) == plain.hyperarcName(static_cast<int>(e)));
      CHECK(dut.hyperarcs()[e].rest_pose != RestPose::kAside);
    }
    const int first = static_cast<int>(plain.numHyperarcs());
    CHECK(dut.hyperarcName(first) == "place(r0,o0,aside)");
    CHECK(dut.hyperarcName(first + 1) == "place(r1,o0,aside)");
    CHECK(dut.hyperarcName(first + 2) == "pick(r0,o0,aside)");
    CHECK(dut.hyperarcName(first + 3) == "pick(r1,o0,aside)");
    const TransitionHyperarc& set_down = dut.hyperarcs()[static_cast<std::size_t>(first + 1)];
    const TransitionHyperarc& pick_up = dut.hyperarcs()[static_cast<std::size_t>(first + 3)];
    CHECK(set_down.kind == TransitionKind::kPlace);
    CHECK(set_down.rest_pose == RestPose::kAside);
    CHECK(set_down.tail == std::vector<int>{dut.holdingVertex(1, 0)});
    CHECK(pick_up.kind == TransitionKind::kPick);
    CHECK(pick_up.rest_pose == RestPose::kAside);
    CHECK(pick_up.tail == set_down.head);
    CHECK(pick_up.head == set_down.tail);
  }
  SECTION("without handoffs r1 never holds o0: only r0 sets it aside") {
    allowed.handoff = overlapMatrix(2, false);
    const TaskSpaceHypergraph dut(allowed);
    checkInvariants(dut);
    std::vector<std::string> aside;
    for (std::size_t e = 0; e < dut.numHyperarcs(); ++e) {
      if (dut.hyperarcs()[e].rest_pose == RestPose::kAside) aside.push_back(dut.hyperarcName(static_cast<int>(e)));
    }
    CHECK(aside == std::vector<std::string>{"place(r0,o0,aside)", "pick(r0,o0,aside)"});
  }
}

TEST_CASE("robots without workspace overlap get no handoffs", "[planner][task_space]") {
  // three robots in a row: r0-r1 and r1-r2 overlap, r0-r2 do not
  std::vector<std::vector<bool>> overlap = overlapMatrix(3, false);
  overlap[0][1] = overlap[1][0] = overlap[1][2] = overlap[2][1] = true;
  AllowedTransitions allowed = AllowedTransitions::everything(3, 2);
  allowed.handoff = overlap;
  const TaskSpaceHypergraph dut(allowed);
  checkInvariants(dut);
  CHECK(dut.numVertices() == hypergraphSize(3, 2).vertices);
  CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == 2 * 4);  // 4 ordered pairs per object
  for (std::size_t e = 0; e < dut.numHyperarcs(); ++e) {
    const TransitionHyperarc& arc = dut.hyperarcs()[e];
    if (arc.kind != TransitionKind::kHandoff) continue;
    CHECK(std::abs(arc.robot - arc.receiver) == 1);
  }

  const TaskSpaceHypergraph isolated(3, 2, allowed.reach, overlapMatrix(3, false));
  CHECK(isolated.numHyperarcs() == 2 * 3 * 2);
  CHECK(isolated.countHyperarcs(TransitionKind::kHandoff) == 0);
}

TEST_CASE("cross starts: picks by one robot, places by the other, handoffs between", "[planner][task_space]") {
  // every start reached only by r0, every goal only by r1 (the default world's pattern)
  const auto reach = reachMap({{0}, {0}, {0}, {0}}, {{1}, {1}, {1}, {1}});
  const TaskSpaceHypergraph dut(2, 4, reach, overlapMatrix(2, true));
  checkInvariants(dut);
  CHECK(dut.numVertices() == 14);
  CHECK(dut.countHyperarcs(TransitionKind::kPick) == 4);
  CHECK(dut.countHyperarcs(TransitionKind::kPlace) == 4);
  CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == 8);

  // without overlap r1 never gets an object, so its places are unreachable and left out
  const TaskSpaceHypergraph apart(2, 4, reach, overlapMatrix(2, false));
  CHECK(apart.numVertices() == 2 + 4 + 4);
  CHECK(apart.numHyperarcs() == 4);
  CHECK(apart.countHyperarcs(TransitionKind::kPlace) == 0);
}

TEST_CASE("hyperarc sets at each composite element generate exactly the composite graph",
          "[planner][task_space][representation]") {
  // cross-check of two independent constructions: a composite transition is a non-empty set of
  // hyperarcs with pairwise independent tails, all present in the element's decomposition
  for (int n = 1; n <= 3; ++n) {
    for (int m = 1; m <= 3; ++m) {
      INFO(n << " robots, " << m << " objects");
      const TaskSpaceHypergraph hypergraph(AllowedTransitions::everything(n, m));
      const CompositeTaskGraph graph = enumerateCompositeTaskGraph(n, m);
      std::map<std::vector<int>, int> index;
      for (std::size_t e = 0; e < graph.elements.size(); ++e) index[graph.elements[e]] = static_cast<int>(e);

      std::set<std::pair<int, int>> generated;
      std::size_t action_sets = 0;
      for (std::size_t e = 0; e < graph.elements.size(); ++e) {
        const std::vector<int>& holder = graph.elements[e];
        // decomposition of the element into task-space vertices
        std::set<int> present;
        std::vector<bool> busy(static_cast<std::size_t>(n), false);
        for (int o = 0; o < m; ++o) {
          if (holder[o] < 0) {
            present.insert(hypergraph.objectRestingVertex(o));
          } else {
            present.insert(hypergraph.holdingVertex(holder[o], o));
            busy[holder[o]] = true;
          }
        }
        for (int r = 0; r < n; ++r) {
          if (!busy[r]) present.insert(hypergraph.robotAloneVertex(r));
        }
        std::vector<int> applicable;
        for (std::size_t a = 0; a < hypergraph.numHyperarcs(); ++a) {
          const auto& tail = hypergraph.hyperarcs()[a].tail;
          if (std::all_of(tail.begin(), tail.end(), [&](int v) { return present.count(v) > 0; })) {
            applicable.push_back(static_cast<int>(a));
          }
        }
        REQUIRE(applicable.size() < 20);
        for (unsigned mask = 1; mask < (1u << applicable.size()); ++mask) {
          std::set<int> used;
          bool independent = true;
          std::vector<int> next = holder;
          for (std::size_t i = 0; i < applicable.size() && independent; ++i) {
            if (!(mask & (1u << i))) continue;
            const TransitionHyperarc& arc = hypergraph.hyperarcs()[applicable[i]];
            for (const int v : arc.tail) independent = used.insert(v).second && independent;
            switch (arc.kind) {
              case TransitionKind::kPick: next[arc.object] = arc.robot; break;
              case TransitionKind::kPlace: next[arc.object] = CompositeTaskGraph::kResting; break;
              case TransitionKind::kHandoff: next[arc.object] = arc.receiver; break;
            }
          }
          if (!independent) continue;
          ++action_sets;
          REQUIRE(index.count(next) == 1);
          REQUIRE(generated.insert({static_cast<int>(e), index.at(next)}).second);  // distinct sets, distinct successors
        }
      }
      const std::set<std::pair<int, int>> enumerated(graph.transitions.begin(), graph.transitions.end());
      CHECK(generated == enumerated);
      CHECK(action_sets == compositeGraphTransitions(n, m));
    }
  }
}

TEST_CASE("bad allowed transitions are rejected with a message", "[planner][task_space]") {
  AllowedTransitions allowed = AllowedTransitions::everything(2, 2);
  SECTION("robot out of range") {
    allowed.reach.start[1] = {0, 2};
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("reach.start[1] names robot 2 of 2"));
  }
  SECTION("robot repeated") {
    allowed.reach.goal[0] = {1, 1};
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("reach.goal[0] names robot 1 twice"));
  }
  SECTION("reach of the wrong size") {
    allowed.reach.goal.pop_back();
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("one entry per object"));
  }
  SECTION("overlap matrix of the wrong size") {
    allowed.handoff[1].pop_back();
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("handoff row 1 has 1 entries, expected 2"));
  }
  SECTION("set-aside robots of the wrong size or out of range") {
    allowed.aside = {{0}};
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("aside needs no entry or one per object (2), got 1"));
    allowed.aside = {{0}, {2}};
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("aside[1] names robot 2 of 2"));
  }
  SECTION("negative counts") {
    allowed.robots = -1;
    CHECK_THROWS_WITH(TaskSpaceHypergraph(allowed), Contains("must be >= 0"));
  }
  SECTION("out-of-range accessors") {
    const TaskSpaceHypergraph dut(allowed);
    CHECK_THROWS_AS(dut.holdingVertex(2, 0), std::out_of_range);
    CHECK_THROWS_AS(dut.objectRestingVertex(-1), std::out_of_range);
    CHECK_THROWS_AS(dut.vertexName(99), std::out_of_range);
  }
}

TEST_CASE("DOT output is deterministic and draws each hyperarc as a node", "[planner][task_space][dot]") {
  const auto reach = reachMap({{0}, {0, 1}}, {{1}, {1}});
  const TaskSpaceHypergraph a(2, 2, reach, overlapMatrix(2, true));
  const TaskSpaceHypergraph b(2, 2, reach, overlapMatrix(2, true));
  const std::string dot = toDot(a);
  CHECK(dot == toDot(b));
  CHECK(dot.rfind("digraph \"task_space_hypergraph\" {", 0) == 0);
  CHECK(dot.back() == '\n');

  std::size_t vertex_nodes = 0, hyperarc_nodes = 0, lines_in = 0, arrows_out = 0;
  std::istringstream lines(dot);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  v", 0) == 0 && line.find("[label=") != std::string::npos) ++vertex_nodes;
    if (line.rfind("  e", 0) == 0 && line.find("shape=circle") != std::string::npos) ++hyperarc_nodes;
    if (line.find("arrowhead=none") != std::string::npos) ++lines_in;
    if (line.rfind("  e", 0) == 0 && line.find(" -> v") != std::string::npos) ++arrows_out;
  }
  std::size_t tails = 0, heads = 0;
  for (const auto& arc : a.hyperarcs()) {
    tails += arc.tail.size();
    heads += arc.head.size();
  }
  CHECK(vertex_nodes == a.numVertices());
  CHECK(hyperarc_nodes == a.numHyperarcs());
  CHECK(lines_in == tails);
  CHECK(arrows_out == heads);
  CHECK_THAT(dot, Contains("label=\"r1:o1\""));
  CHECK_THAT(dot, Contains("xlabel=\"handoff(r0,r1,o0)\""));
}

TEST_CASE("fromWorld on the default world: cross starts, handoffs between the two robots", "[planner][task_space]") {
  const auto loaded = dashbed::core::loadWorld(std::filesystem::path(DASHBED_SOURCE_ROOT) / "worlds/default.yaml");
  const auto& world = *loaded.world;
  REQUIRE(world.robots.size() == 2);
  REQUIRE(world.objects.size() == 4);
  // the world's cross layout: each start reached by one robot, its goal by the other one
  for (std::size_t o = 0; o < 4; ++o) {
    INFO(world.objects[o].name);
    REQUIRE(loaded.reach.start[o].size() == 1);
    REQUIRE(loaded.reach.goal[o].size() == 1);
    REQUIRE(loaded.reach.start[o][0] != loaded.reach.goal[o][0]);
  }

  const TaskSpaceHypergraph dut = TaskSpaceHypergraph::fromWorld(world, *loaded.robots, loaded.reach);
  checkInvariants(dut);
  CHECK(dut.allowed().handoff[0][1]);
  CHECK(dut.allowed().handoff[1][0]);
  CHECK(dut.numVertices() == 14);
  CHECK(dut.numHyperarcs() == 16);
  CHECK(dut.countHyperarcs(TransitionKind::kPick) == 4);
  CHECK(dut.countHyperarcs(TransitionKind::kPlace) == 4);
  CHECK(dut.countHyperarcs(TransitionKind::kHandoff) == 8);
  CHECK(dut.numHyperarcs() < hypergraphSize(2, 4).transitions);

  // names come from the world; each pick is by the robot reaching the start, each place by the
  // robot reaching the goal
  CHECK(dut.vertexName(dut.objectRestingVertex(0)) == "cube_0");
  CHECK(dut.robotName(0) == "r0");
  for (const TransitionHyperarc& arc : dut.hyperarcs()) {
    if (arc.kind == TransitionKind::kPick) CHECK(arc.robot == loaded.reach.start[arc.object][0]);
    if (arc.kind == TransitionKind::kPlace) CHECK(arc.robot == loaded.reach.goal[arc.object][0]);
  }
  const int giver = loaded.reach.start[0][0];
  const int receiver = loaded.reach.goal[0][0];
  CHECK(dut.vertexName(dut.holdingVertex(receiver, 0)) == world.robots[receiver].name + ":cube_0");
  bool found = false;
  for (std::size_t e = 0; e < dut.numHyperarcs(); ++e) {
    found = found || dut.hyperarcName(static_cast<int>(e)) ==
                         "handoff(" + world.robots[giver].name + "," + world.robots[receiver].name + ",cube_0)";
  }
  CHECK(found);
}
