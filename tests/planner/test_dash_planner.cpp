// The DaSH planner end to end, with iteration caps (no wall-clock budgets): plans solve, are
// valid, are collision-free along the written timing (checked independently of the planner's
// own checks), are deterministic, and infeasible worlds say why.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <functional>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/trajectory_interpolator.h"
#include "core/plan.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "planner/dash_planner.h"
#include "planner/search/hyperpath_search.h"
#include "planner/motion/hypergraph_dot.h"
#include "tests/planner/dash_test_support.h"
#include "tests/planner/plan_checks.h"

using namespace dashbed;
using namespace dashbed::planner;
using namespace dashbed::planner::testing;
using Catch::Matchers::Contains;

namespace {

/// A world loaded without the reachability check, so that the planner has to find out.
core::LoadedWorld unchecked(core::World world) {
  core::LoadedWorld loaded;
  loaded.world = std::make_unique<const core::World>(std::move(world));
  loaded.robots = std::make_unique<const core::RobotSet>(*loaded.world);
  loaded.reach = core::computeReach(*loaded.world, *loaded.robots);
  return loaded;
}

}  // namespace

TEST_CASE("greedy DaSH plans the default world into valid collision-free chains", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const PlanResult result = solve(world, testSettings());
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  const core::Plan& plan = *result.plan;
  core::checkPlanStructure(plan, "plan");
  requireValidActions(plan, *world.world);
  // 4 cubes that all need a handoff (cross starts): 4 picks, 4 handoffs, 4 places
  CHECK(plan.actions.size() == 12);
  requireMovesStartAtRest(plan);
  requireNoCollision(plan, world);
  CHECK(result.stats.makespan > 0.0);
  CHECK(result.stats.makespan == Approx(plan.duration()).margin(1e-9));
  CHECK(plan.statistics.at("status") == "solved");
  // the two robots hand the cubes over side by side: no fallback to one object at a time
  CHECK_FALSE(result.stats.sequential);
  CHECK(plan.statistics.at("sequential") == false);
}

TEST_CASE("the same seed gives a byte-identical plan", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const PlanResult a = solve(world, testSettings());
  // the second with a progress log, which must not change the plan
  std::vector<std::string> progress;
  PlannerBudget budget;
  budget.progress = [&](const std::string& line) { progress.push_back(line); };
  const PlanResult b = solve(world, testSettings(), budget);
  REQUIRE(a.plan);
  REQUIRE(b.plan);
  CHECK(core::writePlanJson(*a.plan) == core::writePlanJson(*b.plan));
  std::ostringstream makespan;
  makespan << std::fixed << std::setprecision(2) << b.stats.makespan << " s";
  REQUIRE(progress.size() >= 4);
  CHECK_THAT(progress[0], Contains("round 1: "));
  CHECK_THAT(progress[1], Contains("greedy query"));
  CHECK_THAT(progress[2], Contains("found a task plan after"));
  CHECK_THAT(progress.back(), Contains("conflict resolution: makespan " + makespan.str()));
}

TEST_CASE("direct queries that use up their share of the time leave the rest to the sequential one",
          "[planner][dash]") {
  // the default world has a direct plan (above); with no time for the direct queries, round 1
  // still ends with a plan, its sequential one. The deadline itself is never reached.
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  PlannerSettings settings = testSettings();
  settings.max_rounds = 1;
  settings.direct_time_share = 1e-9;
  std::vector<std::string> progress;
  PlannerBudget budget;
  budget.deadline = std::chrono::steady_clock::now() + std::chrono::hours(1);
  budget.progress = [&](const std::string& line) { progress.push_back(line); };
  const PlanResult result = solve(world, settings, budget);
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  CHECK(result.stats.sequential);
  requireValidActions(*result.plan, *world.world);
  requireNoCollision(*result.plan, world);
  REQUIRE(progress.size() >= 2);
  CHECK_THAT(progress[1], Contains("the direct queries used their share of the time budget"));
  CHECK(std::none_of(progress.begin(), progress.end(),
                     [](const std::string& line) { return line.find("greedy query, 0") == 0; }));

  settings.direct_time_share = 0.0;
  REQUIRE_THROWS_WITH(solve(world, settings), Contains("direct_time_share: must be in (0, 1]"));
}

