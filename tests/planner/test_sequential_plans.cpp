// The sequential greedy query (QueryMode::kSequential), the planner's last resort when conflict
// resolution cannot order the robots of the other plans: its steps run one after another, the
// robots of other steps wait at home, and conflict resolution keeps that order. Also the direct
// query whose transitions keep clear of the robots at home as the sequential ones do
// (QueryMode::kParkClearOfHomes).
#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>
#include <vector>

#include "core/world_loader.h"
#include "core/plan.h"
#include "planner/collision/home_check.h"
#include "planner/search/hyperpath_search.h"
#include "planner/plan_writer.h"
#include "planner/scheduling/robot_conflicts.h"
#include "planner/scheduling/scheduled_cbs.h"
#include "tests/planner/dash_test_support.h"

using namespace dashbed;
using namespace dashbed::planner;
using namespace dashbed::planner::testing;

namespace {

/// The robots taking part in a history step.
std::vector<int> robotsOf(const MotionHypergraph& graph, const ScheduledTransition& step) {
  std::vector<int> robots;
  for (const TransitionMotion& m : graph.transition(step.transition).sample.motions) robots.push_back(m.robot);
  return robots;
}

ConflictResolutionBudget conflictBudget() {
  ConflictResolutionBudget budget;
  budget.max_nodes = 300;
  return budget;
}

/// The graph's sequential greedy task plan and its schedule from conflict resolution.
std::pair<TransitionHistory, Schedule> resolvedSequential(WorldGraph& g) {
  const SearchResult found = HyperpathSearch(g.graph, QueryMode::kSequential).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const ConflictResult resolved = resolveConflicts(g.graph, *found.plan, conflictBudget());
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  return {*found.plan, *resolved.schedule};
}

/// Whether transition `id` runs into `idle` standing at home with its gripper open, checked
/// on 50 configurations per straight piece of every motion.
bool hitsHome(WorldGraph& g, CollisionChecker& checker, int id, int idle) {
  const Eigen::VectorXd home = homeConfiguration(*g.world.world, g.graph.scene(), idle);
  for (const TransitionMotion& m : g.graph.transition(id).sample.motions) {
    for (std::size_t i = 0; i + 1 < m.keys.size(); ++i) {
      for (int k = 0; k <= 50; ++k) {
        core::ArmConfig q;
        for (std::size_t j = 0; j < q.size(); ++j) q[j] = m.keys[i].q[j] + (m.keys[i + 1].q[j] - m.keys[i].q[j]) * k / 50.0;
        const Eigen::VectorXd x = g.graph.scene().configuration(m.robot, q, m.finger[i]);
        if (!checker.robotsFree(m.robot, x, m.held[i], idle, home, std::nullopt)) return true;
      }
    }
  }
  return false;
}

/// Checks that no step of `history` runs into a robot it does not need standing at home.
void checkStepsClearOfHomes(WorldGraph& g, const TransitionHistory& history) {
  CollisionChecker checker(g.graph.scene());
  for (const ScheduledTransition& step : history.steps) {
    const std::vector<int> busy = robotsOf(g.graph, step);
    for (int idle = 0; idle < g.graph.scene().numRobots(); ++idle) {
      INFO("transition " << step.transition << ", robot " << idle << " at home");
      if (std::find(busy.begin(), busy.end(), idle) == busy.end()) CHECK_FALSE(hitsHome(g, checker, step.transition, idle));
    }
  }
}

/// The handoffs of `history` that `robot` receives an object in.
int handoffsTo(const MotionHypergraph& graph, const TransitionHistory& history, int robot) {
  return static_cast<int>(std::count_if(history.steps.begin(), history.steps.end(), [&](const ScheduledTransition& step) {
    const TransitionSample& sample = graph.transition(step.transition).sample;
    return sample.kind == TransitionKind::kHandoff && sample.holderAfter() == robot;
  }));
}

}  // namespace

