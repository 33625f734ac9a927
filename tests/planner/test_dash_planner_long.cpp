// The DaSH planner's longer runs (label "long"): the shelving search with its scheduling
// constraints, shelving end to end, three robots in a hand-written layout, six robots in rows,
// five in a ring, four in the paper's square and at the table's corners (a robot folding out of
// the others' way), the sequential search on a crowded ring, and MM-DaSH against greedy.
// Iteration caps, no wall-clock budgets.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/world_loader.h"
#include "planner/dash_planner.h"
#include "planner/search/hyperpath_search.h"
#include "planner/scheduling/robot_conflicts.h"
#include "planner/scheduling/scheduled_cbs.h"
#include "tools/scenarios/scenarios.h"
#include "tests/planner/dash_test_support.h"
#include "tests/planner/plan_checks.h"

using namespace dashbed;
using namespace dashbed::planner;
using namespace dashbed::planner::testing;

namespace {

/// solve() on `world`, which must solve it with a plan whose actions are valid and whose robots
/// never collide along its timing.
PlanResult solvedValid(const core::LoadedWorld& world, const PlannerSettings& settings) {
  PlanResult result = solve(world, settings);
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  requireValidActions(*result.plan, *world.world);
  requireNoCollision(*result.plan, world);
  return result;
}

/// The first greedy task plan on `graph`, which must be a direct one, resolved as the
/// planner's first try does (500 nodes, Greedy's focal weight, 24 re-routes); it must resolve.
ConflictResult firstTaskPlanResolved(MotionHypergraph& graph) {
  const SearchResult found = HyperpathSearch(graph).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  REQUIRE_FALSE(found.plan->sequential);
  ConflictResolutionBudget budget;
  budget.max_nodes = 500;
  budget.focal_weight = kGreedyConflictFocalWeight;
  budget.max_reroutes = 24;
  ConflictResult resolved = resolveConflicts(graph, *found.plan, budget);
  INFO(resolved.reason);
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  return resolved;
}

}  // namespace