TEST_CASE("a cube no robot can reach makes the problem infeasible and is named", "[planner][dash]") {
  core::World world = core::loadWorldFile(worldPath("default.yaml"));
  world.objects[2].X_WO.translation() = Eigen::Vector3d(0.0, 2.5, 0.775);
  const core::LoadedWorld loaded = unchecked(std::move(world));
  const PlanResult result = solve(loaded, testSettings());
  CHECK(result.status == PlannerStatus::kInfeasible);
  CHECK_THAT(result.reason, Contains(loaded.world->objects[2].name));
  CHECK_FALSE(result.plan);
}

TEST_CASE("a robot colliding at home is a world error naming the file, line and robot", "[planner][dash]") {
  core::World world = core::loadWorldFile(worldPath("default.yaml"));
  std::string field;
  std::string what;
  SECTION("with the table") {
    world.robots[1].home[1] = 0.6;  // shoulder lifted below the horizontal: the gripper down in the table top
    field = "robots[1].home: robot '" + world.robots[1].name + "'";
    what = "collides at its home configuration (gripper open): its hande_right_finger and fixture 'table'";
  }
  SECTION("with another robot") {
    // facing r0 0.7 m away (its pedestal clear of r0's): the forearms, reaching forward at home, cross
    world.robots[1].X_WBase.translation() = world.robots[0].X_WBase.translation() + Eigen::Vector3d(0.7, 0.0, 0.0);
    field = "robots[1].home: robot '" + world.robots[1].name + "'";
    what = "collides with robot '" + world.robots[0].name + "' when both stand at their home configurations: its " +
           "forearm_link and robot '" + world.robots[0].name + "''s forearm_link";
  }
  const core::LoadedWorld loaded = unchecked(std::move(world));
  const auto location = "default.yaml:" + std::to_string(loaded.world->robots[1].where.line) + ":";
  CHECK_THROWS_AS(solve(loaded, testSettings()), core::WorldError);
  CHECK_THROWS_WITH(solve(loaded, testSettings()), Contains(location) && Contains(field) && Contains(what));
}

TEST_CASE("planner settings out of range are refused before any planning and named", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  using Spoil = std::function<void(PlannerSettings&)>;
  const std::vector<std::pair<std::string, Spoil>> out_of_range = {
      {"max_rounds", [](PlannerSettings& s) { s.max_rounds = 0; }},
      {"sequential_fallback_rounds", [](PlannerSettings& s) { s.sequential_fallback_rounds = -1; }},
      {"conflict_focal_weight", [](PlannerSettings& s) { s.conflict_focal_weight = 0.9; }},
      {"conflict_nodes", [](PlannerSettings& s) { s.conflict_nodes = 0; }},
      {"conflict_nodes_along_time", [](PlannerSettings& s) { s.conflict_nodes_along_time = 0; }},
      {"conflict_nodes_depth_first", [](PlannerSettings& s) { s.conflict_nodes_depth_first = 0; }},
      {"conflict_reroutes_retry", [](PlannerSettings& s) { s.conflict_reroutes_retry = -1; }},
      {"direct_time_share", [](PlannerSettings& s) { s.direct_time_share = 0.0; }},
  };
  for (const auto& [field, spoil] : out_of_range) {
    INFO(field);
    PlannerSettings settings = testSettings();
    spoil(settings);
    CHECK_THROWS_AS(solve(world, settings), std::invalid_argument);
    CHECK_THROWS_WITH(solve(world, settings), Contains("planner settings: ") && Contains(field));
  }
}

