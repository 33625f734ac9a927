#include "planner/planning_rounds.h"

#include <algorithm>
#include <utility>

#include "planner/planner_text.h"

namespace dashbed::planner {
namespace {

using Clock = PlanningRounds::Clock;

/// Failed direct task plans of a round resolved again (PlannerSettings::conflict_reroutes_retry).
constexpr std::size_t kSecondTries = 3;

/// Whether `t` is set and has passed.
bool past(const std::optional<Clock::time_point>& t) { return t && Clock::now() >= *t; }

/// [s] the time `work` takes, less the construction time it adds meanwhile: the search and
/// conflict resolution plan moves lazily (for the task plan, detours, parkings), which counts
/// as the representation's construction.
template <class Work>
double secondsBeyondConstruction(const MotionHypergraph& graph, Work&& work) {
  const Clock::time_point t0 = Clock::now();
  const double built = graph.constructionSeconds();
  work();
  return std::chrono::duration<double>(Clock::now() - t0).count() - (graph.constructionSeconds() - built);
}

/// Two task plans with the same steps (transitions, and moves to them) and final moves: a
/// query that meets the same constraints again returns the same plan.
bool sameTransitionsAndMoves(const TransitionHistory& a, const TransitionHistory& b) {
  const auto same_step = [](const ScheduledTransition& x, const ScheduledTransition& y) {
    return x.transition == y.transition && x.moves == y.moves;
  };
  return a.final_moves == b.final_moves && std::equal(a.steps.begin(), a.steps.end(), b.steps.begin(), b.steps.end(), same_step);
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

}  // namespace

PlanningRounds::PlanningRounds(MotionHypergraph& graph, const PlannerSettings& settings, PlannerStats& stats,
                               std::optional<Clock::time_point> deadline,
                               std::optional<Clock::time_point> direct_deadline,
                               std::function<void(const std::string&)> say)
    : graph_(graph),
      settings_(settings),
      stats_(stats),
      deadline_(deadline),
      direct_deadline_(direct_deadline),
      say_(std::move(say)),
      checked_placeable_(static_cast<std::size_t>(graph.taskSpace().numObjects()), false) {
  const std::function<bool()> time_up = [this] { return timeUp(); };
  search_budget_ = {settings.search_expansions, time_up};
  conflict_budget_.max_nodes = settings.conflict_nodes;
  conflict_budget_.max_reroutes = settings.conflict_reroutes;
  conflict_budget_.stop = time_up;
}

bool PlanningRounds::timeUp() const {
  return past(deadline_) || (direct_queries_ && past(direct_deadline_));
}

SearchResult PlanningRounds::searchTimed(const std::function<SearchResult()>& query) {
  SearchResult found;
  stats_.search_seconds += secondsBeyondConstruction(graph_, [&] { found = query(); });
  stats_.expansions += found.expansions;
  const char* status[] = {"found a task plan", "found none", "ran out of its budget"};
  std::string line = std::string(status[static_cast<int>(found.status)]) + " after " +
                     std::to_string(found.expansions) + " expansions";
  if (found.plan) line += ", optimistic makespan " + secondsText(found.plan->makespan());
  if (found.furthest) line += furthestText(graph_, *found.furthest);
  say(line);
  return found;
}

// Conflict resolution of a task plan (with this focal weight); keeps it when better than the
// best so far. Returns true when its failure gave a new scheduling constraint (at most the
// round's allowance; none on a second try). With a fallback plan in hand, a direct task plan
// that fails joins failed_direct_ for the round's second try, which resolves in `order`.
bool PlanningRounds::resolve(const TransitionHistory& history, double focal_weight, bool second_try, NodeOrder order) {
  ++stats_.task_plans;
  ConflictResolutionBudget weighted = conflict_budget_;
  weighted.focal_weight = focal_weight;
  if (second_try) {  // with the fallback in hand: only a shorter plan is worth it
    weighted.max_reroutes = settings_.conflict_reroutes_retry;
    weighted.makespan_below = best_;
    weighted.order = order;
    if (order == NodeOrder::kAlongTime) weighted.max_nodes = settings_.conflict_nodes_along_time;
    if (order == NodeOrder::kDepthFirst) weighted.max_nodes = settings_.conflict_nodes_depth_first;
  }
  ConflictResult resolved;
  stats_.conflict_seconds += secondsBeyondConstruction(graph_, [&] {
    resolved = resolveConflicts(graph_, history, weighted);
    stats_.conflict_nodes += resolved.nodes;
    if (resolved.status == ConflictStatus::kResolved && history.sequential) {
      std::optional<ConflictResult> overlapping =
          overlapSequentialSteps(graph_, history, weighted, resolved, stats_.conflict_nodes,
                                 [this](const std::string& line) { say(line); });
      if (overlapping) resolved = std::move(*overlapping);
    }
  });
  if (resolved.status != ConflictStatus::kResolved) {
    last_failure_ = "conflict resolution failed: " + resolved.reason;
    if (best_schedule_ && !history.sequential && !second_try &&
        std::none_of(failed_direct_.begin(), failed_direct_.end(),
                     [&](const TransitionHistory& h) { return sameTransitionsAndMoves(h, history); })) {
      failed_direct_.push_back(history);
    }
    if (feedbacks_ < settings_.scheduling_constraints_per_round && !second_try) {
      const auto fed_back = [&](bool added, const std::string& between) {
        if (!added) return false;
        ++feedbacks_;
        ++stats_.scheduling_constraints;
        say(last_failure_ + nodesText(resolved.nodes) + "; scheduling constraint from a conflict no order resolved: " +
            between);
        return true;
      };
      for (const auto& [a, b] : resolved.unordered) {
        if (fed_back(graph_.addSchedulingConstraint(a, b),
                     describeTransition(graph_, a) + " / " + describeTransition(graph_, b))) {
          return true;
        }
      }
      for (const auto& [transition, robot] : resolved.home_blocked) {
        if (fed_back(graph_.addHomeConstraint(transition, robot),
                     describeTransition(graph_, transition) + " / " +
                         graph_.world().world->robots[static_cast<std::size_t>(robot)].name + " at home")) {
          return true;
        }
      }
    }
    say(last_failure_ + nodesText(resolved.nodes));
    return false;
  }
  say("conflict resolution: makespan " + secondsText(resolved.schedule->makespan) + nodesText(resolved.nodes));
  if (resolved.schedule->makespan < best_) {
    best_ = resolved.schedule->makespan;
    best_history_ = history;
    best_fallback_ = history.sequential;
    best_schedule_ = resolved.schedule;
    stats_.conflict_constraints = resolved.constraints;
    stats_.unresolved_makespan = toSeconds(resolved.unresolved_makespan);
  }
  return false;
}

SearchResult PlanningRounds::greedyQuery(int round, QueryMode mode, HyperpathSearch::Relays relays) {
  static const char* const modes[] = {"", ", idle robots parking at home",
                                      ", idle robots parking at home out of every transition's way",
                                      ", one object at a time", ", one object at a time, idle robots folded"};
  const bool relaying = relays != HyperpathSearch::Relays::kOff;
  say(std::string("greedy query") + modes[static_cast<int>(mode)] + (relaying ? ", relaying around the robots waiting" : "") +
      ", " + std::to_string(graph_.numSchedulingConstraints()) + " scheduling constraints");
  SearchBudget query_budget = search_budget_;
  query_budget.max_expansions = greedySearchExpansions(settings_, mode, graph_.numSchedulingConstraints() > 0, round,
                                                       unconstrained_expansions_);
  HyperpathSearch query(graph_, mode, relays);
  const SearchResult greedy = searchTimed([&] { return query.greedy(query_budget); });
  if (greedy.status == SearchStatus::kFound && graph_.numSchedulingConstraints() == 0) {
    unconstrained_expansions_ = greedy.expansions;
  }
  if (greedy.furthest && (!furthest_ || greedy.furthest->objectsAtGoal() > furthest_->objectsAtGoal())) {
    furthest_ = greedy.furthest;
  }
  if (greedy.status == SearchStatus::kBudget) last_failure_ = "the greedy search ran out of expansions";
  if (greedy.status == SearchStatus::kExhausted) last_failure_ = "no task plan in the representation";
  return greedy;
}

// The greedy plan, and when its robots cannot be ordered, the one parking idle robots at home;
// a new scheduling constraint starts the queries again.
void PlanningRounds::directQueries(int round) {
  for (bool again = true; again && !directPlan() && !timeUp();) {
    again = false;
    for (const QueryMode mode : {QueryMode::kDirect, QueryMode::kParkAtHome}) {
      const SearchResult greedy = greedyQuery(round, mode);
      if (greedy.status == SearchStatus::kFound) again = resolve(*greedy.plan, settings_.conflict_focal_weight);
      // a pair conflict resolution could not order in one history may be ordered in another:
      // constraints that leave no task plan (within the budget) are dropped (and none comes
      // back this round: the same plan would bring the same pair)
      if (greedy.status != SearchStatus::kFound && graph_.numSchedulingConstraints() > 0) {
        say("scheduling constraints dropped");
        graph_.clearSchedulingConstraints();
        feedbacks_ = settings_.scheduling_constraints_per_round;
        again = true;
        break;
      }
      if (again || directPlan() || timeUp()) break;
    }
  }
}

// Where they leave no direct plan, once a round: the robots parking at home out of every
// transition's way, objects relayed around them (its conflicts feed no constraint back: the
// round's queries are done with them). A fallback: its robots wait for each other at home,
// where a later round's direct plan may not, so that plan can be shorter.
void PlanningRounds::parkedClearOfHomes(int round) {
  if (directPlan() || timeUp()) return;
  const SearchResult greedy = greedyQuery(round, QueryMode::kParkClearOfHomes, HyperpathSearch::Relays::kAroundIdleRobots);
  feedbacks_ = settings_.scheduling_constraints_per_round;
  const Millis before = best_;
  if (greedy.status == SearchStatus::kFound) resolve(*greedy.plan, settings_.conflict_focal_weight);
  if (best_ < before) best_fallback_ = true;
}

// Conflict resolution's second try (PlannerSettings::conflict_reroutes_retry).
void PlanningRounds::secondTries() {
  if (!best_schedule_ || directPlan() || failed_direct_.empty() ||
      settings_.conflict_reroutes_retry <= settings_.conflict_reroutes) {
    return;
  }
  std::stable_sort(failed_direct_.begin(), failed_direct_.end(),
                   [](const TransitionHistory& a, const TransitionHistory& b) { return a.makespan() < b.makespan(); });
  failed_direct_.resize(std::min<std::size_t>(failed_direct_.size(), kSecondTries));
  say("conflict resolution again for the round's " + std::to_string(failed_direct_.size()) +
      " shortest failed direct task plans, up to " + std::to_string(settings_.conflict_reroutes_retry) +
      " detours and parkings, best first, then along time, the shortest also depth first");
  // any schedule shorter than the fallback's will do: where best first runs out of nodes
  // (robots meeting again and again, each meeting ordered both ways), along time finds one in
  // fewer nodes (NodeOrder::kAlongTime); where the robots crowd so that it goes
  // back and forth between orders, depth first gets through, to a longer schedule
  for (std::size_t i = 0; i < failed_direct_.size(); ++i) {
    for (const NodeOrder order : {NodeOrder::kMakespan, NodeOrder::kAlongTime, NodeOrder::kDepthFirst}) {
      if (directPlan() || timeUp() || (order == NodeOrder::kDepthFirst && i > 0)) break;
      resolve(failed_direct_[i], settings_.conflict_focal_weight, true, order);
    }
  }
}

// The last resort of the round: the sequential plan, its own scheduling constraints (most
// often a robot waiting at home in the way of another's transition) starting it again; it is
// kept as a fallback while the next rounds look for a direct plan. Where the robots waiting at
// home leave it none, they wait folded back; where that leaves none either, both run again
// relaying objects around the robots waiting (HyperpathSearch::Relays).
void PlanningRounds::sequentialQueries(int round) {
  for (const HyperpathSearch::Relays relays : {HyperpathSearch::Relays::kOff, HyperpathSearch::Relays::kAroundIdleRobots}) {
    for (const QueryMode mode : {QueryMode::kSequential, QueryMode::kSequentialFolded}) {
      feedbacks_ = 0;
      for (bool again = !best_schedule_; again && !timeUp();) {
        const SearchResult greedy = greedyQuery(round, mode, relays);
        again = greedy.status == SearchStatus::kFound && resolve(*greedy.plan, settings_.conflict_focal_weight);
      }
    }
  }
  if (best_schedule_ && fallback_round_ == 0) fallback_round_ = round;
}

// Next-Best Search (Alg. 5): task plans in order of optimistic makespan until no better is
// possible, from the best plan so far as the upper bound.
void PlanningRounds::nextBestSearch() {
  for (bool again = true; again && !timeUp();) {
    again = false;
    HyperpathSearch search(graph_);
    for (int k = 0; k < settings_.next_best_plans && !again && !timeUp(); ++k) {
      const SearchResult next = searchTimed([&] { return search.nextBest(search_budget_); });
      if (next.status != SearchStatus::kFound || next.plan->makespan() >= best_) break;
      again = resolve(*next.plan, 1.0);  // best first: the shortest schedule of each
    }
  }
}

// An object without any place sample after a round may be one no grasp can ever place; so may
// any object while no task plan has been found at all (its place samples may be for grasps the
// placing robot can never come to hold). False (and never_placeable_ says why) for such one.
bool PlanningRounds::checkPlaceable() {
  for (int o = 0; o < graph_.taskSpace().numObjects(); ++o) {
    if (checked_placeable_[static_cast<std::size_t>(o)] || !graph_.sites().goal[o] ||
        (graph_.hasPlaceSample(o) && stats_.task_plans > 0)) {
      continue;
    }
    checked_placeable_[static_cast<std::size_t>(o)] = true;
    if (graph_.neverPlaceable(o)) {
      const core::World& w = *graph_.world().world;
      const std::string& object = w.objects[static_cast<std::size_t>(o)].name;
      const std::string& region = w.regions[static_cast<std::size_t>(graph_.sites().goal_region[o])].name;
      never_placeable_ = object + " can never be placed in " + region + ": no robot that reaches " + region +
                         " can hold " + object + " in a grasp it has a collision-free place for (grasps come only "
                         "from picks and handoffs; nothing is regrasped)";
      return false;
    }
  }
  return true;
}

void PlanningRounds::run() {
  for (int round = 1; round <= settings_.max_rounds && !timeUp(); ++round) {
    if (round > 1) graph_.expand();
    feedbacks_ = 0;
    unconstrained_expansions_ = 0;
    say("round " + std::to_string(round) + ": " + std::to_string(graph_.numTransitions()) + " transitions, " +
        std::to_string(graph_.numMoves()) + " moves");
    direct_queries_ = !best_schedule_;
    failed_direct_.clear();
    directQueries(round);
    parkedClearOfHomes(round);
    secondTries();
    if (direct_queries_ && past(direct_deadline_) && !past(deadline_)) {
      // cut short, they may leave constraints in force that no query of theirs has dropped yet
      // (those steer a depth-first search into corners, and the sequential query has one try)
      say("the direct queries used their share of the time budget without a plan; on to the sequential query" +
          std::string(graph_.numSchedulingConstraints() > 0 ? ", their scheduling constraints dropped" : ""));
      graph_.clearSchedulingConstraints();
    }
    direct_queries_ = false;
    sequentialQueries(round);
    // MM-DaSH's Next-Best Search starts from Greedy's plan as its upper bound: not in a round
    // without one (its lazily planned moves would grow the representation otherwise than
    // Greedy's next round does, which then may find a plan Next-Best Search cannot improve on,
    // but Greedy's is better), nor while a sequential fallback waits for the direct queries of
    // the next rounds
    const bool fallback_done = round >= fallback_round_ + settings_.sequential_fallback_rounds;
    const bool greedy_done = directPlan() || (best_schedule_ && fallback_done);
    if (settings_.method == Method::kOptimal && greedy_done) nextBestSearch();
    if (greedy_done) return;
    if (best_schedule_) {
      say(std::string("keeping the ") +
          (best_history_->sequential ? "sequential plan" : "plan with the robots parked out of every transition's way") +
          " (makespan " + secondsText(best_) + ") while looking for a direct one");
      continue;
    }
    if (!checkPlaceable()) return;
  }
}

}  // namespace dashbed::planner
