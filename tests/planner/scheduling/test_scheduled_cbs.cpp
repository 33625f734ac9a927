// Conflict resolution (resolveConflicts) checked from outside: every schedule it returns keeps
// the rules of its temporal network (each robot's segments in order, a handoff's robots
// starting together, moves arriving just in time or early and then waiting where they end,
// objects' sites free when a motion passes through them) and has no robot-robot conflict, by
// the planner's check and by the independent one on the written plan (plan_checks.h); a bound
// on the makespan drops the schedules not below it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "planner/plan_writer.h"
#include "planner/search/hyperpath_search.h"
#include "planner/sampling/object_sites.h"
#include "planner/scheduling/robot_conflicts.h"
#include "planner/scheduling/schedule_view.h"
#include "planner/scheduling/scheduled_cbs.h"
#include "tests/planner/dash_test_support.h"
#include "tests/planner/plan_checks.h"

using namespace dashbed;
using namespace dashbed::planner;
using namespace dashbed::planner::testing;

namespace {

/// The first greedy task plan of `g`, a direct one.
TransitionHistory firstTaskPlan(WorldGraph& g) {
  const SearchResult found = HyperpathSearch(g.graph).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  REQUIRE_FALSE(found.plan->sequential);
  return *found.plan;
}

const TransitionSample& sampleOf(const MotionHypergraph& graph, const TransitionHistory& history,
                                 const ScheduleSegment& seg) {
  return graph.transition(history.steps.at(static_cast<std::size_t>(seg.step)).transition).sample;
}

/// The sites a segment passes through: its move's, or its transition's.
const SiteSet& touchesOf(const MotionHypergraph& graph, const TransitionHistory& history, const ScheduleSegment& seg) {
  return seg.move != nullptr ? seg.move->touches : sampleOf(graph, history, seg).touches;
}

Millis endOf(const Schedule& schedule, std::size_t s) { return schedule.start[s] + schedule.segments[s].duration; }

/// Checks the rules every resolved schedule of a history without set-aside objects keeps, and
/// returns how many of its moves arrive before their transitions start.
int requireScheduleRules(const MotionHypergraph& graph, const TransitionHistory& history, const Schedule& schedule) {
  const std::vector<ScheduleSegment>& segments = schedule.segments;
  REQUIRE(schedule.start.size() == segments.size());
  int early = 0;
  Millis makespan = 0;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    INFO("segment " << s << " of robot " << segments[s].robot);
    CHECK(schedule.start[s] >= 0);
    makespan = std::max(makespan, endOf(schedule, s));
    if (s + 1 == segments.size() || segments[s + 1].robot != segments[s].robot) continue;
    // a robot does one thing at a time, in its history's order
    CHECK(schedule.start[s + 1] >= endOf(schedule, s));
    if (segments[s].move == nullptr || segments[s + 1].motion == nullptr) continue;
    // a move into a transition arrives as it starts, or (allowed to arrive early) before, and
    // then stands where it ends
    if (!segments[s].early) {
      CHECK(endOf(schedule, s) == schedule.start[s + 1]);
      continue;
    }
    if (endOf(schedule, s) == schedule.start[s + 1]) continue;
    ++early;
    for (const Millis t : {endOf(schedule, s), (endOf(schedule, s) + schedule.start[s + 1]) / 2, schedule.start[s + 1]}) {
      CHECK(scheduledArm(graph, schedule, segments[s].robot, toSeconds(t)) == segments[s].move->path.back());
    }
  }
  CHECK(schedule.makespan == makespan);

  // a handoff's robots start it together
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (std::size_t u = s + 1; u < segments.size(); ++u) {
      if (segments[s].motion != nullptr && segments[u].motion != nullptr && segments[s].step == segments[u].step) {
        CHECK(schedule.start[s] == schedule.start[u]);
      }
    }
  }

  // an object's start site is passed through only after its pick, its goal site only before its
  // place
  const int objects = static_cast<int>(history.objects.size());
  std::vector<int> pick(objects, -1), place(objects, -1);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (segments[s].motion == nullptr) continue;
    const TransitionSample& sample = sampleOf(graph, history, segments[s]);
    const RestPose rest = graph.taskSpace().hyperarcs().at(static_cast<std::size_t>(sample.hyperarc)).rest_pose;
    REQUIRE(rest != RestPose::kAside);
    if (sample.kind == TransitionKind::kPick) pick[sample.object] = static_cast<int>(s);
    if (sample.kind == TransitionKind::kPlace) place[sample.object] = static_cast<int>(s);
  }
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const SiteSet& touches = touchesOf(graph, history, segments[s]);
    for (int b = 0; b < objects; ++b) {
      INFO("segment " << s << ", object " << b);
      if (touches.test(ObjectSites::startSite(b)) && pick[b] >= 0 && pick[b] != static_cast<int>(s)) {
        CHECK(schedule.start[s] >= endOf(schedule, static_cast<std::size_t>(pick[b])));
      }
      if (touches.test(ObjectSites::goalSite(b)) && place[b] >= 0 && place[b] != static_cast<int>(s)) {
        CHECK(endOf(schedule, s) <= schedule.start[static_cast<std::size_t>(place[b])]);
      }
    }
  }
  return early;
}

}  // namespace