TEST_CASE("an object no grasp can ever place makes the problem infeasible and is named", "[planner][dash]") {
  // a 40 mm cube sent to a shelf slot: a slot takes objects slid in from the side, and a side
  // grasp of the cube on the table runs into the table
  const core::LoadedWorld world = core::loadWorld(testWorldPath("cube_to_shelf_slot.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  CHECK(graph.neverPlaceable(0));
  CHECK(graph.numTransitions() == graph.transitionsOf(0, -1).size());  // the picks only: nothing added

  const PlanResult result = solve(world, testSettings());
  CHECK(result.status == PlannerStatus::kInfeasible);
  CHECK_THAT(result.reason, Contains("cube_a can never be placed in slot_a"));
  CHECK(result.stats.rounds == 1);
  CHECK_FALSE(result.plan);
}

TEST_CASE("a box only one robot can hold, and only another can place, makes the problem infeasible",
          "[planner][dash]") {
  // r1 picks the box by its only narrow face pair; a handoff would give r0 another pair. Once r0
  // has placed the cube, the box has place samples (for r1's grasps), but no task plan exists
  const core::LoadedWorld world = core::loadWorld(testWorldPath("flat_box_handoff.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  std::set<int> pickers;  // robots with a pick sample of the box
  for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = task_space.hyperarcs()[h];
    if (arc.kind == TransitionKind::kPick && arc.object == 0 && !graph.transitionsOf(static_cast<int>(h), -1).empty()) {
      pickers.insert(arc.robot);
    }
  }
  REQUIRE(pickers == std::set<int>{1});
  CHECK(graph.neverPlaceable(0));
  CHECK_FALSE(graph.neverPlaceable(1));  // the cube r0 picks and places itself

  const PlanResult result = solve(world, testSettings());
  CHECK(result.status == PlannerStatus::kInfeasible);
  CHECK_THAT(result.reason, Contains("box_0 can never be placed in bin_a"));
  CHECK(result.stats.rounds == 1);
}

TEST_CASE("objects the default and shelving worlds place are not proven never placeable", "[planner][dash]") {
  for (const char* name : {"default.yaml", "shelf_2r_4o.yaml"}) {
    const core::LoadedWorld world = core::loadWorld(worldPath(name));
    const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
    MotionHypergraph graph(world, task_space, 7);
    for (int o = 0; o < task_space.numObjects(); ++o) {
      INFO(name << ": " << world.world->objects[static_cast<std::size_t>(o)].name);
      CHECK_FALSE(graph.neverPlaceable(o));
    }
  }
}

TEST_CASE("a cube too small or too large to be handed over makes the problem infeasible", "[planner][dash]") {
  // 30 mm: the receiver's 29.2 mm wide pads do not fit between the giver's fingers; 45 mm: the
  // receiver's open fingers (50 mm) leave 2.5 mm beside it, less than the checker's margins
  const double side = GENERATE(0.030, 0.045);
  INFO("cube side " << side << " m");
  core::World world = core::loadWorldFile(testWorldPath("handoff_too_wide.yaml"));
  world.objects[0].size = Eigen::Vector3d::Constant(side);
  world.objects[0].X_WO.translation().z() = 0.75 + side / 2;  // on the table
  const core::LoadedWorld loaded = unchecked(std::move(world));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*loaded.world, *loaded.robots, loaded.reach);
  MotionHypergraph graph(loaded, task_space, 7);
  const TransitionSampler sampler(loaded, task_space, graph.scene(), graph.sites(), {});
  std::size_t picks = 0;
  for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
    if (task_space.hyperarcs()[h].kind != TransitionKind::kPick) continue;
    for (const int t : graph.transitionsOf(static_cast<int>(h), -1)) {
      ++picks;
      CHECK(sampler.handoffGrasps(0, *graph.transition(t).sample.grasp_after).empty());
    }
  }
  REQUIRE(picks > 0);
  CHECK(graph.neverPlaceable(0));

  const PlanResult result = solve(loaded, testSettings());
  CHECK(result.status == PlannerStatus::kInfeasible);
  CHECK_THAT(result.reason, Contains("cube_0 can never be placed in bin_red"));
  CHECK(result.stats.rounds == 1);
}

TEST_CASE("a timeout without any task plan says how far the search got and names the transitions never sampled",
          "[planner][dash]") {
  // a 40 mm cube can be handed over, but not at handoff heights out of either arm's reach
  core::World world = core::loadWorldFile(testWorldPath("handoff_too_wide.yaml"));
  world.objects[0].size = Eigen::Vector3d::Constant(0.040);
  world.objects[0].X_WO.translation().z() = 0.75 + 0.020;
  const core::LoadedWorld loaded = unchecked(std::move(world));
  PlannerSettings settings = testSettings();
  settings.max_rounds = 3;
  settings.representation.transitions.handoff.min_height = 1.5;
  settings.representation.transitions.handoff.max_height = 1.6;
  const PlanResult result = solve(loaded, settings);
  CHECK(result.status == PlannerStatus::kTimeout);
  // a pick of cube_0 would leave its robot no way to pass it on: the search never takes one
  CHECK_THAT(result.reason, Contains("no task plan in the representation") &&
                                Contains("the furthest task plan tried placed 0 of 1 objects, not cube_0 (at its start)") &&
                                Contains("never sampled: handoff cube_0 by r1 to r0"));
  CHECK_FALSE(result.plan);
}

TEST_CASE("an object in the way of another's every pick is set aside and picked up again", "[planner][dash]") {
  // one robot: green goes in behind blue, and every pick of green reaches over blue. The spot
  // nearest blue's start is passed over by every pick of green as well
  PlannerSettings settings = testSettings();
  settings.max_rounds = 20;
  const core::LoadedWorld world = core::loadWorld(worldPath("handwritten/x6_one_hand_set_aside.yaml"));
  const PlanResult result = solve(world, settings);
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  const core::Plan& plan = *result.plan;
  core::checkPlanStructure(plan, "plan");
  requireValidActions(plan, *world.world);
  requireMovesStartAtRest(plan);
  CHECK(plan.statistics.at("set_aside_sites") == 1);
  std::vector<std::string> order;  // "pick blue", "set aside blue", ...
  for (const core::PlanAction& action : plan.actions) {
    const bool aside = action.type == core::ActionType::kPlace && action.region.empty();
    order.push_back(std::string(aside ? "set aside" : action.type == core::ActionType::kPick ? "pick" : "place") + " " +
                    action.object);
  }
  CHECK(order == std::vector<std::string>{"pick blue", "set aside blue", "pick green", "place green", "pick blue",
                                          "place blue"});
}

TEST_CASE("a transition touches a resting object where its sample touches that object's site", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("handwritten/x6_one_hand_set_aside.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  const int green = 0, blue = 1;
  core::Pose far = graph.sites().start[blue];  // on the table behind the robot
  far.translation().x() = -0.6;
  int picks = 0;
  for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = task_space.hyperarcs()[h];
    if (arc.kind != TransitionKind::kPick || arc.object != green) continue;
    for (const int id : graph.transitionsOf(static_cast<int>(h), -1)) {
      const TransitionSample& sample = graph.transition(id).sample;
      CHECK(sample.touches.test(ObjectSites::startSite(blue)));  // x6: every pick of green passes over blue
      CHECK(graph.touches(id, {blue, graph.sites().start[blue]}));
      CHECK_FALSE(graph.touches(id, {blue, far}));
      ++picks;
    }
  }
  CHECK(picks > 0);
}

TEST_CASE("a timeout without any task plan names the picks that pass over other objects", "[planner][dash]") {
  PlannerSettings settings = testSettings();
  settings.max_rounds = 2;
  settings.set_aside = false;  // nothing set down anywhere but at its goal
  const PlanResult result = solve(core::loadWorld(worldPath("handwritten/x6_one_hand_set_aside.yaml")), settings);
  CHECK(result.status == PlannerStatus::kTimeout);
  CHECK_THAT(result.reason, Contains("no task plan in the representation; every pick of green passes over "
                                     "blue at its start"));
  CHECK_THAT(result.reason, !Contains("every pick of blue"));
  // blue goes into the slot in front of green's, which nothing can pick meanwhile: both stay
  CHECK_THAT(result.reason, Contains("placed 0 of 2 objects, not green (at its start), blue (at its start)"));
  CHECK_FALSE(result.plan);
}

TEST_CASE("the motion hypergraph's DOT shows its vertex map and transitions", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 1);
  std::size_t picks = 0;
  for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
    if (task_space.hyperarcs()[h].kind == TransitionKind::kPick) picks += graph.transitionsOf(static_cast<int>(h), -1).size();
  }
  REQUIRE(picks == graph.numTransitions());
  std::ostringstream out;
  writeMotionDot(out, graph);
  const std::string dot = out.str();
  std::size_t arcs = 0, clusters = 0;
  for (std::size_t at = dot.find(" -> t"); at != std::string::npos; at = dot.find(" -> t", at + 1)) {
    if (std::isdigit(static_cast<unsigned char>(dot[at + 5])) != 0) ++arcs;  // not "-> target"
  }
  for (std::size_t at = dot.find("subgraph"); at != std::string::npos; at = dot.find("subgraph", at + 1)) ++clusters;
  CHECK(arcs == 2 * picks);  // a pick's tail: the robot and the object
  // every robot alone, every object resting, and the robot-holding elements the picks reach
  std::set<int> task_vertices;
  for (std::size_t v = 0; v < graph.numVertices(); ++v) task_vertices.insert(graph.vertex(static_cast<int>(v)).task_vertex);
  CHECK(clusters == task_vertices.size());
  CHECK_THAT(dot, Contains("source ->") && Contains("-> target"));
}

