// The search layers on hand-made instances: the test is the transition planner P_trans, giving
// each hyperarc samples of chosen motions and durations, so that the answers are known. The
// world supplies the robots, the object sites and the roadmaps that plan the move hyperarcs;
// each expected makespan is summed here from those moves' and samples' durations, apart from
// the search (one robot: its moves and transitions one after another).
//
//  - the A*-like query (nextBest, Alg. 4) returns every complete history in order of makespan,
//    the optimum first; the greedy query takes the earliest transition and misses it;
//  - MM-DaSH's Next-Best Search (Alg. 5) returns the optimum, Greedy-MM-DaSH the greedy plan;
//  - a grasp with no place is a dead end both queries back out of, and with no place at all
//    they exhaust the hypergraph and the planner calls the object never placeable;
//  - a handoff waits for its later tail vertex (the receiver still on its way);
//  - conflict resolution orders two robots reaching into one spot the way that ends sooner, and
//    the plan it writes is collision-free by the independent check.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "core/world_loader.h"
#include "planner/motion/motion_hypergraph.h"
#include "planner/plan_writer.h"
#include "planner/planning_rounds.h"
#include "planner/sampling/transition_planner.h"
#include "planner/sampling/transition_sampler.h"
#include "planner/scheduling/scheduled_cbs.h"
#include "planner/search/hyperpath_search.h"
#include "tests/planner/dash_test_support.h"
#include "tests/planner/plan_checks.h"

using namespace dashbed;
using namespace dashbed::planner;
using namespace dashbed::planner::testing;

namespace {

/// P_trans of a hand-made instance: the samples the test gives. Places are found by the grasp
/// they need; each handoff's samples are handed out once per giver grasp (the first round).
class HandMadeTransitions final : public TransitionPlanner {
 public:
  std::map<int, std::vector<TransitionSample>> picks, places, handoffs;  // by hyperarc

  std::vector<TransitionSample> pick(int hyperarc) override { return picks[hyperarc]; }
  std::vector<TransitionSample> place(int hyperarc, const Grasp& held) override {
    return withGraspBefore(places[hyperarc], held);
  }
  std::vector<TransitionSample> handoff(int hyperarc, const Grasp& giver_grasp, std::mt19937_64&, int) override {
    for (const Grasp& asked : handed_out_[hyperarc]) {
      if (sameGrasp(asked, giver_grasp)) return {};
    }
    handed_out_[hyperarc].push_back(giver_grasp);
    return withGraspBefore(handoffs[hyperarc], giver_grasp);
  }
  std::vector<Grasp> handoffGrasps(int object, const Grasp& giver) const override {
    std::vector<Grasp> grasps;
    for (const auto& [hyperarc, samples] : handoffs) {
      for (const TransitionSample& sample : samples) {
        if (sample.object == object && sameGrasp(*sample.grasp_before, giver)) grasps.push_back(*sample.grasp_after);
      }
    }
    return grasps;
  }

 private:
  static std::vector<TransitionSample> withGraspBefore(const std::vector<TransitionSample>& samples, const Grasp& g) {
    std::vector<TransitionSample> out;
    for (const TransitionSample& sample : samples) {
      if (sameGrasp(*sample.grasp_before, g)) out.push_back(sample);
    }
    return out;
  }
  std::map<int, std::vector<Grasp>> handed_out_;
};

/// A hand-made instance: a world of tests/planner/worlds/ with its task-space hypergraph, and
/// its motion hypergraph on the samples `make` gives.
struct Instance {
  core::LoadedWorld world;
  TaskSpaceHypergraph task_space;
  std::unique_ptr<MotionHypergraph> graph;
  /// [object] two grasps of it, from the geometric sampler's picks by its first picking robot
  /// (real grasps, which the roadmaps of a robot holding it can check)
  std::vector<std::vector<Grasp>> grasps;
  Grasp g1, g2;  ///< cube_0's