TEST_CASE("shelving task plans fill the back slot before the front slot in front of it", "[planner][dash][shelf]") {
  // the scheduling constraint at the level of the hyperpath search: a place into a back slot
  // touches the goal site of the object in front, so the front object waits
  const core::LoadedWorld world = core::loadWorld(worldPath("shelf_2r_4o.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  RepresentationSettings settings;
  settings.handoff_samples_per_round = 1;  // the tall items' handoffs are costly to sample
  MotionHypergraph graph(world, task_space, 3, settings);
  HyperpathSearch search(graph);
  SearchBudget budget;
  budget.max_expansions = 5000;
  SearchResult found;
  for (int round = 0; round < 5 && found.status != SearchStatus::kFound; ++round) {
    if (round > 0) graph.expand();
    found = search.greedy(budget);
  }
  REQUIRE(found.status == SearchStatus::kFound);
  // the order the greedy query ranks its candidates by: green_k (back) before blue_k (front)
  const auto id = [&](const std::string& name) {
    return static_cast<int>(world.world->findObject(name) - world.world->objects.data());
  };
  for (const std::string k : {"0", "1"}) {
    const std::vector<int>& before_blue = search.placedBefore(id("blue_" + k));
    const std::vector<int>& before_green = search.placedBefore(id("green_" + k));
    CHECK(std::count(before_blue.begin(), before_blue.end(), id("green_" + k)) == 1);
    CHECK(std::count(before_green.begin(), before_green.end(), id("blue_" + k)) == 0);
  }
  std::map<std::string, Millis> placed_at;  // region -> start of its place
  for (const ScheduledTransition& step : found.plan->steps) {
    const TransitionSample& sample = graph.transition(step.transition).sample;
    if (sample.kind != TransitionKind::kPlace) continue;
    placed_at[world.world->regions[graph.sites().goal_region[sample.object]].name] = step.start;
  }
  REQUIRE(placed_at.size() == world.world->objects.size());
  int pairs = 0;
  for (const auto& [region, start] : placed_at) {
    const auto front = region.find("_front");
    if (front == std::string::npos) continue;
    const std::string back = region.substr(0, front) + "_back";
    if (placed_at.count(back) == 0) continue;
    ++pairs;
    CHECK(placed_at.at(back) < start);
  }
  CHECK(pairs == 2);
}

TEST_CASE("shelving plans solve end to end, back slots first, with conflicts fed back to the search",
          "[planner][dash][shelf]") {
  // generator seed 1 (the file), and seed 5: there r1 reaches its front slot only with the arm
  // along the shelf, and the robot-alone roadmap has to grow into the shelf to get it home
  const std::uint64_t seed = GENERATE(1, 5);
  const core::LoadedWorld world = seed == 1 ? core::loadWorld(worldPath("shelf_2r_4o.yaml"))
                                            : core::validateWorld(tools::generateShelving({4, seed}));
  PlannerSettings settings = testSettings();
  settings.seed = seed;
  const PlanResult result = solvedValid(world, settings);
  std::map<std::string, double> placed_at;  // region -> start of its place (not setting aside)
  for (const core::PlanAction& a : result.plan->actions) {
    if (a.type == core::ActionType::kPlace && !a.region.empty()) placed_at[a.region] = a.start;
  }
  REQUIRE(placed_at.size() == world.world->objects.size());
  int pairs = 0;
  for (const auto& [region, start] : placed_at) {
    const auto front = region.find("_front");
    if (front == std::string::npos) continue;
    ++pairs;
    CHECK(placed_at.at(region.substr(0, front) + "_back") < start);
  }
  CHECK(pairs == 2);
}

TEST_CASE("three robots in a layout of their own get valid collision-free plans", "[planner][dash]") {
  // r2 stands at the side of the table between the two others: its moves cross theirs, and
  // conflict resolution needs orderings, detours or parkings
  const core::LoadedWorld world = core::loadWorld(worldPath("sort_3r_6c_side.yaml"));
  const PlanResult result = solvedValid(world, testSettings());
  std::set<std::string> busy;
  for (const core::PlanAction& a : result.plan->actions) busy.insert(a.robot);
  CHECK(busy.size() == 3);
}

TEST_CASE("six robots in two rows hand every cube along the table", "[planner][dash]") {
  // cross start in rows: each cube starts at the far end of the table from its bin, two columns
  // away, so it passes through at least two handoffs (and robots hand to neighbours on either
  // side while others work next to them)
  const core::LoadedWorld world =
      core::validateWorld(tools::generateSorting({6, 4, 4, tools::StartLayout::kCross, 1, tools::RobotLayout::kRows}));
  const PlanResult result = solvedValid(world, testSettings());
  std::map<std::string, int> handoffs;  // object -> handoffs
  std::set<std::string> busy;
  for (const core::PlanAction& a : result.plan->actions) {
    busy.insert(a.robot);
    if (a.type == core::ActionType::kHandoff) {
      ++handoffs[a.object];
      busy.insert(a.receiver);
    }
  }
  REQUIRE(handoffs.size() == world.world->objects.size());
  for (const auto& [object, count] : handoffs) {
    INFO(object);
    CHECK(count >= 2);
  }
  CHECK(busy.size() == 6);
}

TEST_CASE("five robots in a ring hand cubes across their shared centre", "[planner][dash]") {
  // cross start in a ring: each cube starts in front of the robot across from its bin's robot
  const core::LoadedWorld world =
      core::validateWorld(tools::generateSorting({5, 5, 4, tools::StartLayout::kCross, 3, tools::RobotLayout::kRing}));
  const PlanResult result = solvedValid(world, testSettings());
  int handoffs = 0;
  for (const core::PlanAction& a : result.plan->actions) handoffs += a.type == core::ActionType::kHandoff ? 1 : 0;
  CHECK(handoffs >= static_cast<int>(world.world->objects.size()));
}

TEST_CASE("four robots hand twelve crossing cubes side by side, a focal weight above 1 in fewer nodes",
          "[planner][dash]") {
  // the paper's square of four robots: every cube needs a handoff, and the robots reach into
  // the shared centre at once. Greedy's default weight resolves the conflicts in fewer nodes
  // than best first (focal weight 1), which exhausts more task plans' conflict trees before one
  // resolves, and here ends within its factor of best first's makespan (the weight bounds a
  // node against the shortest open one when it is taken, not against best first's result: a
  // detour may make a child shorter than its parent)
  const core::LoadedWorld world = core::validateWorld(tools::generateSorting({4, 12, 4, tools::StartLayout::kCross, 2}));
  const auto run = [&](double focal_weight) {
    PlannerSettings settings;
    settings.seed = 2;
    settings.max_rounds = 8;
    settings.conflict_focal_weight = focal_weight;
    const PlanResult result = solvedValid(world, settings);
    CHECK_FALSE(result.stats.sequential);
    return result.stats;
  };
  const PlannerStats best_first = run(1.0);
  const PlannerStats focal = run(kGreedyConflictFocalWeight);
  CHECK(focal.task_plans <= best_first.task_plans);
  CHECK(focal.conflict_nodes < best_first.conflict_nodes);
  CHECK(focal.makespan <= kGreedyConflictFocalWeight * best_first.makespan);
}

TEST_CASE("MM-DaSH (optimal) is never worse than greedy", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const PlanResult greedy = solve(world, testSettings(Method::kGreedy));
  PlannerSettings settings = testSettings(Method::kOptimal);
  settings.search_expansions = 100;
  settings.next_best_plans = 2;
  const PlanResult optimal = solve(world, settings);
  REQUIRE(greedy.status == PlannerStatus::kSolved);
  REQUIRE(optimal.status == PlannerStatus::kSolved);
  CHECK(optimal.stats.makespan <= greedy.stats.makespan);
}

TEST_CASE("MM-DaSH runs as greedy until greedy has a plan, and is then never worse", "[planner][dash]") {
  // with one handoff sample a round, greedy finds no plan in its first rounds; Next-Best Search
  // waits for one (its upper bound), so that the representation grows as greedy's does
  const core::LoadedWorld world = core::loadWorld(testWorldPath("shelf_front_slots.yaml"));
  const auto run = [&](Method method, std::vector<std::string>& log) {
    PlannerSettings settings = testSettings(method);
    settings.representation.handoff_samples_per_round = 1;
    PlannerBudget budget;
    budget.progress = [&](const std::string& line) { log.push_back(line); };
    return solve(world, settings, budget);
  };
  std::vector<std::string> greedy_log, optimal_log;
  const PlanResult greedy = run(Method::kGreedy, greedy_log);
  const PlanResult optimal = run(Method::kOptimal, optimal_log);
  REQUIRE(greedy.status == PlannerStatus::kSolved);
  REQUIRE(greedy.stats.rounds > 1);
  REQUIRE(optimal.status == PlannerStatus::kSolved);
  CHECK(optimal.stats.rounds == greedy.stats.rounds);
  CHECK(optimal.stats.makespan <= greedy.stats.makespan);
  // the same queries and conflict resolutions up to greedy's plan
  const auto found = std::find_if(greedy_log.begin(), greedy_log.end(), [](const std::string& line) {
    return line.rfind("conflict resolution: makespan", 0) == 0;
  });
  REQUIRE(found != greedy_log.end());
  const std::vector<std::string> before(greedy_log.begin(), found + 1);
  REQUIRE(optimal_log.size() >= before.size());
  CHECK(std::vector<std::string>(optimal_log.begin(), optimal_log.begin() + before.size()) == before);
}

TEST_CASE("a crowded sequential task plan backtracks to the step that went wrong, not through all after it",
          "[planner][dash]") {
  // five robots around a crowded centre. Two ways a depth-first search can order every other
  // step before finding out, then run out of its budget backtracking through the last ones: a
  // place whose robot has no way back to where it waits clear of the robots waiting (the
  // history fails only at its final move), and a robot holding an object it has no way to hand
  // on, while the search starts on other objects instead of taking back that pick. The search
  // must catch both where they happen.
  const core::LoadedWorld world = core::loadWorld(testWorldPath("ring_5r_10c.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  SearchBudget budget;
  budget.max_expansions = 1000;  // a sequential query's in round 1
  for (const QueryMode mode : {QueryMode::kSequential, QueryMode::kSequentialFolded}) {
    INFO("folded " << (mode == QueryMode::kSequentialFolded));
    const SearchResult found = HyperpathSearch(graph, mode).greedy(budget);
    REQUIRE(found.status == SearchStatus::kFound);
    const TransitionHistory& history = *found.plan;
    CHECK(history.steps.size() >= 20);  // 10 picks and 10 places at least
    for (std::size_t r = 0; r < history.final_moves.size(); ++r) {
      const core::ArmConfig& rest = graph.idleConfiguration(static_cast<int>(r), history.idle);
      if (history.final_moves[r] != nullptr) CHECK(history.final_moves[r]->path.back() == rest);
    }
  }
}

TEST_CASE("a round's failed direct task plans resolved again with more reroutes replace a longer sequential plan",
          "[planner][dash]") {
  // two robots 0.6 m apart: conflict resolution with a first allowance of 12 detours and
  // parkings orders the robots of none of the direct task plans, and round 1 falls back to one
  // object at a time; a later round's second try with more resolves one of its direct plans,
  // shorter (with the default 24, the first try already resolves one)
  const core::LoadedWorld world = core::loadWorld(worldPath("handwritten/v12_close_0p6.yaml"));
  PlannerSettings settings;  // `dashbed plan`'s, with fewer re-routes on the first try
  settings.conflict_reroutes = 12;
  PlannerSettings once = settings;
  once.conflict_reroutes_retry = once.conflict_reroutes;  // no second try
  const PlanResult first_try = solvedValid(world, once);
  CHECK(first_try.stats.sequential);
  const PlanResult second_try = solvedValid(world, settings);
  CHECK_FALSE(second_try.stats.sequential);
  CHECK(second_try.stats.makespan < first_try.stats.makespan);
}

TEST_CASE("six robots in a ring get a direct plan from the second try along time with its own node budget",
          "[planner][dash]") {
  // six robots reaching into one shared centre: round 1 ends with a sequential plan, and no
  // direct task plan resolves best first; the second try along time (NodeOrder::kAlongTime)
  // resolves the conflicts one after another and needs more nodes than conflict_nodes for it:
  // its own budget, conflict_nodes_along_time
  const core::LoadedWorld world =
      core::validateWorld(tools::generateSorting({6, 6, 4, tools::StartLayout::kRandom, 3, tools::RobotLayout::kRing}));
  const PlannerSettings settings;  // `dashbed plan`'s
  REQUIRE(settings.conflict_nodes_along_time > settings.conflict_nodes);
  const PlanResult result = solvedValid(world, settings);
  CHECK_FALSE(result.stats.sequential);
  CHECK(result.stats.rounds > 1);  // found in a round after the sequential fallback's
}

TEST_CASE("a plan with the robots parked out of every transition's way is a fallback: the direct queries go on",
          "[planner][dash]") {
  // a row of three relaying cubes from end to end: no direct task plan of round 1 resolves,
  // the one keeping clear of the robots at home does; like a sequential plan it is kept while
  // the direct queries of sequential_fallback_rounds more rounds look for a shorter one, and the
  // sequential query never runs
  const core::LoadedWorld world = core::loadWorld(worldPath("handwritten/v16_row3_relay.yaml"));
  const PlannerSettings settings;
  std::vector<std::string> progress;
  PlannerBudget budget;
  budget.progress = [&](const std::string& line) { progress.push_back(line); };
  const PlanResult result = solve(world, settings, budget);
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  requireValidActions(*result.plan, *world.world);
  requireNoCollision(*result.plan, world);
  CHECK_FALSE(result.stats.sequential);
  CHECK(result.stats.rounds == 1 + settings.sequential_fallback_rounds);
  const auto said = [&](const std::string& text) {
    return std::any_of(progress.begin(), progress.end(),
                       [&](const std::string& line) { return line.find(text) != std::string::npos; });
  };
  CHECK(said("keeping the plan with the robots parked out of every transition's way"));
  CHECK_FALSE(said("one object at a time"));
}

TEST_CASE("a second try that runs out of nodes best first resolves depth first along time, below the sequential plan",
          "[planner][dash]") {
  // two robots 0.6 m apart sorting 10 cubes: no direct task plan resolves on the first try and
  // round 1 falls back to one object at a time. On a later round's second try, best first runs
  // out of its nodes ordering the robots' many meetings both ways; along time (or, on the
  // shortest plan, depth first), which takes any schedule shorter than the fallback's, finds one
  const core::LoadedWorld world = core::loadWorld(worldPath("handwritten/v15_close_10c.yaml"));
  std::vector<std::string> progress;
  PlannerBudget budget;
  budget.progress = [&](const std::string& line) { progress.push_back(line); };
  const PlanResult result = solve(world, PlannerSettings{}, budget);
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  requireValidActions(*result.plan, *world.world);
  requireNoCollision(*result.plan, world);
  CHECK_FALSE(result.stats.sequential);
  const auto line_with = [&](const std::string& text, std::size_t from = 0) {
    return std::find_if(progress.begin() + static_cast<std::ptrdiff_t>(from), progress.end(),
                        [&](const std::string& line) { return line.find(text) != std::string::npos; });
  };
  const std::string kept = "keeping the sequential plan (makespan ";
  const auto fallback = line_with(kept);
  REQUIRE(fallback != progress.end());
  CHECK(result.stats.makespan < std::stod(fallback->substr(fallback->find(kept) + kept.size())));
  // the plan comes from a second try, after a failure there
  const auto again = line_with("conflict resolution again");
  REQUIRE(again != progress.end());
  const auto resolved = line_with("conflict resolution: makespan", static_cast<std::size_t>(again - progress.begin()));
  REQUIRE(resolved != progress.end());
  REQUIRE(resolved - again >= 2);
  CHECK((resolved - 1)->find("conflict resolution failed") != std::string::npos);
}

TEST_CASE("a robot standing in the others' way folds back over its base to wait where no nearer parking helps",
          "[planner][dash]") {
  // four robots at the table's corners: seed 1's first greedy task plan resolves only with a
  // robot folded back over its base while the others pass (without folding: no schedule in
  // 500 nodes)
  WorldGraph g(worldPath("handwritten/u05_corners_4r.yaml"), 1);
  MotionHypergraph& graph = g.graph;
  const ConflictResult resolved = firstTaskPlanResolved(graph);
  const Schedule& schedule = *resolved.schedule;
  CHECK_FALSE(firstConflict(graph, schedule).has_value());

  int folds = 0;
  for (std::size_t s = 0; s + 1 < schedule.segments.size(); ++s) {
    const ScheduleSegment& there = schedule.segments[s];
    const core::ArmConfig& folded = graph.idleConfiguration(there.robot, IdlePose::kFolded);
    if (there.move == nullptr || !there.to_parking || there.move->path.back() != folded) continue;
    ++folds;
    INFO("robot " << there.robot << " folds in segment " << s);
    CHECK(folded != g.world.world->robots[static_cast<std::size_t>(there.robot)].home);
    CHECK_FALSE(there.held.has_value());
    // it goes on from there with the move it was parked before, and stands folded in between
    const ScheduleSegment& on = schedule.segments[s + 1];
    REQUIRE(on.robot == there.robot);
    REQUIRE(on.move != nullptr);
    CHECK(on.move->path.front() == folded);
    const Millis arrived = schedule.start[s] + there.duration;
    REQUIRE(schedule.start[s + 1] >= arrived);
    const double waiting = toSeconds(arrived + (schedule.start[s + 1] - arrived) / 2);
    CHECK(scheduledArm(graph, schedule, there.robot, waiting) == folded);
  }
  CHECK(folds >= 1);
}

TEST_CASE("the search below a folded robot has re-routes of its own and leaves the others theirs",
          "[planner][dash][shelf]") {
  // 6 shelf objects, world seed 2: round 1's first greedy task plan resolves. Folded children
  // come first in its search; the nodes below them have re-routes of their own, so they cannot
  // use up those the nodes without a fold need
  WorldGraph g(core::validateWorld(tools::generateShelving({6, 2})), 4);
  MotionHypergraph& graph = g.graph;
  const ConflictResult resolved = firstTaskPlanResolved(graph);
  CHECK_FALSE(firstConflict(graph, *resolved.schedule).has_value());
  CHECK(resolved.constraints > 0);
}