TEST_CASE("a scheduling constraint keeps its pair of transitions out of later task plans", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  const SearchResult first = HyperpathSearch(graph).greedy({});
  REQUIRE(first.status == SearchStatus::kFound);
  // the first transitions of the two robots (both pick at the start of the default world)
  std::map<int, int> first_of;  // robot -> transition
  for (const ScheduledTransition& step : first.plan->steps) {
    const TransitionSample& sample = graph.transition(step.transition).sample;
    if (sample.kind == TransitionKind::kPick) first_of.emplace(sample.motions[0].robot, step.transition);
  }
  REQUIRE(first_of.size() == 2);
  const int a = first_of.begin()->second, b = first_of.rbegin()->second;
  CHECK(graph.addSchedulingConstraint(a, b));
  CHECK_FALSE(graph.addSchedulingConstraint(b, a));  // one pair, either order
  CHECK(graph.schedulingConflict(b, a));

  const SearchResult second = HyperpathSearch(graph).greedy({});
  REQUIRE(second.status == SearchStatus::kFound);
  std::set<int> used;
  for (const ScheduledTransition& step : second.plan->steps) used.insert(step.transition);
  CHECK_FALSE((used.count(a) == 1 && used.count(b) == 1));

  graph.clearSchedulingConstraints();
  CHECK_FALSE(graph.schedulingConflict(a, b));
}