TEST_CASE("a sequential task plan waits at home between steps and picks one object at a time when it can",
          "[planner][dash]") {
  WorldGraph g(worldPath("default.yaml"));
  const SearchResult found = HyperpathSearch(g.graph, QueryMode::kSequential).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& history = *found.plan;
  CHECK(history.sequential);
  REQUIRE(history.steps.size() >= 2);
  int held = 0;
  for (std::size_t i = 0; i < history.steps.size(); ++i) {
    const ScheduledTransition& step = history.steps[i];
    const TransitionSample& sample = g.graph.transition(step.transition).sample;
    held += sample.kind == TransitionKind::kPick ? 1 : sample.kind == TransitionKind::kPlace ? -1 : 0;
    CHECK(held <= 1);  // the default world's cubes never need a second one on the move
    if (i == 0) continue;
    const ScheduledTransition& before = history.steps[i - 1];
    // the optimistic schedule runs the steps one after another
    CHECK(step.start >= before.start + g.graph.transition(before.transition).sample.duration);
    // a robot that sat out the step before comes from home
    const std::vector<int> previous = robotsOf(g.graph, before);
    for (std::size_t m = 0; m < sample.motions.size(); ++m) {
      const int robot = sample.motions[m].robot;
      if (std::find(previous.begin(), previous.end(), robot) != previous.end()) continue;
      const std::vector<const Move*>& moves = step.moves[m];
      const core::ArmConfig& home = g.world.world->robots[static_cast<std::size_t>(robot)].home;
      const bool from_home = moves.front()->path.front() == home || moves.front()->path.back() == home;
      CHECK(from_home);
    }
  }
}

TEST_CASE("conflict resolution keeps the steps of a sequential task plan one after another", "[planner][dash]") {
  WorldGraph g(worldPath("default.yaml"));
  const auto [history, schedule] = resolvedSequential(g);
  CHECK_FALSE(firstConflict(g.graph, schedule).has_value());
  // every segment of a later phase starts once every segment of an earlier one has ended
  for (std::size_t a = 0; a < schedule.segments.size(); ++a) {
    for (std::size_t b = 0; b < schedule.segments.size(); ++b) {
      if (schedule.segments[a].phase >= schedule.segments[b].phase) continue;
      INFO("segment " << a << " (phase " << schedule.segments[a].phase << ") before segment " << b << " (phase "
                      << schedule.segments[b].phase << ")");
      CHECK(schedule.start[a] + schedule.segments[a].duration <= schedule.start[b]);
    }
  }
  // and only then: a plain history lets the robots overlap
  const SearchResult direct = HyperpathSearch(g.graph).greedy({});
  REQUIRE(direct.status == SearchStatus::kFound);
  CHECK_FALSE(direct.plan->sequential);
  const ConflictResult overlapping = resolveConflicts(g.graph, *direct.plan, conflictBudget());
  REQUIRE(overlapping.status == ConflictStatus::kResolved);
  CHECK(overlapping.schedule->makespan < schedule.makespan);
}

TEST_CASE("conflict resolution may overlap the steps of a sequential task plan, robots waiting at home between theirs",
          "[planner][dash]") {
  WorldGraph g(worldPath("default.yaml"));
  const auto [history, one_after_another] = resolvedSequential(g);
  ConflictResolutionBudget budget = conflictBudget();
  budget.makespan_below = one_after_another.makespan;
  budget.order = GENERATE(NodeOrder::kMakespan, NodeOrder::kAlongTime, NodeOrder::kDepthFirst);
  INFO("node order " << static_cast<int>(budget.order));
  const ConflictResult overlapping = resolveConflicts(g.graph, history, budget, SequentialSteps::kOverlapping);
  REQUIRE(overlapping.status == ConflictStatus::kResolved);
  const Schedule& schedule = *overlapping.schedule;
  CHECK_FALSE(firstConflict(g.graph, schedule).has_value());
  CHECK(schedule.makespan < one_after_another.makespan);
  CHECK(overlapping.unresolved_makespan <= schedule.makespan);
  // the same transitions per robot, in the same order
  const auto parts = [](const Schedule& s, int robot) {
    std::vector<const TransitionMotion*> motions;
    for (const ScheduleSegment& seg : s.segments) {
      if (seg.robot == robot && seg.motion != nullptr) motions.push_back(seg.motion);
    }
    return motions;
  };
  for (int robot = 0; robot < static_cast<int>(g.world.world->robots.size()); ++robot) {
    CHECK(parts(schedule, robot) == parts(one_after_another, robot));
  }
  // two robots of different steps are busy at once somewhere
  bool overlap = false;
  for (std::size_t a = 0; a < schedule.segments.size(); ++a) {
    for (std::size_t b = 0; b < schedule.segments.size(); ++b) {
      const ScheduleSegment& x = schedule.segments[a];
      const ScheduleSegment& y = schedule.segments[b];
      if (x.robot == y.robot || x.phase == y.phase) continue;
      overlap = overlap ||
                (schedule.start[a] < schedule.start[b] + y.duration && schedule.start[b] < schedule.start[a] + x.duration);
    }
  }
  CHECK(overlap);
  // best first, the schedule found is the shortest: none is shorter
  if (budget.order == NodeOrder::kMakespan) {
    budget.makespan_below = schedule.makespan;
    CHECK(resolveConflicts(g.graph, history, budget, SequentialSteps::kOverlapping).status != ConflictStatus::kResolved);
  }
}

