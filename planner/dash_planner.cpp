#include "planner/dash_planner.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "planner/collision/home_check.h"
#include "planner/search/hyperpath_search.h"
#include "planner/plan_writer.h"
#include "planner/planner_text.h"
#include "planner/planning_rounds.h"

namespace dashbed::planner {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Every pick sample of `object`, by any robot (picks are enumerated, not drawn: more rounds
/// never add one).
std::vector<int> pickTransitionsOf(MotionHypergraph& graph, int object) {
  const TaskSpaceHypergraph& task_space = graph.taskSpace();
  std::vector<int> picks;
  for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = task_space.hyperarcs()[h];
    if (arc.object != object || arc.kind != TransitionKind::kPick || arc.rest_pose != RestPose::kStart) continue;
    const std::vector<int>& ids = graph.transitionsOf(static_cast<int>(h), -1);
    picks.insert(picks.end(), ids.begin(), ids.end());
  }
  return picks;
}

/// An object with a goal that no robot picks without touching the start sites of `others`.
struct CrowdedPick {
  int object = -1;
  std::vector<int> others;
};

/// The objects with a goal whose every pick sample (start sites only) touches some other
/// objects' start sites, with those objects. Such a pick waits until the others have been
/// picked up; where those must wait for it in turn (a front slot for its back one), one of them
/// has to be set aside meanwhile.
std::vector<CrowdedPick> crowdedPicks(MotionHypergraph& graph) {
  const TaskSpaceHypergraph& task_space = graph.taskSpace();
  std::vector<CrowdedPick> crowded;
  for (int o = 0; o < task_space.numObjects(); ++o) {
    if (!graph.sites().goal[static_cast<std::size_t>(o)]) continue;
    const std::vector<int> picks = pickTransitionsOf(graph, o);
    CrowdedPick pick{o, {}};
    for (int other = 0; other < task_space.numObjects() && !picks.empty(); ++other) {
      const int site = ObjectSites::startSite(other);
      if (std::all_of(picks.begin(), picks.end(), [&](int id) { return graph.transition(id).sample.touches.test(site); })) {
        pick.others.push_back(other);
      }
    }
    if (!pick.others.empty()) crowded.push_back(std::move(pick));
  }
  return crowded;
}

/// "; every pick of green_3 passes over blue_0 and blue_3 at their starts": crowdedPicks, at
/// most `limit` objects.
std::string crowdedPicksText(MotionHypergraph& graph, std::size_t limit) {
  const core::World& world = *graph.world().world;
  std::vector<std::string> lines;
  for (const CrowdedPick& pick : crowdedPicks(graph)) {
    lines.push_back("every pick of " + world.objects[static_cast<std::size_t>(pick.object)].name + " passes over " +
                    objectList(world, pick.others) + " at " + (pick.others.size() == 1 ? "its start" : "their starts"));
  }
  return lines.empty() ? "" : "; " + firstFew(lines, limit, "; ", " objects");
}

/// The objects some other object's every pick passes over (crowdedPicks), in id order.
std::vector<int> objectsInTheWay(const std::vector<CrowdedPick>& crowded) {
  std::vector<int> in_the_way;
  for (const CrowdedPick& pick : crowded) in_the_way.insert(in_the_way.end(), pick.others.begin(), pick.others.end());
  std::sort(in_the_way.begin(), in_the_way.end());
  in_the_way.erase(std::unique(in_the_way.begin(), in_the_way.end()), in_the_way.end());
  return in_the_way;
}

/// Whether `object` set aside at X_WO leaves some pick of each of `crowded`'s objects it is in
/// the way of clear (one at its start and set aside there would still be in the way).
bool asideKeepsClear(MotionHypergraph& graph, const std::vector<CrowdedPick>& crowded, int object, const core::Pose& X_WO) {
  return std::all_of(crowded.begin(), crowded.end(), [&](const CrowdedPick& pick) {
    if (std::find(pick.others.begin(), pick.others.end(), object) == pick.others.end()) return true;
    const std::vector<int> picks = pickTransitionsOf(graph, pick.object);
    return std::any_of(picks.begin(), picks.end(), [&](int id) { return !graph.touches(id, {object, X_WO}); });
  });
}

/// [object] the robots reaching its set-aside site (none without one).
std::vector<std::vector<int>> setAsideReach(const core::LoadedWorld& world, const ObjectSites& sites) {
  std::vector<std::vector<int>> reach(sites.aside.size());
  for (std::size_t o = 0; o < sites.aside.size(); ++o) {
    for (std::size_t r = 0; r < world.robots->size() && sites.aside[o]; ++r) {
      if (core::reachesBox((*world.robots)[r], *sites.aside[o], world.world->objects[o].size)) {
        reach[o].push_back(static_cast<int>(r));
      }
    }
  }
  return reach;
}

/// "blue_0 at (0.060, -0.090), blue_3 at (0.300, 0.165)"
std::string describeSetAsideSites(const core::World& world, const ObjectSites& sites, const std::vector<int>& objects) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(3);
  for (const int o : objects) {
    const Eigen::Vector3d& p = sites.aside[static_cast<std::size_t>(o)]->translation();
    text << (o == objects.front() ? "" : ", ") << world.objects[static_cast<std::size_t>(o)].name << " at (" << p.x()
         << ", " << p.y() << ")";
  }
  return text.str();
}