TEST_CASE("a second scheduling constraint on the same two hyperarcs constrains all their samples", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  // two pick hyperarcs of different robots with at least two samples each
  std::vector<std::vector<int>> picks;  // samples of each chosen hyperarc
  std::set<int> robots;
  for (std::size_t h = 0; h < task_space.numHyperarcs() && picks.size() < 2; ++h) {
    const TransitionHyperarc& arc = task_space.hyperarcs()[h];
    if (arc.kind != TransitionKind::kPick || robots.count(arc.robot) == 1) continue;
    const std::vector<int>& samples = graph.transitionsOf(static_cast<int>(h), -1);
    if (samples.size() < 2) continue;
    picks.push_back(samples);
    robots.insert(arc.robot);
  }
  REQUIRE(picks.size() == 2);
  const std::vector<int>& a = picks[0];
  const std::vector<int>& b = picks[1];
  REQUIRE(graph.addSchedulingConstraint(a[0], b[0]));
  CHECK(graph.schedulingConflict(a[0], b[0]));
  CHECK_FALSE(graph.schedulingConflict(a[1], b[1]));  // one pair: those samples only
  REQUIRE(graph.addSchedulingConstraint(a[1], b[0]));
  CHECK(graph.schedulingConflict(a[1], b[1]));  // two pairs: every sample of the two hyperarcs
  CHECK(graph.schedulingConflict(b[1], a[0]));
  CHECK_FALSE(graph.schedulingConflict(a[0], a[1]));  // not within a hyperarc
  CHECK(graph.numSchedulingConstraints() == 2);
  graph.clearSchedulingConstraints();
  CHECK_FALSE(graph.schedulingConflict(a[1], b[1]));
  REQUIRE(graph.addSchedulingConstraint(a[1], b[1]));  // counting starts again
  CHECK_FALSE(graph.schedulingConflict(a[0], b[0]));
}

TEST_CASE("a pick that runs into a robot standing at home is planned around with a handoff", "[planner][dash]") {
  // only r1 reaches the bin, but r1 picking the cube runs into r0's gripper at home
  const core::LoadedWorld world = core::loadWorld(testWorldPath("idle_home_block.yaml"));
  const PlanResult result = solve(world, testSettings());
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  CHECK(result.stats.scheduling_constraints >= 1);
  const core::Plan& plan = *result.plan;
  requireValidActions(plan, *world.world);
  requireNoCollision(plan, world);
  REQUIRE(plan.actions.size() == 3);
  CHECK(plan.actions[0].type == core::ActionType::kPick);
  CHECK(plan.actions[0].robot == "r0");
  CHECK(plan.actions[1].type == core::ActionType::kHandoff);
}

