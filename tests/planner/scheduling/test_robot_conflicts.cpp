// The robot-robot check of conflict resolution (firstConflict): which item of each robot a
// conflict at an exact instant belongs to, and which pair's conflict comes first, on schedules
// written by hand; that it checks the robots where the written plan takes them; and how a
// conflict left unresolved is named.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/trajectory_interpolator.h"
#include "core/plan.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "planner/collision/home_check.h"
#include "planner/search/hyperpath_search.h"
#include "planner/plan_writer.h"
#include "planner/scheduling/robot_conflicts.h"
#include "planner/scheduling/scheduled_cbs.h"
#include "planner/sampling/timing.h"
#include "tests/planner/dash_test_support.h"

using namespace dashbed;
using namespace dashbed::planner;
using namespace dashbed::planner::testing;

namespace {

/// A configuration reaching out over the table, the base turned by `pan` [rad].
core::ArmConfig reachingOut(double pan) { return {pan, -0.35, 0.35, -1.5708, -1.5708, 0.0}; }

}  // namespace

TEST_CASE("a robot whose move ends at the instant of a conflict stands after it, whatever the rounding of seconds",
          "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  const MotionHypergraph graph(world, task_space, 7);
  const CollisionScene& scene = graph.scene();
  CollisionChecker checker(scene);
  const core::ArmConfig home_a = world.world->robots[0].home, home_b = world.world->robots[1].home;

  // robot a moves out over the table and stays; robot b, at home until then, is out there as
  // well from the instant a's move ends (a jump no plan makes, so that the two robots first
  // collide at exactly that instant)
  const std::array<double, 4> pans = {0.0, 3.141592653589793, 1.5708, -1.5708};
  std::optional<std::pair<core::ArmConfig, core::ArmConfig>> out;  // (a's, b's)
  const auto free = [&](const core::ArmConfig& qa, const core::ArmConfig& qb) {
    return checker.robotsFree(0, scene.configuration(0, qa, kFingersOpen), std::nullopt, 1,
                              scene.configuration(1, qb, kFingersOpen), std::nullopt);
  };
  for (double pan_a : pans) {
    for (double pan_b : pans) {
      const core::ArmConfig qa = reachingOut(pan_a), qb = reachingOut(pan_b);
      if (!out && !free(qa, qb) && free(qa, home_b) && free(home_a, qb) && free(home_a, home_b)) out.emplace(qa, qb);
    }
  }
  REQUIRE(out);
  Move move_a;
  move_a.robot = 0;
  move_a.path = {home_a, out->first};
  move_a.duration = restToRestDuration(home_a, out->first, graph.timing());
  core::ArmConfig turned_b = out->second;  // b's wrist turns while it is out there
  turned_b[5] += 0.5;
  Move turn_b;
  turn_b.robot = 1;
  turn_b.path = {out->second, turned_b};
  turn_b.duration = restToRestDuration(out->second, turned_b, graph.timing());
  REQUIRE(move_a.duration > 0);

  // a start whose seconds plus the move's seconds come out above the seconds of their sum in
  // whole milliseconds (0.1 + 0.2 > 0.3 in doubles)
  Millis start = 1;
  while (start < 1000 && toSeconds(start) + toSeconds(move_a.duration) <= toSeconds(start + move_a.duration)) ++start;
  REQUIRE(start < 1000);
  const Millis end = start + move_a.duration;

  Schedule schedule;
  ScheduleSegment seg_a;
  seg_a.robot = 0;
  seg_a.move = &move_a;
  seg_a.duration = move_a.duration;
  seg_a.finger = kFingersOpen;
  ScheduleSegment seg_b = seg_a;
  seg_b.robot = 1;
  seg_b.move = &turn_b;
  seg_b.duration = turn_b.duration;
  schedule.segments = {seg_a, seg_b};
  schedule.start = {start, end};
  schedule.makespan = end + turn_b.duration;

  const std::optional<RobotConflict> conflict = firstConflict(graph, schedule);
  REQUIRE(conflict);
  CHECK(conflict->t == toSeconds(end));
  CHECK(conflict->robot_a == 0);
  CHECK(conflict->robot_b == 1);
  CHECK(conflict->item_a == -2);  // standing after its move (its only segment), not on it
  CHECK(conflict->item_b == 0);   // on its segment, which starts then
}

TEST_CASE("conflict resolution checks the robots where the written plan's interpolation takes them",
          "[planner][dash]") {
  WorldGraph g(worldPath("default.yaml"));
  MotionHypergraph& graph = g.graph;
  const SearchResult found = HyperpathSearch(graph).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  ConflictResolutionBudget budget;
  budget.max_nodes = 300;
  const ConflictResult resolved = resolveConflicts(graph, *found.plan, budget);
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  const Schedule& schedule = *resolved.schedule;
  const core::Plan plan = writePlan(graph, *found.plan, schedule);
  REQUIRE(plan.trajectories.size() == g.world.world->robots.size());

  // Along a transition the simulator follows the cubic through the keys, as conflict resolution
  // does; a move is written as samples every 50 ms with their velocities, whose cubics stay
  // within 2e-4 rad of the time-optimal profile conflict resolution checks.
  std::vector<core::TrajectoryInterpolator> written;
  for (const core::RobotTrajectory& trajectory : plan.trajectories) written.emplace_back(trajectory.points);
  int transitions = 0;
  for (std::size_t s = 0; s < schedule.segments.size(); ++s) {
    const ScheduleSegment& seg = schedule.segments[s];
    const double tolerance = seg.motion != nullptr ? 1e-9 : 2e-4;
    transitions += seg.motion != nullptr && seg.motion->keys.size() >= 3 ? 1 : 0;
    for (Millis t = schedule.start[s]; t <= schedule.start[s] + seg.duration; t += 3) {
      const core::ArmConfig checked = scheduledArm(graph, schedule, seg.robot, toSeconds(t));
      const core::JointReference followed = written[static_cast<std::size_t>(seg.robot)].at(toSeconds(t));
      for (int j = 0; j < 6; ++j) {
        INFO("segment " << s << " (robot " << seg.robot << (seg.motion != nullptr ? ", transition" : ", move")
                        << "), t = " << toSeconds(t) << " s, joint " << j);
        REQUIRE(std::abs(checked[j] - followed.q[j]) <= tolerance);
      }
    }
  }
  CHECK(transitions >= 4);  // transitions with keys between their ends, where cubic and line differ
}

