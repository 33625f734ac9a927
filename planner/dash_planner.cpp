#include "planner/dash_planner.h"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "planner/home_check.h"
#include "planner/hyperpath_search.h"
#include "planner/plan_writer.h"
#include "planner/scheduled_cbs.h"

namespace dashbed::planner {
namespace {

using Clock = std::chrono::steady_clock;

/// Failed direct task plans of a round resolved again (PlannerSettings::conflict_reroutes_retry).
constexpr std::size_t kSecondTries = 3;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// [s] the time `work` takes, less the construction time it adds meanwhile: the search and
/// conflict resolution plan moves lazily (for the task plan, detours, parkings), which counts
/// as the representation's construction.
template <class Work>
double secondsBeyondConstruction(const MotionHypergraph& graph, Work&& work) {
  const Clock::time_point t0 = Clock::now();
  const double built = graph.constructionSeconds();
  work();
  return secondsSince(t0) - (graph.constructionSeconds() - built);
}

/// Two task plans with the same steps (transitions, and moves to them) and final moves: a
/// query that meets the same constraints again returns the same plan.
bool sameTransitionsAndMoves(const TransitionHistory& a, const TransitionHistory& b) {
  const auto same_step = [](const ScheduledTransition& x, const ScheduledTransition& y) {
    return x.transition == y.transition && x.moves == y.moves;
  };
  return a.final_moves == b.final_moves && std::equal(a.steps.begin(), a.steps.end(), b.steps.begin(), b.steps.end(), same_step);
}

/// "12.34 s"
std::string secondsText(Millis t) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << toSeconds(t) << " s";
  return out.str();
}

/// " (12 nodes)": a conflict resolution's size, as the progress lines give it.
std::string nodesText(int nodes) { return " (" + std::to_string(nodes) + " nodes)"; }

/// "pick cube_0 by r1", "handoff cube_0 by r0 to r1": a task-space hyperarc in words.
std::string describeHyperarc(const core::World& world, const TaskSpaceHypergraph& task_space, int hyperarc) {
  const TransitionHyperarc& arc = task_space.hyperarcs().at(static_cast<std::size_t>(hyperarc));
  const bool aside = arc.rest_pose == RestPose::kAside;
  static const char* const kinds[] = {"pick", "place", "handoff"};
  std::string text = std::string(aside && arc.kind == TransitionKind::kPlace ? "set aside" : kinds[static_cast<int>(arc.kind)]) +
                     " " + world.objects[arc.object].name + " by " + world.robots[arc.robot].name;
  if (arc.kind == TransitionKind::kHandoff) text += " to " + world.robots[arc.receiver].name;
  if (aside && arc.kind == TransitionKind::kPick) text += " where it was set aside";
  return text;
}

/// "place green_1 by r1 (transition 63)"
std::string describeTransition(const MotionHypergraph& graph, int id) {
  return describeHyperarc(*graph.world().world, graph.taskSpace(), graph.transition(id).sample.hyperarc) +
         " (transition " + std::to_string(id) + ")";
}

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

/// "blue_0 and blue_3", "a, b and c"
std::string objectList(const core::World& world, const std::vector<int>& objects) {
  std::string text;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    text += (k == 0 ? "" : k + 1 == objects.size() ? " and " : ", ") + world.objects[static_cast<std::size_t>(objects[k])].name;
  }
  return text;
}