TEST_CASE("a resolved schedule keeps its network's rules and lets a robot arrive early only to wait where it stops",
          "[planner][dash]") {
  // worlds whose first greedy task plan resolves with moves arriving early: two robots going
  // into one handoff (3 robots side by side, 2 robots with crossing cubes, the tee), a robot
  // waiting in front of a shelf pick while the other places, and a third robot going early into
  // its handoff so that two others can be ordered (4 robots, 8 crossing cubes: r3 for r1
  // waiting to place cube_1 and r2 on its way to pick cube_7, at Greedy's focal weight)
  struct Case {
    std::string world;
    std::uint64_t seed;
    double focal_weight;
  };
  const Case kase = GENERATE(Case{"sort_3r_6c_side.yaml", 1, 1.0}, Case{"sort_2r_8c_cross.yaml", 7, 1.0},
                             Case{"shelf_2r_4o.yaml", 1, 1.0}, Case{"handwritten/v02_tee_3r_9c.yaml", 7, 1.0},
                             Case{"sort_4r_8c_cross.yaml", 1, kGreedyConflictFocalWeight});
  INFO(kase.world << ", seed " << kase.seed);
  WorldGraph g(worldPath(kase.world), kase.seed);
  const TransitionHistory history = firstTaskPlan(g);
  ConflictResolutionBudget budget;
  budget.max_nodes = 500;
  budget.focal_weight = kase.focal_weight;
  const ConflictResult resolved = resolveConflicts(g.graph, history, budget);
  INFO(resolved.reason);
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  const Schedule& schedule = *resolved.schedule;
  CHECK(schedule.makespan >= resolved.unresolved_makespan);
  CHECK(requireScheduleRules(g.graph, history, schedule) >= 1);
  CHECK_FALSE(firstConflict(g.graph, schedule).has_value());
  // and judged apart from the planner: the written plan, on the simulator's geometry
  requireNoCollision(writePlan(g.graph, history, schedule), g.world);
}

TEST_CASE("conflict resolution keeps only schedules shorter than its bound", "[planner][dash]") {
  WorldGraph g(worldPath("sort_3r_6c_side.yaml"), 1);
  const TransitionHistory history = firstTaskPlan(g);
  ConflictResolutionBudget budget;
  budget.max_nodes = 500;
  const ConflictResult free = resolveConflicts(g.graph, history, budget);
  REQUIRE(free.status == ConflictStatus::kResolved);
  REQUIRE(free.schedule->makespan > free.unresolved_makespan);  // the robots meet and wait

  SECTION("no schedule can be shorter than the one without conflicts resolved") {
    budget.makespan_below = free.unresolved_makespan;
    const ConflictResult bounded = resolveConflicts(g.graph, history, budget);
    CHECK(bounded.status == ConflictStatus::kUnresolvable);
    CHECK_FALSE(bounded.schedule.has_value());
    CHECK(bounded.nodes == 0);
    CHECK(bounded.reason == "no schedule is shorter than " + std::to_string(free.unresolved_makespan) + " ms");
  }
  SECTION("a bound just above the schedule found without one finds one below it") {
    budget.makespan_below = free.schedule->makespan + 1;
    const ConflictResult bounded = resolveConflicts(g.graph, history, budget);
    REQUIRE(bounded.status == ConflictStatus::kResolved);
    CHECK(bounded.schedule->makespan <= free.schedule->makespan);
    requireScheduleRules(g.graph, history, *bounded.schedule);
    CHECK_FALSE(firstConflict(g.graph, *bounded.schedule).has_value());
    requireNoCollision(writePlan(g.graph, history, *bounded.schedule), g.world);
  }
  SECTION("best first, nothing the search reaches is shorter than what it found: bounded there, it finds none") {
    REQUIRE(budget.focal_weight == 1.0);
    budget.makespan_below = free.schedule->makespan;
    const ConflictResult bounded = resolveConflicts(g.graph, history, budget);
    CHECK(bounded.status == ConflictStatus::kUnresolvable);  // every node expanded, none kept
    CHECK(bounded.nodes < budget.max_nodes);
    CHECK_FALSE(bounded.schedule.has_value());
    CHECK_THAT(bounded.reason, Catch::Contains("collide at t = "));  // the last conflict left
  }
}