  explicit Instance(const std::string& name)
      : world(core::loadWorld(testWorldPath(name))),
        task_space(TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, world.reach)) {
    const CollisionScene scene(*world.world, *world.robots, RepresentationSettings{}.collision);
    const ObjectSites sites = objectSites(world);
    TransitionSampler sampler(world, task_space, scene, sites);
    grasps.resize(static_cast<std::size_t>(task_space.numObjects()));
    for (const TransitionHyperarc& arc : task_space.hyperarcs()) {
      std::vector<Grasp>& of = grasps[static_cast<std::size_t>(arc.object)];
      if (arc.kind != TransitionKind::kPick || !of.empty()) continue;
      for (const TransitionSample& pick : sampler.pick(hyperarc(TransitionKind::kPick, arc.robot, -1, arc.object))) {
        if (of.size() < 2) of.push_back(*pick.grasp_after);
      }
      REQUIRE(of.size() == 2);
    }
    g1 = grasps[0][0];
    g2 = grasps[0][1];
  }
  /// Builds the motion hypergraph on `transitions` (call once).
  void build(std::unique_ptr<HandMadeTransitions> transitions) {
    graph = std::make_unique<MotionHypergraph>(world, task_space, objectSites(world), 7, RepresentationSettings{},
                                               nullptr, std::move(transitions));
  }

  /// The task-space hyperarc of `kind` by `robot` (giver) of `object` (into its goal).
  int hyperarc(TransitionKind kind, int robot, int receiver = -1, int object = 0) const {
    for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
      const TransitionHyperarc& arc = task_space.hyperarcs()[h];
      if (arc.kind == kind && arc.robot == robot && arc.object == object && arc.receiver == receiver &&
          arc.rest_pose != RestPose::kAside) {
        return static_cast<int>(h);
      }
    }
    FAIL("no such hyperarc in " << world.world->name);
    return -1;
  }
  /// Robot r's home with its base joint turned by `angle` [rad]: free, and reached by a
  /// straight move.
  core::ArmConfig turned(int robot, double angle) const {
    core::ArmConfig q = world.world->robots[static_cast<std::size_t>(robot)].home;
    q[0] += angle;
    return q;
  }
  const core::ArmConfig& home(int robot) const { return world.world->robots[static_cast<std::size_t>(robot)].home; }

  /// A site set with the given sites occupied.
  SiteSet occupied(std::initializer_list<int> sites) const {
    SiteSet set(graph->sites().numSites());
    for (const int s : sites) set.set(s);
    return set;
  }
  /// Duration of the move hyperarc the search takes, of `robot` alone (grasp -1) or holding
  /// cube_0 in `grasp` (asserted planned).
  Millis move(int robot, int grasp, const core::ArmConfig& from, const core::ArmConfig& to, const SiteSet& occupied) {
    const Move* m = graph->move(robot, grasp < 0 ? -1 : 0, grasp, from, to, occupied);
    REQUIRE(m != nullptr);
    return m->duration;
  }
  /// The grasp id of cube_0's grasp `g` in the hypergraph (known once a sample holding it was added).
  int graspId(const Grasp& g) const {
    const std::vector<Grasp>& seen = graph->graspsOf(0);
    for (std::size_t i = 0; i < seen.size(); ++i) {
      if (sameGrasp(seen[i], g)) return static_cast<int>(i);
    }
    FAIL("grasp not seen");
    return -1;
  }
  /// Robot r's configuration with the TCP at p_W pointing down (the IK solution nearest home).
  core::ArmConfig reaching(int robot, const Eigen::Vector3d& p_W) const {
    core::Pose X_WT = core::Pose::Identity();
    X_WT.linear() = Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
    X_WT.translation() = p_W;
    const std::vector<core::ArmConfig> solutions = (*world.robots)[robot].solveInWorld(X_WT, home(robot));
    REQUIRE_FALSE(solutions.empty());
    return solutions.front();
  }
};

/// One robot's motion from `from` to `to` over `duration`: fingers at `finger`, holding cube_0
/// throughout when `held` (gripper commands are left out: the search does not read them).
TransitionMotion motion(int robot, const core::ArmConfig& from, const core::ArmConfig& to, Millis duration,
                        std::optional<HeldObject> held = std::nullopt) {
  TransitionMotion m;
  m.robot = robot;
  m.keys = {{0, from}, {duration, to}};
  m.finger = {held ? 0.02 : kFingersOpen};
  m.held = {held};
  return m;
}