TEST_CASE("a plan kept as a fallback is written out the same after the representation grows", "[planner][dash]") {
  // the planner keeps a sequential plan while later rounds look for a direct one: its moves
  // must outlive the rounds that plan every move again
  WorldGraph g(worldPath("default.yaml"));
  const auto [history, schedule] = resolvedSequential(g);
  const std::string before = core::writePlanJson(writePlan(g.graph, history, schedule));
  const std::size_t moves = g.graph.numMoves();
  g.graph.expand();
  g.graph.expand();
  CHECK(g.graph.numMoves() == moves);  // the old moves retired, none planned yet
  CHECK(core::writePlanJson(writePlan(g.graph, history, schedule)) == before);
}

TEST_CASE("a transition is clear of a robot at home unless its motions run into it", "[planner][dash]") {
  // the cube lies right under r0's gripper at home: r1's picks run into it
  WorldGraph g(testWorldPath("idle_home_block.yaml"));
  CollisionChecker checker(g.graph.scene());
  int blocked = 0, clear = 0;
  for (std::size_t h = 0; h < g.task_space.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = g.task_space.hyperarcs()[h];
    if (arc.kind != TransitionKind::kPick) continue;
    const int idle = 1 - arc.robot;
    for (const int id : g.graph.transitionsOf(static_cast<int>(h), -1)) {
      const bool hits = hitsHome(g, checker, id, idle);
      INFO("pick " << id << " by r" << arc.robot);
      if (hits) CHECK_FALSE(g.graph.clearOfIdle(id, idle, IdlePose::kHome));
      (g.graph.clearOfIdle(id, idle, IdlePose::kHome) ? clear : blocked) += 1;
    }
  }
  CHECK(blocked > 0);
  CHECK(clear > 0);
}

TEST_CASE("a sequential task plan keeps every step clear of the robots waiting at home", "[planner][dash]") {
  // only r1 reaches the bin, and its picks run into r0 at home: r0 picks and hands over
  WorldGraph g(testWorldPath("idle_home_block.yaml"));
  const SearchResult found = HyperpathSearch(g.graph, QueryMode::kSequential).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& history = *found.plan;
  REQUIRE_FALSE(history.steps.empty());
  CHECK(g.graph.transition(history.steps.front().transition).sample.motions.front().robot == 0);
  checkStepsClearOfHomes(g, history);
}