TEST_CASE("the earliest conflict of any robot pair is found, whichever pair comes first in order",
          "[planner][dash]") {
  // three robots: r0 and r1 face each other across the table, r2 stands between them at its side
  const core::LoadedWorld world = core::loadWorld(worldPath("sort_3r_6c_side.yaml"));
  REQUIRE(world.world->robots.size() == 3);
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  const MotionHypergraph graph(world, task_space, 7);
  const CollisionScene& scene = graph.scene();
  CollisionChecker checker(scene);
  const auto free = [&](int ra, const core::ArmConfig& qa, int rb, const core::ArmConfig& qb) {
    return checker.robotsFree(ra, scene.configuration(ra, qa, kFingersOpen), std::nullopt, rb,
                              scene.configuration(rb, qb, kFingersOpen), std::nullopt);
  };
  const auto home = [&](int r) { return world.world->robots[static_cast<std::size_t>(r)].home; };
  for (int ra = 0; ra < 3; ++ra) {
    for (int rb = ra + 1; rb < 3; ++rb) REQUIRE(free(ra, home(ra), rb, home(rb)));
  }
  // r2 reaching out into r1 standing at home, clear of r0 at home; r0 reaching out into r1 at
  // home (r1 and r2 are the last pair in order, r0 and r1 the first)
  std::vector<core::ArmConfig> reaching;
  for (int k = 0; k < 16; ++k) {
    for (const double shoulder : {-0.35, -0.9}) {
      reaching.push_back({-3.141592653589793 + k * 3.141592653589793 / 8, shoulder, 0.35, -1.5708, -1.5708, 0.0});
    }
  }
  std::optional<core::ArmConfig> q2, q0;
  for (const core::ArmConfig& q : reaching) {
    if (!q2 && !free(1, home(1), 2, q) && free(0, home(0), 2, q)) q2 = q;
    if (!q0 && !free(0, q, 1, home(1))) q0 = q;
  }
  REQUIRE(q2);
  REQUIRE(q0);

  // each robot jumps to where it reaches out (a one-configuration move: no plan makes such a
  // jump, so that a pair first collides at exactly its start) and stays there
  std::vector<Move> moves(2);
  moves[0].robot = 2;
  moves[0].path = {*q2};
  moves[1].robot = 0;
  moves[1].path = {*q0};
  const auto segment = [&](const Move& move, Millis duration) {
    ScheduleSegment seg;
    seg.robot = move.robot;
    seg.move = &move;
    seg.duration = duration;
    seg.finger = kFingersOpen;
    return seg;
  };
  Schedule schedule;
  schedule.segments = {segment(moves[1], 1000), segment(moves[0], 2000)};
  schedule.makespan = 4000;

  SECTION("the last pair in order first") {
    schedule.start = {3000, 1000};  // r0 out at 3 s, r2 at 1 s
    const std::optional<RobotConflict> conflict = firstConflict(graph, schedule);
    REQUIRE(conflict);
    CHECK(conflict->t == 1.0);
    CHECK(conflict->robot_a == 1);
    CHECK(conflict->robot_b == 2);
    // checked from a later time on (a search node free before then): r2 still stands in r1
    const std::optional<RobotConflict> later = firstConflict(graph, schedule, 1.5);
    REQUIRE(later);
    CHECK(later->t == 1.5);
    CHECK(later->robot_a == 1);
    CHECK(later->robot_b == 2);
  }
  SECTION("two pairs at the same instant: the first in order") {
    schedule.start = {2000, 2000};
    const std::optional<RobotConflict> conflict = firstConflict(graph, schedule);
    REQUIRE(conflict);
    CHECK(conflict->t == 2.0);
    CHECK(conflict->robot_a == 0);
    CHECK(conflict->robot_b == 1);
  }
}

TEST_CASE("a conflict left unresolved is named by what each robot is doing", "[planner][dash]") {
  // the 3 robots' greedy plan has conflicts from its first schedule on: one node leaves the
  // first of them unresolved, and the reason says which robots meet, doing what, and when
  WorldGraph g(worldPath("sort_3r_6c_side.yaml"));
  const SearchResult found = HyperpathSearch(g.graph).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  ConflictResolutionBudget budget;
  budget.max_nodes = 1;
  const ConflictResult resolved = resolveConflicts(g.graph, *found.plan, budget);
  REQUIRE(resolved.status == ConflictStatus::kBudget);
  INFO(resolved.reason);
  const std::string doing =
      R"(\((at home|done|folding|unfolding|on its way to rest|((waiting for|on its way to|parking on its way to) )?)"
      R"((pick|place|handoff) cube_\d( by r\d)+( to r\d)?)\))";
  CHECK_THAT(resolved.reason, Catch::Matches("r\\d " + doing + " and r\\d " + doing + " collide at t = [0-9.]+ s"));
}