TransitionSample sample(int hyperarc, TransitionKind kind, std::vector<TransitionMotion> motions, Millis duration,
                        std::optional<Grasp> before, std::optional<Grasp> after, int object = 0) {
  TransitionSample s;
  s.hyperarc = hyperarc;
  s.kind = kind;
  s.object = object;
  s.motions = std::move(motions);
  s.duration = duration;
  s.grasp_before = std::move(before);
  s.grasp_after = std::move(after);
  s.action_end = duration;
  return s;
}

HeldObject heldIn(const Grasp& g, int object = 0) { return {object, g.X_OT.inverse(), true}; }

/// One robot, one cube: two picks in grasps g1 and g2, two places for each grasp. The pick near
/// home (g1) starts first but is slow; the far one (g2) is fast. Each transition turns the base
/// by 0.05 rad from where it starts.
struct OneRobotInstance : Instance {
  struct Step {
    double at;  ///< base turn of the transition's start [rad]
    Millis duration;
  };
  static constexpr Step kPicks[2] = {{0.2, 4000}, {1.2, 1000}};                  // in g1, g2
  static constexpr Step kPlaces[2][2] = {{{0.6, 1000}, {-0.4, 1500}}, {{0.9, 1200}, {-0.9, 1100}}};  // [grasp]
  bool placeable[2];  ///< [grasp] its places are given

  explicit OneRobotInstance(bool place_g1 = true, bool place_g2 = true)
      : Instance("hand_made_1r_1c.yaml"), placeable{place_g1, place_g2} {
    auto transitions = std::make_unique<HandMadeTransitions>();
    const int pick = hyperarc(TransitionKind::kPick, 0), place = hyperarc(TransitionKind::kPlace, 0);
    for (int g = 0; g < 2; ++g) {
      const Grasp& grasp = g == 0 ? g1 : g2;
      const Step p = kPicks[g];
      transitions->picks[pick].push_back(sample(pick, TransitionKind::kPick,
                                                {motion(0, turned(0, p.at), turned(0, p.at + 0.05), p.duration, heldIn(grasp))},
                                                p.duration, std::nullopt, grasp));
      if (!placeable[g]) continue;
      for (const Step& q : kPlaces[g]) {
        transitions->places[place].push_back(sample(place, TransitionKind::kPlace,
                                                    {motion(0, turned(0, q.at), turned(0, q.at + 0.05), q.duration, heldIn(grasp))},
                                                    q.duration, grasp, std::nullopt));
      }
    }
    build(std::move(transitions));
  }

  /// The makespan of the history picking in grasp g (0, 1) and placing by its place k: move to
  /// the pick, pick, move holding the cube to the place, place, move home. Asks the hypergraph
  /// for the moves (after a search has seen the grasp).
  Millis makespan(int g, int k) {
    const int start = ObjectSites::startSite(0), goal = ObjectSites::goalSite(0);
    const Step p = kPicks[g], q = kPlaces[g][k];
    return move(0, -1, home(0), turned(0, p.at), occupied({start})) + p.duration +
           move(0, graspId(g == 0 ? g1 : g2), turned(0, p.at + 0.05), turned(0, q.at), occupied({})) + q.duration +
           move(0, -1, turned(0, q.at + 0.05), home(0), occupied({goal}));
  }
  /// Every complete history's makespan, sorted.
  std::vector<Millis> makespans() {
    std::vector<Millis> all;
    for (int g = 0; g < 2; ++g) {
      for (int k = 0; k < 2 && placeable[g]; ++k) all.push_back(makespan(g, k));
    }
    std::sort(all.begin(), all.end());
    return all;
  }
};

/// The sample of a history's step.
const TransitionSample& stepSample(const MotionHypergraph& graph, const TransitionHistory& h, std::size_t i) {
  REQUIRE(i < h.steps.size());
  return graph.transition(h.steps[i].transition).sample;
}

PlanningRounds::Clock::time_point never() { return PlanningRounds::Clock::time_point::max(); }

Millis plannedMakespan(MotionHypergraph& graph, Method method) {
  const PlannerSettings settings = testSettings(method);
  PlannerStats stats;
  PlanningRounds rounds(graph, settings, stats, never(), never(), {});
  rounds.run();
  REQUIRE(rounds.bestHistory());
  REQUIRE(rounds.bestSchedule());
  return rounds.bestMakespan();
}

}  // namespace