TEST_CASE("a robot folds back over its base unless it would hit something, then it waits at home",
          "[planner][dash]") {
  WorldGraph g(testWorldPath("idle_home_fold.yaml"));
  const core::World& world = *g.world.world;
  const std::vector<core::ArmConfig> folded = foldedConfigurations(world, g.graph.scene());
  REQUIRE(folded.size() == 2);
  // r0 folds: the arm pulled in, the gripper nearer its base than at home
  CHECK(folded[0] != world.robots[0].home);
  CHECK(g.graph.idleConfiguration(0, IdlePose::kFolded) == folded[0]);
  CHECK(g.graph.idleConfiguration(0, IdlePose::kHome) == world.robots[0].home);
  const auto reach = [&](const core::ArmConfig& q) {  // horizontal, from the base
    return (*g.world.robots)[0].ik->tcpPose(q).translation().head<2>().norm();
  };
  CHECK(reach(folded[0]) < reach(world.robots[0].home) - 0.2);
  CollisionChecker checker(g.graph.scene());
  const Eigen::VectorXd x0 = g.graph.scene().configuration(0, folded[0], kFingersOpen);
  CHECK(checker.robotFree(0, x0, {}));
  CHECK(checker.robotsFree(0, x0, std::nullopt, 1, homeConfiguration(world, g.graph.scene(), 1), std::nullopt));
  // r1's upper arm would lean into the wall behind it
  CHECK(folded[1] == world.robots[1].home);
  core::ArmConfig r1_folded = world.robots[1].home;
  r1_folded[1] = folded[0][1];
  r1_folded[2] = folded[0][2];
  r1_folded[3] = folded[0][3];
  CHECK_FALSE(checker.robotFree(1, g.graph.scene().configuration(1, r1_folded, kFingersOpen), {}));
}

TEST_CASE("with idle robots folded, a sequential plan folds first, waits folded and unfolds last",
          "[planner][dash]") {
  // the 38 mm cube cannot be handed over, only r1 places it, and r1's picks run into r0 at home
  WorldGraph g(testWorldPath("idle_home_fold.yaml"));
  const SearchResult at_home = HyperpathSearch(g.graph, QueryMode::kSequential).greedy({});
  CHECK(at_home.status == SearchStatus::kExhausted);
  const SearchResult found = HyperpathSearch(g.graph, QueryMode::kSequentialFolded).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& history = *found.plan;
  CHECK(history.sequential);
  CHECK(history.idle == IdlePose::kFolded);
  REQUIRE(history.fold_moves.size() == 2);
  REQUIRE(history.unfold_moves.size() == 2);
  REQUIRE(history.fold_moves[0] != nullptr);
  CHECK(history.fold_moves[1] == nullptr);  // r1 cannot fold (the wall)
  CHECK(history.fold_moves[0]->path.back() == g.graph.idleConfiguration(0, IdlePose::kFolded));
  REQUIRE(history.unfold_moves[0] != nullptr);
  CHECK(history.unfold_moves[0]->path.back() == g.world.world->robots[0].home);
  for (const ScheduledTransition& step : history.steps) CHECK(robotsOf(g.graph, step) == std::vector<int>{1});

  const ConflictResult resolved = resolveConflicts(g.graph, history, conflictBudget());
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  const Schedule& schedule = *resolved.schedule;
  CHECK_FALSE(firstConflict(g.graph, schedule).has_value());
  // r0 is folded (its fold move over) whenever r1 acts, and unfolds once r1 is done
  Millis folded = -1, unfolds = -1, r1_first = -1, r1_last = 0;
  for (std::size_t s = 0; s < schedule.segments.size(); ++s) {
    const ScheduleSegment& seg = schedule.segments[s];
    const Millis end = schedule.start[s] + seg.duration;
    if (seg.move == history.fold_moves[0]) folded = end;
    if (seg.move == history.unfold_moves[0]) unfolds = schedule.start[s];
    if (seg.robot == 1) {
      if (r1_first < 0) r1_first = schedule.start[s];
      r1_last = std::max(r1_last, end);
    }
  }
  REQUIRE(folded >= 0);
  REQUIRE(unfolds >= 0);
  CHECK(folded <= r1_first);
  CHECK(unfolds >= r1_last);
  CHECK(schedule.makespan == unfolds + history.unfold_moves[0]->duration);
  // the written plan starts and ends with both robots at home
  const core::Plan plan = writePlan(g.graph, history, schedule);
  for (std::size_t r = 0; r < 2; ++r) {
    const core::ArmConfig& home = g.world.world->robots[r].home;
    for (const core::TrajectoryPoint* p : {&plan.trajectories[r].points.front(), &plan.trajectories[r].points.back()}) {
      for (std::size_t j = 0; j < 6; ++j) CHECK(p->q[j] == Approx(home[j]).margin(1e-9));
    }
  }
}