TEST_CASE("robots hand over where their handoff zone moved: before a post, beside a riser", "[planner][dash]") {
  // the midpoint of the bases is inside a post between side-by-side robots / out of reach of a
  // robot on the table when the other stands on a 0.5 m riser
  const auto [file, cubes] = GENERATE(std::pair{"post_between.yaml", 2}, std::pair{"riser_handoff.yaml", 4});
  const core::LoadedWorld world = core::loadWorld(testWorldPath(file));
  const PlanResult result = solve(world, testSettings());
  INFO(file << ": " << result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  const core::Plan& plan = *result.plan;
  requireValidActions(plan, *world.world);
  requireNoCollision(plan, world);
  // every cube starts on the far side from its bin
  const auto handoffs = std::count_if(plan.actions.begin(), plan.actions.end(), [](const core::PlanAction& a) {
    return a.type == core::ActionType::kHandoff;
  });
  CHECK(handoffs == cubes);
}

TEST_CASE("a robot standing at home over the only pick another robot can make folds out of its way", "[planner][dash]") {
  // the 38 mm cube cannot be handed over and only r1 places it; r0 at home stands over it
  const core::LoadedWorld world = core::loadWorld(testWorldPath("idle_home_fold.yaml"));
  const PlanResult result = solve(world, testSettings());
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  const core::Plan& plan = *result.plan;
  requireValidActions(plan, *world.world);
  requireNoCollision(plan, world);
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[0].robot == "r1");
  CHECK(plan.actions[1].robot == "r1");
  // folding the idle robot away is what a sequential plan does
  CHECK(result.stats.sequential);
  CHECK(plan.statistics.at("sequential") == true);
  // r0 leaves home only to fold, and stands folded (upper arm leaning back) while r1 picks
  const core::RobotTrajectory& r0 = plan.trajectories[0];
  const double pick = plan.actions[0].end;
  const auto at = [&](double t) {
    return std::find_if(r0.points.begin(), r0.points.end(), [&](const core::TrajectoryPoint& p) { return p.t >= t; });
  };
  REQUIRE(at(pick) != r0.points.end());
  CHECK(at(pick)->q[1] < world.world->robots[0].home[1] - 0.5);
  CHECK(r0.points.back().q == world.world->robots[0].home);
}

TEST_CASE("a goal slot only a robot missing the region's centre reaches is placed by that robot", "[planner][dash]") {
  // r1 reaches the bin's centre, r0 only the slot the cube is given: the place is r0's
  const core::LoadedWorld world = core::loadWorld(testWorldPath("slot_off_centre_reach.yaml"));
  const PlanResult result = solve(world, testSettings());
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  const core::Plan& plan = *result.plan;
  requireValidActions(plan, *world.world);
  requireNoCollision(plan, world);
  REQUIRE_FALSE(plan.actions.empty());
  CHECK(plan.actions.back().type == core::ActionType::kPlace);
  CHECK(plan.actions.back().robot == "r0");
}

TEST_CASE("a bin whose centre is out of reach gets its objects in its near part", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(testWorldPath("bin_centre_out_of_reach.yaml"));
  const PlanResult result = solve(world, testSettings());
  INFO(result.reason);
  REQUIRE(result.status == PlannerStatus::kSolved);
  requireValidActions(*result.plan, *world.world);
  int places = 0;
  for (const core::PlanAction& action : result.plan->actions) places += action.type == core::ActionType::kPlace;
  CHECK(places == 2);
}