TEST_CASE("the A*-like query returns every complete history of a hand-made instance in order of makespan",
          "[search]") {
  OneRobotInstance instance;
  HyperpathSearch search(*instance.graph);
  SearchBudget budget;
  budget.max_expansions = 100;
  std::vector<Millis> found;
  for (int k = 0; k < 4; ++k) {
    const SearchResult next = search.nextBest(budget);
    REQUIRE(next.status == SearchStatus::kFound);
    REQUIRE(next.plan->steps.size() == 2);
    found.push_back(next.plan->makespan());
  }
  CHECK(search.nextBest(budget).status == SearchStatus::kExhausted);
  const std::vector<Millis> expected = instance.makespans();
  CHECK(found == expected);
  // the instance is one where the order matters: the optimum takes the pick that starts later
  CHECK(expected.front() < expected.back());
}

TEST_CASE("the greedy query takes the transition that starts first and misses the optimum the A*-like query finds",
          "[search]") {
  OneRobotInstance instance;
  const SearchResult greedy = HyperpathSearch(*instance.graph).greedy({});
  REQUIRE(greedy.status == SearchStatus::kFound);
  CHECK(stepSample(*instance.graph, *greedy.plan, 0).duration == 4000);  // the slow pick near home
  const SearchResult best = HyperpathSearch(*instance.graph).nextBest({});
  REQUIRE(best.status == SearchStatus::kFound);
  CHECK(stepSample(*instance.graph, *best.plan, 0).duration == 1000);
  const std::vector<Millis> expected = instance.makespans();
  CHECK(best.plan->makespan() == expected.front());
  CHECK(greedy.plan->makespan() > expected.front());
  // the greedy plan is one of the complete histories, the fastest through its pick
  CHECK(greedy.plan->makespan() == std::min(instance.makespan(0, 0), instance.makespan(0, 1)));
}

TEST_CASE("Next-Best Search (MM-DaSH) returns the optimum of a hand-made instance, Greedy-MM-DaSH the greedy plan",
          "[search]") {
  OneRobotInstance optimal;
  const Millis mm_dash = plannedMakespan(*optimal.graph, Method::kOptimal);
  OneRobotInstance greedy;
  const Millis greedy_dash = plannedMakespan(*greedy.graph, Method::kGreedy);
  const std::vector<Millis> expected = optimal.makespans();
  CHECK(mm_dash == expected.front());
  CHECK(greedy_dash > mm_dash);
  CHECK(greedy_dash == HyperpathSearch(*greedy.graph).greedy({}).plan->makespan());
}

TEST_CASE("a grasp without a place is a dead end the queries back out of", "[search]") {
  OneRobotInstance instance(/*place_g1=*/false, /*place_g2=*/true);
  const SearchResult greedy = HyperpathSearch(*instance.graph).greedy({});
  REQUIRE(greedy.status == SearchStatus::kFound);
  CHECK(stepSample(*instance.graph, *greedy.plan, 0).grasp_after->X_OT.isApprox(instance.g2.X_OT));
  const SearchResult best = HyperpathSearch(*instance.graph).nextBest({});
  REQUIRE(best.status == SearchStatus::kFound);
  CHECK(best.plan->makespan() == instance.makespans().front());
}

TEST_CASE("with no place for any grasp the queries exhaust the hypergraph and the object is never placeable",
          "[search]") {
  OneRobotInstance instance(/*place_g1=*/false, /*place_g2=*/false);
  SearchBudget budget;
  budget.max_expansions = 100;
  CHECK(HyperpathSearch(*instance.graph).greedy(budget).status == SearchStatus::kExhausted);
  CHECK(HyperpathSearch(*instance.graph).nextBest(budget).status == SearchStatus::kExhausted);
  CHECK(instance.graph->neverPlaceable(0));

  OneRobotInstance planned(false, false);
  PlannerSettings settings = testSettings();
  settings.max_rounds = 2;
  PlannerStats stats;
  PlanningRounds rounds(*planned.graph, settings, stats, never(), never(), {});
  rounds.run();
  CHECK_FALSE(rounds.bestHistory());
  CHECK_THAT(rounds.neverPlaceable(), Catch::Matchers::Contains("cube_0 can never be placed in bin_red"));
}