/// The first `limit` items joined by `separator`, then " and N more<what>" for the rest:
/// reasons name a few of many things.
std::string firstFew(const std::vector<std::string>& items, std::size_t limit, const std::string& separator,
                     const std::string& what = "") {
  std::string text;
  for (std::size_t k = 0; k < items.size() && k < limit; ++k) text += (k == 0 ? "" : separator) + items[k];
  if (items.size() > limit) text += " and " + std::to_string(items.size() - limit) + " more" + what;
  return text;
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

/// "; the furthest task plan tried placed 11 of 12 objects, not blue_5 (held by r1)": how far
/// a greedy query without a plan got, and what it left (at most 4 objects named).
std::string furthestText(const MotionHypergraph& graph, const TransitionHistory& furthest) {
  const core::World& world = *graph.world().world;
  std::vector<std::string> left;
  int goals = 0;
  for (std::size_t o = 0; o < furthest.objects.size(); ++o) {
    if (!graph.sites().goal[o]) continue;
    ++goals;
    const TransitionHistory::ObjectState& object = furthest.objects[o];
    if (object.place == ObjectPlace::kGoal) continue;
    std::string where = "at its start";
    if (object.place == ObjectPlace::kHeld) where = "held by " + world.robots[static_cast<std::size_t>(object.holder)].name;
    if (object.place == ObjectPlace::kAside) where = "set aside";
    left.push_back(world.objects[o].name + " (" + where + ")");
  }
  if (left.empty()) {  // complete, but finish() found a robot no way to where it rests
    return "; the furthest task plan tried placed all " + std::to_string(goals) +
           " objects, but a robot found no way back to where it rests";
  }
  return "; the furthest task plan tried placed " + std::to_string(furthest.objectsAtGoal()) + " of " +
         std::to_string(goals) + " objects, not " + firstFew(left, 4, ", ");
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

/// A sequential plan's steps may overlap where they keep clear of each other: conflict
/// resolution runs again without the steps' order and any schedule shorter than theirs one
/// after another will do. Where the task plan's order (`budget`: the shortest first within
/// its focal weight) finds none, the node free of conflicts for longest first gets a second
/// try. Returns the overlapping schedule, or nothing when neither finds one shorter; adds the
/// nodes expanded to `nodes` and says one line per try.
std::optional<ConflictResult> overlapSequentialSteps(MotionHypergraph& graph, const TransitionHistory& history,
                                                     ConflictResolutionBudget budget,
                                                     const ConflictResult& one_after_another, int& nodes,
                                                     const std::function<void(const std::string&)>& say) {
  budget.makespan_below = one_after_another.schedule->makespan;
  for (const NodeOrder order : {NodeOrder::kMakespan, NodeOrder::kAlongTime}) {
    budget.order = order;
    ConflictResult overlapping = resolveConflicts(graph, history, budget, SequentialSteps::kOverlapping);
    nodes += overlapping.nodes;
    say("steps one after another: makespan " + secondsText(one_after_another.schedule->makespan) +
        nodesText(one_after_another.nodes) + "; overlapping" + (order == NodeOrder::kAlongTime ? ", along time" : "") +
        ": " +
        (overlapping.status == ConflictStatus::kResolved ? "makespan " + secondsText(overlapping.schedule->makespan)
         : overlapping.status == ConflictStatus::kBudget ? std::string("none shorter within the budget")
                                                         : std::string("none shorter")) +
        nodesText(overlapping.nodes));
    if (overlapping.status == ConflictStatus::kResolved) return overlapping;
  }
  return std::nullopt;
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

const char* toString(Method method) { return method == Method::kGreedy ? "greedy" : "optimal"; }

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

std::uint64_t constrainedSearchExpansions(const PlannerSettings& settings, int round, std::uint64_t unconstrained) {
  std::uint64_t grown = settings.constrained_search_expansions;
  for (int r = 1; r < round && grown < settings.search_expansions; ++r) grown *= 2;
  return std::min(settings.search_expansions, std::max(grown, 2 * unconstrained));
}

std::uint64_t greedySearchExpansions(const PlannerSettings& settings, QueryMode mode, bool constrained, int round,
                                     std::uint64_t unconstrained) {
  if (!constrained && !keepsClearOfIdle(mode)) return settings.search_expansions;
  return constrainedSearchExpansions(settings, round, unconstrained);
}

PlanResult solve(const core::LoadedWorld& world, const PlannerSettings& settings, const PlannerBudget& budget) {
  if (settings.max_rounds < 1) throw std::invalid_argument("planner settings: max_rounds: must be >= 1");
  if (settings.sequential_fallback_rounds < 0) {
    throw std::invalid_argument("planner settings: sequential_fallback_rounds: must be >= 0");
  }
  if (!(settings.conflict_focal_weight >= 1.0)) {
    throw std::invalid_argument("planner settings: conflict_focal_weight: must be >= 1");
  }
  if (settings.conflict_nodes < 1 || settings.conflict_nodes_along_time < 1 ||
      settings.conflict_nodes_depth_first < 1) {
    throw std::invalid_argument(
        "planner settings: conflict_nodes, conflict_nodes_along_time, conflict_nodes_depth_first: must be >= 1");
  }
  if (settings.conflict_reroutes < 0 || settings.conflict_reroutes_retry < 0) {
    throw std::invalid_argument("planner settings: conflict_reroutes, conflict_reroutes_retry: must be >= 0");
  }
  if (!(settings.direct_time_share > 0.0 && settings.direct_time_share <= 1.0)) {
    throw std::invalid_argument("planner settings: direct_time_share: must be in (0, 1]");
  }
  PlanResult result;
  PlannerStats& stats = result.stats;
  const Clock::time_point started = Clock::now();
  // the direct queries' share of the time (see direct_time_share): their searches and conflict
  // resolutions stop at its end, the sequential query's at the deadline
  std::optional<Clock::time_point> direct_deadline;
  if (budget.deadline && *budget.deadline > started) {
    direct_deadline = started + std::chrono::duration_cast<Clock::duration>((*budget.deadline - started) *
                                                                             settings.direct_time_share);
  }
  bool direct_queries = false;  // while the direct queries of a round run without a plan so far
  const auto past = [](const std::optional<Clock::time_point>& t) { return t && Clock::now() >= *t; };
  const auto time_up = [&] { return past(budget.deadline) || (direct_queries && past(direct_deadline)); };
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
  auto graph = std::make_unique<MotionHypergraph>(world, *task_space, sites, settings.seed, settings.representation);
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

  requireFreeHomes(*world.world, graph->scene());
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
      graph = std::make_unique<MotionHypergraph>(world, *with_aside, sites, settings.seed, settings.representation);
      task_space = std::move(with_aside);
      stats.set_aside_sites = static_cast<int>(given.size());
      say("set-aside sites: " + describeSetAsideSites(*world.world, sites, given) + crowdedPicksText(*graph, 4));
    }
  }

  const SearchBudget search_budget{settings.search_expansions, time_up};
  ConflictResolutionBudget conflict_budget;
  conflict_budget.max_nodes = settings.conflict_nodes;
  conflict_budget.max_reroutes = settings.conflict_reroutes;
  conflict_budget.stop = time_up;
  std::optional<TransitionHistory> best_history;
  // a fallback plan (sequential, or with the robots parked out of every transition's way) is
  // kept while the next rounds' direct queries look for a shorter one
  bool best_fallback = false;
  std::optional<Schedule> best_schedule;
  Millis best = std::numeric_limits<Millis>::max();
  std::string last_failure = "no task plan found";
  int fallback_round = 0;  // the round that found the first sequential plan
  std::optional<TransitionHistory> furthest;  // of the greedy queries without a plan so far

  // conflict resolution of a task plan (with this focal weight); keeps it when better than the
  // best so far. Returns true when its failure gave a new scheduling constraint (at most the
  // round's allowance; none on a second try). With a fallback plan in hand, a direct task plan
  // that fails joins failed_direct for the round's second try, which resolves in `order`.
  int feedbacks = 0;  // this round
  std::vector<TransitionHistory> failed_direct;  // this round's, distinct
  const auto resolve = [&](const TransitionHistory& history, double focal_weight, bool second_try = false,
                           NodeOrder order = NodeOrder::kMakespan) {
    ++stats.task_plans;
    ConflictResolutionBudget weighted = conflict_budget;
    weighted.focal_weight = focal_weight;
    if (second_try) {  // with the fallback in hand: only a shorter plan is worth it
      weighted.max_reroutes = settings.conflict_reroutes_retry;
      weighted.makespan_below = best;
      weighted.order = order;
      if (order == NodeOrder::kAlongTime) weighted.max_nodes = settings.conflict_nodes_along_time;
      if (order == NodeOrder::kDepthFirst) weighted.max_nodes = settings.conflict_nodes_depth_first;
    }
    ConflictResult resolved;
    stats.conflict_seconds += secondsBeyondConstruction(*graph, [&] {
      resolved = resolveConflicts(*graph, history, weighted);
      stats.conflict_nodes += resolved.nodes;
      if (resolved.status == ConflictStatus::kResolved && history.sequential) {
        std::optional<ConflictResult> overlapping =
            overlapSequentialSteps(*graph, history, weighted, resolved, stats.conflict_nodes, say);
        if (overlapping) resolved = std::move(*overlapping);
      }
    });
    if (resolved.status != ConflictStatus::kResolved) {
      last_failure = "conflict resolution failed: " + resolved.reason;
      if (best_schedule && !history.sequential && !second_try &&
          std::none_of(failed_direct.begin(), failed_direct.end(),
                       [&](const TransitionHistory& h) { return sameTransitionsAndMoves(h, history); })) {
        failed_direct.push_back(history);
      }
      if (feedbacks < settings.scheduling_constraints_per_round && !second_try) {
        const auto fed_back = [&](bool added, const std::string& between) {
          if (!added) return false;
          ++feedbacks;
          ++stats.scheduling_constraints;
          say(last_failure + nodesText(resolved.nodes) + "; scheduling constraint from a conflict no order resolved: " +
              between);
          return true;
        };
        for (const auto& [a, b] : resolved.unordered) {
          if (fed_back(graph->addSchedulingConstraint(a, b),
                       describeTransition(*graph, a) + " / " + describeTransition(*graph, b))) {
            return true;
          }
        }
        for (const auto& [transition, robot] : resolved.home_blocked) {
          if (fed_back(graph->addHomeConstraint(transition, robot),
                       describeTransition(*graph, transition) + " / " +
                           graph->world().world->robots[static_cast<std::size_t>(robot)].name + " at home")) {
            return true;
          }
        }
      }
      say(last_failure + nodesText(resolved.nodes));
      return false;
    }
    say("conflict resolution: makespan " + secondsText(resolved.schedule->makespan) + nodesText(resolved.nodes));
    if (resolved.schedule->makespan < best) {
      best = resolved.schedule->makespan;
      best_history = history;
      best_fallback = history.sequential;
      best_schedule = resolved.schedule;
      stats.conflict_constraints = resolved.constraints;
      stats.unresolved_makespan = toSeconds(resolved.unresolved_makespan);
    }
    return false;
  };
  const auto search_timed = [&](auto&& query) {
    SearchResult found;
    stats.search_seconds += secondsBeyondConstruction(*graph, [&] { found = query(); });
    stats.expansions += found.expansions;
    const char* status[] = {"found a task plan", "found none", "ran out of its budget"};
    std::string line = std::string(status[static_cast<int>(found.status)]) + " after " +
                       std::to_string(found.expansions) + " expansions";
    if (found.plan) line += ", optimistic makespan " + secondsText(found.plan->makespan());
    if (found.furthest) line += furthestText(*graph, *found.furthest);
    say(line);
    return found;
  };

  std::vector<bool> checked_placeable(static_cast<std::size_t>(task_space->numObjects()), false);
  for (int round = 1; round <= settings.max_rounds && !time_up(); ++round) {
    if (round > 1) graph->expand();
    feedbacks = 0;
    say("round " + std::to_string(round) + ": " + std::to_string(graph->numTransitions()) + " transitions, " +
        std::to_string(graph->numMoves()) + " moves");
    // the greedy plan, and when its robots cannot be ordered, the one parking idle robots at
    // home; a new scheduling constraint starts the queries again
    std::uint64_t unconstrained_expansions = 0;  // of the last plan found without constraints
    const auto greedy_query = [&](QueryMode mode, HyperpathSearch::Relays relays = HyperpathSearch::Relays::kOff) {
      static const char* const modes[] = {"", ", idle robots parking at home",
                                          ", idle robots parking at home out of every transition's way",
                                          ", one object at a time",
                                          ", one object at a time, idle robots folded"};
      const bool relaying = relays != HyperpathSearch::Relays::kOff;
      say(std::string("greedy query") + modes[static_cast<int>(mode)] + (relaying ? ", relaying around the robots waiting" : "") +
          ", " + std::to_string(graph->numSchedulingConstraints()) + " scheduling constraints");
      SearchBudget query_budget = search_budget;
      query_budget.max_expansions = greedySearchExpansions(settings, mode, graph->numSchedulingConstraints() > 0, round,
                                                           unconstrained_expansions);
      HyperpathSearch query(*graph, mode, relays);
      const SearchResult greedy = search_timed([&] { return query.greedy(query_budget); });
      if (greedy.status == SearchStatus::kFound && graph->numSchedulingConstraints() == 0) {
        unconstrained_expansions = greedy.expansions;
      }
      if (greedy.furthest && (!furthest || greedy.furthest->objectsAtGoal() > furthest->objectsAtGoal())) {
        furthest = greedy.furthest;
      }
      if (greedy.status == SearchStatus::kBudget) last_failure = "the greedy search ran out of expansions";
      if (greedy.status == SearchStatus::kExhausted) last_failure = "no task plan in the representation";
      return greedy;
    };
    const auto direct_plan = [&] { return best_history && !best_fallback; };
    direct_queries = !best_schedule;
    failed_direct.clear();
    for (bool again = true; again && !direct_plan() && !time_up();) {
      again = false;
      for (const QueryMode mode : {QueryMode::kDirect, QueryMode::kParkAtHome}) {
        const SearchResult greedy = greedy_query(mode);
        if (greedy.status == SearchStatus::kFound) again = resolve(*greedy.plan, settings.conflict_focal_weight);
        // a pair conflict resolution could not order in one history may be ordered in another:
        // constraints that leave no task plan (within the budget) are dropped (and none comes
        // back this round: the same plan would bring the same pair)
        if (greedy.status != SearchStatus::kFound && graph->numSchedulingConstraints() > 0) {
          say("scheduling constraints dropped");
          graph->clearSchedulingConstraints();
          feedbacks = settings.scheduling_constraints_per_round;
          again = true;
          break;
        }
        if (again || direct_plan() || time_up()) break;
      }
    }
    // where they leave no direct plan, once a round: the robots parking at home out of every
    // transition's way, objects relayed around them (its conflicts feed no constraint back: the
    // round's queries are done with them). A fallback: its robots wait for each other at home,
    // where a later round's direct plan may not (4 robots / 16 crossing cubes, seeds 7 and 9:
    // 184.7 and 180.1 s in round 1, direct plans of 175.9 and 173.9 s in round 2)
    if (!direct_plan() && !time_up()) {
      const SearchResult greedy = greedy_query(QueryMode::kParkClearOfHomes, HyperpathSearch::Relays::kAroundIdleRobots);
      feedbacks = settings.scheduling_constraints_per_round;
      const Millis before = best;
      if (greedy.status == SearchStatus::kFound) resolve(*greedy.plan, settings.conflict_focal_weight);
      if (best < before) best_fallback = true;
    }
    // conflict resolution's second try (PlannerSettings::conflict_reroutes_retry)
    if (best_schedule && !direct_plan() && !failed_direct.empty() &&
        settings.conflict_reroutes_retry > settings.conflict_reroutes) {
      std::stable_sort(failed_direct.begin(), failed_direct.end(),
                       [](const TransitionHistory& a, const TransitionHistory& b) { return a.makespan() < b.makespan(); });
      failed_direct.resize(std::min<std::size_t>(failed_direct.size(), kSecondTries));
      say("conflict resolution again for the round's " + std::to_string(failed_direct.size()) + " shortest failed direct task plans, up to " +
          std::to_string(settings.conflict_reroutes_retry) +
          " detours and parkings, best first, then along time, the shortest also depth first");
      // any schedule shorter than the fallback's will do: where best first runs out of nodes
      // (robots meeting again and again, each meeting ordered both ways), along time most often
      // finds one in a few dozen (NodeOrder::kAlongTime); where the robots crowd so that it
      // goes back and forth between orders, depth first gets through, to a longer schedule
      for (std::size_t i = 0; i < failed_direct.size(); ++i) {
        for (const NodeOrder order : {NodeOrder::kMakespan, NodeOrder::kAlongTime, NodeOrder::kDepthFirst}) {
          if (direct_plan() || time_up() || (order == NodeOrder::kDepthFirst && i > 0)) break;
          resolve(failed_direct[i], settings.conflict_focal_weight, true, order);
        }
      }
    }
    if (direct_queries && past(direct_deadline) && !past(budget.deadline)) {
      // cut short, they may leave constraints in force that no query of theirs has dropped yet
      // (those steer a depth-first search into corners, and the sequential query has one try)
      say("the direct queries used their share of the time budget without a plan; on to the sequential query" +
          std::string(graph->numSchedulingConstraints() > 0 ? ", their scheduling constraints dropped" : ""));
      graph->clearSchedulingConstraints();
    }
    direct_queries = false;
    // the last resort of the round: the sequential plan, its own scheduling constraints (most
    // often a robot waiting at home in the way of another's transition) starting it again; it
    // is kept as a fallback while the next rounds look for a direct plan. Where the robots
    // waiting at home leave it none, they wait folded back; where that leaves none either, both
    // run again relaying objects around the robots waiting (HyperpathSearch::Relays).
    for (const HyperpathSearch::Relays relays : {HyperpathSearch::Relays::kOff, HyperpathSearch::Relays::kAroundIdleRobots}) {
      for (const QueryMode mode : {QueryMode::kSequential, QueryMode::kSequentialFolded}) {
        feedbacks = 0;
        for (bool again = !best_schedule; again && !time_up();) {
          const SearchResult greedy = greedy_query(mode, relays);
          again = greedy.status == SearchStatus::kFound && resolve(*greedy.plan, settings.conflict_focal_weight);
        }
      }
    }
    if (best_schedule && fallback_round == 0) fallback_round = round;
    // Next-Best Search: task plans in order of optimistic makespan until no better is possible.
    // It starts from Greedy's plan as its upper bound: not in a round without one (its lazily
    // planned moves would grow the representation otherwise than Greedy's next round does, which
    // then may find a plan Next-Best Search cannot improve on, but Greedy's is better), nor while
    // a sequential fallback waits for the direct queries of the next rounds
    const bool fallback_done = round >= fallback_round + settings.sequential_fallback_rounds;
    const bool greedy_done = direct_plan() || (best_schedule && fallback_done);
    for (bool again = settings.method == Method::kOptimal && greedy_done; again && !time_up();) {
      again = false;
      HyperpathSearch search(*graph);
      for (int k = 0; k < settings.next_best_plans && !again && !time_up(); ++k) {
        const SearchResult next = search_timed([&] { return search.nextBest(search_budget); });
        if (next.status != SearchStatus::kFound || next.plan->makespan() >= best) break;
        again = resolve(*next.plan, 1.0);  // best first: the shortest schedule of each
      }
    }
    if (greedy_done) break;
    if (best_schedule) {
      say(std::string("keeping the ") +
          (best_history->sequential ? "sequential plan" : "plan with the robots parked out of every transition's way") +
          " (makespan " + secondsText(best) + ") while looking for a direct one");
      continue;
    }
    // an object without any place sample after a round may be one no grasp can ever place; so
    // may any object while no task plan has been found at all (its place samples may be for
    // grasps the placing robot can never come to hold)
    for (int o = 0; o < task_space->numObjects(); ++o) {
      if (checked_placeable[static_cast<std::size_t>(o)] || !graph->sites().goal[o] ||
          (graph->hasPlaceSample(o) && stats.task_plans > 0)) {
        continue;
      }
      checked_placeable[static_cast<std::size_t>(o)] = true;  // asked once: the answer never changes
      if (graph->neverPlaceable(o)) {
        const core::World& w = *world.world;
        const std::string& object = w.objects[static_cast<std::size_t>(o)].name;
        const std::string& region = w.regions[static_cast<std::size_t>(graph->sites().goal_region[o])].name;
        result.reason = object + " can never be placed in " + region + ": no robot that reaches " + region +
                        " can hold " + object + " in a grasp it has a collision-free place for (grasps come only "
                        "from picks and handoffs; nothing is regrasped)";
        record();
        return result;
      }
    }
  }
  record();
  if (!best_schedule) {
    result.status = PlannerStatus::kTimeout;
    result.reason = (time_up() ? "time budget exhausted after " : "no plan after ") + std::to_string(graph->rounds()) +
                    (graph->rounds() == 1 ? " round" : " rounds") + " of representation expansion: " + last_failure;
    // without any task plan, picks that must wait for other objects to be picked first, and
    // the transitions the search asked for and the sampler never found, say where the gap is
    // (e.g. no handoff of an object too small for two grippers)
    const bool no_task_plan = !best_history && stats.task_plans == 0;
    if (no_task_plan) result.reason += crowdedPicksText(*graph, 4);
    if (no_task_plan && furthest) result.reason += furthestText(*graph, *furthest);
    std::vector<std::string> unsampled;
    if (no_task_plan) {
      for (int id : graph->unsampledHyperarcs()) unsampled.push_back(describeHyperarc(*world.world, *task_space, id));
    }
    if (!unsampled.empty()) result.reason += "; never sampled: " + firstFew(unsampled, 4, ", ");
    return result;
  }
  stats.makespan = toSeconds(best);
  stats.sequential = best_history->sequential;
  result.status = PlannerStatus::kSolved;
  result.plan = writePlan(*graph, *best_history, *best_schedule);
  result.plan->seed = settings.seed;
  result.plan->statistics = planStatistics(settings, stats);
  return result;
}

}  // namespace dashbed::planner