TEST_CASE("with relays, a sequential task plan hands an object through the robot standing between giver and placer",
          "[planner][dash]") {
  // robots a, b, c in a row; a alone reaches blue_0 and c alone its bin (red_0 the other way
  // round). Handoffs straight from a to c run over b waiting at home, and by the fastest
  // handoffs b holding the cube is no nearer the goal than a: without relays, no plan
  WorldGraph g(testWorldPath("row_3r_relay.yaml"));
  CHECK(HyperpathSearch(g.graph, QueryMode::kSequential).greedy({}).status == SearchStatus::kExhausted);
  const SearchResult found =
      HyperpathSearch(g.graph, QueryMode::kSequential, HyperpathSearch::Relays::kAroundIdleRobots).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& history = *found.plan;
  // the world as described: in the grasp each end robot picked its cube in, every handoff
  // straight to the other end runs into b at home
  int end_to_end = 0;
  for (const ScheduledTransition& step : history.steps) {
    const MotionTransition& pick = g.graph.transition(step.transition);
    if (pick.sample.kind != TransitionKind::kPick) continue;
    const int giver = pick.sample.motions.front().robot;
    const int grasp = g.graph.vertex(pick.head.front()).grasp;
    for (std::size_t h = 0; h < g.task_space.numHyperarcs(); ++h) {
      const TransitionHyperarc& arc = g.task_space.hyperarcs()[h];
      if (arc.kind != TransitionKind::kHandoff || arc.object != pick.sample.object || arc.robot != giver ||
          arc.receiver != 2 - giver) {
        continue;
      }
      for (const int id : g.graph.transitionsOf(static_cast<int>(h), grasp)) {
        ++end_to_end;
        CHECK_FALSE(g.graph.clearOfIdle(id, 1, IdlePose::kHome));
      }
    }
  }
  CHECK(end_to_end > 0);
  // both cubes pass through b's hand, and no step runs into a robot waiting at home
  CHECK(handoffsTo(g.graph, history, 1) == 2);
  checkStepsClearOfHomes(g, history);
}

TEST_CASE("idle robots parking at home out of every transition's way: the robots work at once, relaying through the "
          "middle one, and conflict resolution orders them",
          "[planner][dash]") {
  // the row of three again (previous test): a direct plan whose transitions all keep clear of
  // the robots at home, so that conflict resolution can hold any robot without an object there
  WorldGraph g(testWorldPath("row_3r_relay_own_cubes.yaml"));
  const SearchResult found =
      HyperpathSearch(g.graph, QueryMode::kParkClearOfHomes, HyperpathSearch::Relays::kAroundIdleRobots).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& history = *found.plan;
  CHECK_FALSE(history.sequential);
  CHECK(handoffsTo(g.graph, history, 1) == 2);
  checkStepsClearOfHomes(g, history);
  bool overlapping = false;  // two steps of different robots run at once
  for (std::size_t k = 0; k < history.steps.size(); ++k) {
    const ScheduledTransition& step = history.steps[k];
    const TransitionSample& sample = g.graph.transition(step.transition).sample;
    const std::vector<int> busy = robotsOf(g.graph, step);
    for (std::size_t j = 0; j < k; ++j) {
      const ScheduledTransition& before = history.steps[j];
      const std::vector<int> others = robotsOf(g.graph, before);
      const bool shared = std::any_of(busy.begin(), busy.end(),
                                      [&](int r) { return std::find(others.begin(), others.end(), r) != others.end(); });
      const Millis before_end = before.start + g.graph.transition(before.transition).sample.duration;
      overlapping = overlapping || (!shared && step.start < before_end && before.start < step.start + sample.duration);
    }
  }
  CHECK(overlapping);
  const ConflictResult resolved = resolveConflicts(g.graph, history, conflictBudget());
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  // shorter than the sequential query's plan with its steps one after another
  const SearchResult sequential =
      HyperpathSearch(g.graph, QueryMode::kSequential, HyperpathSearch::Relays::kAroundIdleRobots).greedy({});
  REQUIRE(sequential.status == SearchStatus::kFound);
  const ConflictResult one_after_another = resolveConflicts(g.graph, *sequential.plan, conflictBudget());
  REQUIRE(one_after_another.status == ConflictStatus::kResolved);
  CHECK(resolved.schedule->makespan < one_after_another.schedule->makespan);
}