TEST_CASE("a handoff starts when the later of its tail vertices is reached: the receiver still on its way", "[search]") {
  Instance instance("hand_made_2r_1c.yaml");
  auto transitions = std::make_unique<HandMadeTransitions>();
  const int pick = instance.hyperarc(TransitionKind::kPick, 0);
  const int handoff = instance.hyperarc(TransitionKind::kHandoff, 0, 1);
  const int place = instance.hyperarc(TransitionKind::kPlace, 1);
  const Grasp g1 = instance.g1, g2 = instance.g2;
  transitions->picks[pick] = {sample(pick, TransitionKind::kPick,
                                     {motion(0, instance.turned(0, 0.2), instance.turned(0, 0.25), 500, heldIn(g1))},
                                     500, std::nullopt, g1)};
  // the giver is at the handoff's start soon after its pick; the receiver's start is a long
  // turn of its base away from home
  transitions->handoffs[handoff] = {
      sample(handoff, TransitionKind::kHandoff,
             {motion(0, instance.turned(0, 0.3), instance.turned(0, 0.35), 2000, heldIn(g1)),
              motion(1, instance.turned(1, 3.0), instance.turned(1, 3.05), 2000, heldIn(g2))},
             2000, g1, g2)};
  transitions->places[place] = {sample(place, TransitionKind::kPlace,
                                       {motion(1, instance.turned(1, 1.0), instance.turned(1, 1.05), 1000, heldIn(g2))},
                                       1000, g2, std::nullopt)};
  instance.build(std::move(transitions));

  const SearchResult found = HyperpathSearch(*instance.graph).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& h = *found.plan;
  REQUIRE(h.steps.size() == 3);
  const int start = ObjectSites::startSite(0), goal = ObjectSites::goalSite(0);
  const int grasp1 = instance.graspId(g1), grasp2 = instance.graspId(g2);
  const auto turned = [&](int robot, double angle) { return instance.turned(robot, angle); };
  const SiteSet none = instance.occupied({}), at_start = instance.occupied({start}), at_goal = instance.occupied({goal});
  const Millis to_pick = instance.move(0, -1, instance.home(0), turned(0, 0.2), at_start);
  const Millis giver_there = to_pick + 500 + instance.move(0, grasp1, turned(0, 0.25), turned(0, 0.3), none);
  const Millis receiver_there = instance.move(1, -1, instance.home(1), turned(1, 3.0), none);
  REQUIRE(receiver_there > giver_there);  // the instance: the receiver's tail vertex is the later one
  CHECK(h.steps[0].start == to_pick);
  CHECK(h.steps[1].start == receiver_there);
  CHECK(h.steps[2].start == receiver_there + 2000 + instance.move(1, grasp2, turned(1, 3.05), turned(1, 1.0), none));
  const Millis receiver_done = h.steps[2].start + 1000 + instance.move(1, -1, turned(1, 1.05), instance.home(1), at_goal);
  const Millis giver_done = receiver_there + 2000 + instance.move(0, -1, turned(0, 0.35), instance.home(0), at_goal);
  CHECK(h.makespan() == std::max(receiver_done, giver_done));
}