/// Why an object can never reach its goal in the task-space hypergraph, or "".
std::string unreachableReason(const core::World& world, const TaskSpaceHypergraph& ts, const HyperpathSearch& search,
                              int object) {
  const std::string& name = world.objects[object].name;
  const core::Region* region = world.goalRegionOf(world.objects[object]);
  if (search.costToGo(object, ts.objectRestingVertex(object)) >= 0) return "";
  if (ts.allowed().reach.start[object].empty()) return "no robot can reach " + name + " at its start";
  if (ts.allowed().reach.goal[object].empty()) return "no robot can reach a placement of " + name + " in " + region->name;
  return "no chain of robots can carry " + name + " from its start to " + region->name +
         " (the robots reaching it do not share a workspace with those reaching the goal)";
}

/// The plan's deterministic statistics (wall-clock times are left out on purpose).
nlohmann::json planStatistics(const PlannerSettings& settings, const PlannerStats& stats) {
  return {{"planner", "DaSH"},
          {"method", toString(settings.method)},
          {"seed", settings.seed},
          {"status", "solved"},
          {"rounds", stats.rounds},
          {"task_space_hypergraph", {{"vertices", stats.task_vertices}, {"hyperarcs", stats.task_hyperarcs}}},
          {"set_aside_sites", stats.set_aside_sites},
          {"motion_hypergraph",
           {{"vertices", stats.motion_vertices},
            {"transitions", stats.motion_transitions},
            {"moves", stats.motion_moves},
            {"roadmaps", stats.roadmaps},
            {"roadmap_nodes", stats.roadmap_nodes}}},
          {"search_expansions", stats.expansions},
          {"task_plans", stats.task_plans},
          {"conflict_nodes", stats.conflict_nodes},
          {"scheduling_constraints", stats.scheduling_constraints},
          {"conflict_constraints", stats.conflict_constraints},
          {"unresolved_makespan", stats.unresolved_makespan},
          {"makespan", stats.makespan},
          {"sequential", stats.sequential}};
}

}  // namespace

const char* toString(PlannerStatus status) {
  switch (status) {
    case PlannerStatus::kSolved:
      return "solved";
    case PlannerStatus::kInfeasible:
      return "infeasible";
    case PlannerStatus::kTimeout:
      break;
  }
  return "timeout";
}

std::shared_ptr<const CollisionScene> checkedScene(const core::LoadedWorld& world, const PlannerSettings& settings) {
  auto scene = std::make_shared<const CollisionScene>(*world.world, *world.robots, settings.representation.collision);
  requireFreeHomes(*world.world, *scene);
  return scene;
}