TEST_CASE("a home constraint keeps its transition out while the robot stands at home", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(testWorldPath("idle_home_block.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  const SearchResult first = HyperpathSearch(graph).greedy({});
  REQUIRE(first.status == SearchStatus::kFound);
  const int pick = first.plan->steps.front().transition;
  const int picker = graph.transition(pick).sample.motions[0].robot;
  const int other = 1 - picker;
  REQUIRE(graph.addHomeConstraint(pick, other));
  CHECK_FALSE(graph.addHomeConstraint(pick, other));
  CHECK(graph.homeConflict(pick, other));
  CHECK_FALSE(graph.homeConflict(pick, picker));
  CHECK(graph.numSchedulingConstraints() == 1);

  // the next plan does not start with that pick while the other robot is still at home
  const SearchResult second = HyperpathSearch(graph).greedy({});
  REQUIRE(second.status == SearchStatus::kFound);
  bool other_acted = false;
  for (const ScheduledTransition& step : second.plan->steps) {
    const TransitionSample& sample = graph.transition(step.transition).sample;
    if (step.transition == pick) CHECK(other_acted);
    for (const TransitionMotion& motion : sample.motions) other_acted = other_acted || motion.robot == other;
  }
  graph.clearSchedulingConstraints();
  CHECK_FALSE(graph.homeConflict(pick, other));
  CHECK(graph.numSchedulingConstraints() == 0);
}

TEST_CASE("a place its robot cannot get home from counts as no place: the object is handed over", "[planner][dash][long]") {
  // r0 reaches the slots right in front of it only in poses its roadmap cannot bring home
  const core::LoadedWorld world = core::loadWorld(testWorldPath("shelf_front_slots.yaml"));
  const TaskSpaceHypergraph task_space = TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach);
  MotionHypergraph graph(world, task_space, 7);
  SearchResult result = HyperpathSearch(graph).greedy({});
  while (result.status != SearchStatus::kFound && graph.rounds() < 8) {
    graph.expand();
    result = HyperpathSearch(graph).greedy({});
  }
  INFO("rounds: " << graph.rounds());
  REQUIRE(result.status == SearchStatus::kFound);
  int places = 0, handoffs = 0;
  for (const ScheduledTransition& step : result.plan->steps) {
    const TransitionSample& sample = graph.transition(step.transition).sample;
    if (sample.kind == TransitionKind::kHandoff) ++handoffs;
    if (sample.kind != TransitionKind::kPlace) continue;
    ++places;
    CHECK(world.world->robots[static_cast<std::size_t>(sample.motions[0].robot)].name == "r1");
  }
  CHECK(places == 2);
  CHECK(handoffs == 1);
}

TEST_CASE("a constrained greedy query may look twice as far every round, up to the query budget", "[planner][dash]") {
  PlannerSettings settings;
  settings.constrained_search_expansions = 1000;
  settings.search_expansions = 20000;
  CHECK(constrainedSearchExpansions(settings, 1, 0) == 1000);
  CHECK(constrainedSearchExpansions(settings, 2, 0) == 2000);
  CHECK(constrainedSearchExpansions(settings, 4, 0) == 8000);
  CHECK(constrainedSearchExpansions(settings, 5, 0) == 16000);
  CHECK(constrainedSearchExpansions(settings, 6, 0) == 20000);
  CHECK(constrainedSearchExpansions(settings, 1000, 0) == 20000);
  // twice what the last unconstrained query took, when more
  CHECK(constrainedSearchExpansions(settings, 1, 3000) == 6000);
  CHECK(constrainedSearchExpansions(settings, 3, 3000) == 6000);
  CHECK(constrainedSearchExpansions(settings, 1, 15000) == 20000);
}

TEST_CASE("a greedy query keeping clear of the robots at home looks as far as a constrained one", "[planner][dash]") {
  PlannerSettings settings;
  settings.constrained_search_expansions = 1000;
  settings.search_expansions = 20000;
  for (const QueryMode mode : {QueryMode::kDirect, QueryMode::kParkAtHome}) {
    CHECK(greedySearchExpansions(settings, mode, false, 1, 30) == 20000);
    CHECK(greedySearchExpansions(settings, mode, true, 1, 30) == 1000);
  }
  for (const QueryMode mode : {QueryMode::kParkClearOfHomes, QueryMode::kSequential, QueryMode::kSequentialFolded}) {
    CHECK(greedySearchExpansions(settings, mode, false, 1, 30) == 1000);
    CHECK(greedySearchExpansions(settings, mode, false, 3, 30) == 4000);
    CHECK(greedySearchExpansions(settings, mode, true, 2, 3000) == 6000);
  }
}

TEST_CASE("a focal weight below 1 is refused", "[planner][dash]") {
  const core::LoadedWorld world = core::loadWorld(worldPath("default.yaml"));
  PlannerSettings settings;
  settings.conflict_focal_weight = 0.9;
  REQUIRE_THROWS_WITH(solve(world, settings), Catch::Matchers::Contains("conflict_focal_weight: must be >= 1"));
}