TEST_CASE("conflict resolution orders two robots reaching into one spot the way that ends sooner", "[search][conflict]") {
  Instance instance("hand_made_2r_2c.yaml");
  auto transitions = std::make_unique<HandMadeTransitions>();
  // each robot's pick reaches into the middle of the table one second after it starts, its TCP
  // where the other's goes, and is back out at 2 s; r0's pick ends then, r1's holds on to 8 s.
  // Their places take 1 s and 2.5 s.
  const core::ArmConfig mid0 = instance.reaching(0, {0.0, 0.0, 0.95}), mid1 = instance.reaching(1, {0.0, 0.0, 0.95});
  const core::ArmConfig out0 = instance.reaching(0, {-0.3, 0.0, 1.0}), out1 = instance.reaching(1, {0.3, 0.0, 1.0});
  const Millis pick_duration[2] = {2000, 8000}, place_duration[2] = {1000, 2500};
  for (int r = 0; r < 2; ++r) {
    const Grasp& g = instance.grasps[static_cast<std::size_t>(r)][0];
    const int pick = instance.hyperarc(TransitionKind::kPick, r, -1, r);
    const int place = instance.hyperarc(TransitionKind::kPlace, r, -1, r);
    TransitionMotion reach;
    reach.robot = r;
    reach.keys = {{0, r == 0 ? out0 : out1}, {1000, r == 0 ? mid0 : mid1}, {2000, r == 0 ? out0 : out1}};
    reach.finger = {0.02, 0.02};
    reach.held = {heldIn(g, r), heldIn(g, r)};
    transitions->picks[pick] = {sample(pick, TransitionKind::kPick, {reach}, pick_duration[r], std::nullopt, g, r)};
    transitions->places[place] = {sample(place, TransitionKind::kPlace,
                                         {motion(r, instance.turned(r, 0.4), instance.turned(r, 0.45), place_duration[r],
                                                 heldIn(g, r))},
                                         place_duration[r], g, std::nullopt, r)};
  }
  instance.build(std::move(transitions));
  const SearchResult found = HyperpathSearch(*instance.graph).greedy({});
  REQUIRE(found.status == SearchStatus::kFound);
  const TransitionHistory& history = *found.plan;

  // the optimistic schedule has both robots in the middle at once
  ConflictResolutionBudget root;
  root.max_nodes = 1;
  const ConflictResult unresolved = resolveConflicts(*instance.graph, history, root);
  REQUIRE(unresolved.status == ConflictStatus::kBudget);
  CHECK_THAT(unresolved.reason, Catch::Matchers::Contains("collide at t = "));

  ConflictResolutionBudget budget;
  budget.max_nodes = 200;
  const ConflictResult resolved = resolveConflicts(*instance.graph, history, budget);
  INFO(resolved.reason);
  REQUIRE(resolved.status == ConflictStatus::kResolved);
  const Schedule& schedule = *resolved.schedule;
  // The known answer: one pick waits until the other has ended (conflict resolution orders
  // whole items), the waiting robot standing where it was, so its timeline from there on is
  // delayed and nothing else changes. The order with the shorter makespan wins.
  std::map<int, Millis> start, end, done;  // robot -> its pick's start and end, its last motion's end
  for (const ScheduledTransition& step : history.steps) {
    const TransitionSample& s = instance.graph->transition(step.transition).sample;
    if (s.kind != TransitionKind::kPick) continue;
    start[s.motions[0].robot] = step.start;
    end[s.motions[0].robot] = step.start + s.duration;
  }
  for (int r = 0; r < 2; ++r) {
    const Move* home = history.final_moves[static_cast<std::size_t>(r)];
    done[r] = history.final_starts[static_cast<std::size_t>(r)] + (home != nullptr ? home->duration : 0);
  }
  REQUIRE(start.size() == 2);
  REQUIRE(std::max(start[0], start[1]) < std::min(end[0], end[1]));  // the picks overlap in time
  const Millis r0_first = std::max(done[0], done[1] + end[0] - start[1]);
  const Millis r1_first = std::max(done[0] + end[1] - start[0], done[1]);
  REQUIRE(r0_first != r1_first);
  CHECK(schedule.makespan == std::min(r0_first, r1_first));
  std::map<int, Millis> scheduled;  // robot -> its pick's start in the schedule
  for (std::size_t i = 0; i < schedule.segments.size(); ++i) {
    const ScheduleSegment& seg = schedule.segments[i];
    if (seg.motion == nullptr) continue;
    const TransitionSample& s = instance.graph->transition(history.steps.at(static_cast<std::size_t>(seg.step)).transition).sample;
    if (s.kind == TransitionKind::kPick) scheduled[seg.robot] = schedule.start[i];
  }
  const int first = r0_first < r1_first ? 0 : 1, second = 1 - first;
  CHECK(scheduled[first] == start[first]);
  CHECK(scheduled[second] == end[first]);
  // and judged apart from the planner, on the written plan
  requireNoCollision(writePlan(*instance.graph, history, schedule), instance.world);
}