PlanResult solve(const core::LoadedWorld& world, const PlannerSettings& settings, const PlannerBudget& budget,
                 std::shared_ptr<const CollisionScene> checked_scene) {
  validate(settings);
  PlanResult result;
  PlannerStats& stats = result.stats;
  const Clock::time_point started = Clock::now();
  if (!checked_scene) checked_scene = checkedScene(world, settings);
  // the direct queries' share of the time (see direct_time_share): their searches and conflict
  // resolutions stop at its end, the sequential query's at the deadline
  std::optional<Clock::time_point> direct_deadline;
  if (budget.deadline && *budget.deadline > started) {
    direct_deadline = started + std::chrono::duration_cast<Clock::duration>((*budget.deadline - started) *
                                                                             settings.direct_time_share);
  }
  const auto say = [&](const std::string& line) {
    if (budget.progress) budget.progress(line);
  };

  ObjectSites sites;
  try {
    sites = objectSites(world);
  } catch (const std::runtime_error& e) {  // a region without room for the objects sent there
    result.reason = e.what();
    return result;
  }
  auto task_space = std::make_unique<const TaskSpaceHypergraph>(
      TaskSpaceHypergraph::fromWorld(*world.world, *world.robots, placementReach(world, sites)));
  double task_space_seconds = secondsSince(started);
  auto graph = std::make_unique<MotionHypergraph>(world, *task_space, sites, settings.seed, settings.representation,
                                                  checked_scene);
  const auto record = [&] {
    stats.construction_seconds = task_space_seconds + graph->constructionSeconds();
    stats.task_vertices = task_space->numVertices();
    stats.task_hyperarcs = task_space->numHyperarcs();
    stats.rounds = graph->rounds();
    stats.motion_vertices = graph->numVertices();
    stats.motion_transitions = graph->numTransitions();
    stats.motion_moves = graph->numMoves();
    stats.roadmaps = graph->numRoadmaps();
    stats.roadmap_nodes = graph->numRoadmapNodes();
  };

  // objects that can never reach their goals: infeasible, whatever the sampling
  {
    const HyperpathSearch probe(*graph);
    for (int o = 0; o < task_space->numObjects(); ++o) {
      std::string reason = unreachableReason(*world.world, *task_space, probe, o);
      const bool no_pick = reason.empty() && pickTransitionsOf(*graph, o).empty();
      if (no_pick && graph->sites().goal[o]) {
        reason = "no collision-free grasp of " + world.world->objects[o].name + " at its start for any robot reaching it";
      }
      if (!reason.empty()) {
        result.reason = reason;
        record();
        return result;
      }
    }
  }

  // objects in the way of every pick of another one get set-aside sites, in case that one must
  // go in before them (a shelf item behind one that goes into the slot in front of it): the
  // representation is built again with them
  if (settings.set_aside) {
    const std::vector<CrowdedPick> crowded = crowdedPicks(*graph);  // its pick samples: the graph's construction
    const Clock::time_point t0 = Clock::now();
    const std::vector<int> given =
        setAsideSites(world, sites, objectsInTheWay(crowded),
                      [&](int o, const core::Pose& X_WO) { return asideKeepsClear(*graph, crowded, o, X_WO); });
    if (given.empty()) {
      task_space_seconds += secondsSince(t0);
    } else {
      auto with_aside = std::make_unique<const TaskSpaceHypergraph>(TaskSpaceHypergraph::fromWorld(
          *world.world, *world.robots, placementReach(world, sites), setAsideReach(world, sites)));
      // the first representation's construction (its pick samples) counts, then the new one's
      task_space_seconds += secondsSince(t0) + graph->constructionSeconds();
      graph = std::make_unique<MotionHypergraph>(world, *with_aside, sites, settings.seed, settings.representation,
                                                 checked_scene);
      task_space = std::move(with_aside);
      stats.set_aside_sites = static_cast<int>(given.size());
      say("set-aside sites: " + describeSetAsideSites(*world.world, sites, given) + crowdedPicksText(*graph, 4));
    }
  }

  PlanningRounds rounds(*graph, settings, stats, budget.deadline, direct_deadline, budget.progress);
  rounds.run();
  record();
  if (!rounds.neverPlaceable().empty()) {
    result.reason = rounds.neverPlaceable();
    return result;
  }
  if (!rounds.bestSchedule()) {
    result.status = PlannerStatus::kTimeout;
    result.reason = (rounds.timeUp() ? "time budget exhausted after " : "no plan after ") + std::to_string(graph->rounds()) +
                    (graph->rounds() == 1 ? " round" : " rounds") + " of representation expansion: " + rounds.lastFailure();
    // without any task plan, picks that must wait for other objects to be picked first, and
    // the transitions the search asked for and the sampler never found, say where the gap is
    // (e.g. no handoff of an object too small for two grippers)
    const bool no_task_plan = !rounds.bestHistory() && stats.task_plans == 0;
    if (no_task_plan) result.reason += crowdedPicksText(*graph, 4);
    if (no_task_plan && rounds.furthest()) result.reason += furthestText(*graph, *rounds.furthest());
    std::vector<std::string> unsampled;
    if (no_task_plan) {
      for (int id : graph->unsampledHyperarcs()) unsampled.push_back(describeHyperarc(*world.world, *task_space, id));
    }
    if (!unsampled.empty()) result.reason += "; never sampled: " + firstFew(unsampled, 4, ", ");
    return result;
  }
  stats.makespan = toSeconds(rounds.bestMakespan());
  stats.sequential = rounds.bestHistory()->sequential;
  result.status = PlannerStatus::kSolved;
  result.plan = writePlan(*graph, *rounds.bestHistory(), *rounds.bestSchedule());
  result.plan->seed = settings.seed;
  result.plan->statistics = planStatistics(settings, stats);
  return result;
}

}  // namespace dashbed::planner
