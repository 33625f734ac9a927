#pragma once
// The rounds of DaSH's high-level loop (paper: Method > Overview, Alg. 1) on a built
// representation; solve() (dash_planner.h) builds it and turns the outcome into a plan or a
// status. Each round, after the first expanding the motion hypergraph:
//  1. direct queries: Greedy's task plan (idle robots staying where they are, then parking at
//     home), each resolved by conflict resolution; a conflict no order resolves becomes a
//     scheduling constraint and the queries run again (constraints that leave no task plan
//     are dropped);
//  2. without a direct plan, the robots parking at home out of every transition's way (objects
//     relayed around them): a fallback plan;
//  3. with a fallback in hand, conflict resolution's second try on the round's shortest
//     failed direct task plans;
//  4. without any plan, the sequential queries (one object at a time; idle robots folded;
//     relays): the last resort, kept as a fallback while the next rounds look for a direct
//     plan (PlannerSettings::sequential_fallback_rounds);
//  5. MM-DaSH, once Greedy's rounds are done: Next-Best Search from Greedy's plan.
// A round without any plan checks whether an object can never be placed (infeasible).

#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "planner/planner_settings.h"
#include "planner/scheduling/scheduled_cbs.h"

namespace dashbed::planner {

class PlanningRounds {
 public:
  using Clock = std::chrono::steady_clock;
  /// `deadline`: the whole planner's; `direct_deadline`: where the direct queries stop while
  /// there is no plan (PlannerSettings::direct_time_share). `say`: one progress line (may be
  /// empty). The graph, settings and stats must outlive the rounds.
  PlanningRounds(MotionHypergraph& graph, const PlannerSettings& settings, PlannerStats& stats,
                 std::optional<Clock::time_point> deadline, std::optional<Clock::time_point> direct_deadline,
                 std::function<void(const std::string&)> say);
  // its budgets' stop tests refer to it
  PlanningRounds(const PlanningRounds&) = delete;
  PlanningRounds& operator=(const PlanningRounds&) = delete;

  /// Runs rounds until a plan is found (and, for MM-DaSH, improved), the rounds or the time
  /// run out, or an object turns out never placeable.
  void run();

  /// The best plan found: its task plan and conflict-free schedule (none without a plan).
  const std::optional<TransitionHistory>& bestHistory() const { return best_history_; }
  const std::optional<Schedule>& bestSchedule() const { return best_schedule_; }
  Millis bestMakespan() const { return best_; }
  /// Why the last task plan or query failed.
  const std::string& lastFailure() const { return last_failure_; }
  /// Of the greedy queries without a plan: the history that placed the most objects.
  const std::optional<TransitionHistory>& furthest() const { return furthest_; }
  /// Why an object can never be placed, when one can't ("" otherwise): the problem is infeasible.
  const std::string& neverPlaceable() const { return never_placeable_; }
  /// Whether the time budget is used up (the direct queries' share of it while they run).
  bool timeUp() const;

 private:
  SearchResult searchTimed(const std::function<SearchResult()>& query);
  bool resolve(const TransitionHistory& history, double focal_weight, bool second_try = false,
               NodeOrder order = NodeOrder::kMakespan);
  SearchResult greedyQuery(int round, QueryMode mode, HyperpathSearch::Relays relays = HyperpathSearch::Relays::kOff);
  bool directPlan() const { return best_history_ && !best_fallback_; }
  void directQueries(int round);
  void parkedClearOfHomes(int round);
  void secondTries();
  void sequentialQueries(int round);
  void nextBestSearch();
  bool checkPlaceable();
  void say(const std::string& line) const {
    if (say_) say_(line);
  }

  MotionHypergraph& graph_;
  const PlannerSettings& settings_;
  PlannerStats& stats_;
  std::optional<Clock::time_point> deadline_, direct_deadline_;
  std::function<void(const std::string&)> say_;
  bool direct_queries_ = false;  ///< while the direct queries of a round run without a plan so far
  SearchBudget search_budget_;
  ConflictResolutionBudget conflict_budget_;

  std::optional<TransitionHistory> best_history_;
  /// a fallback plan (sequential, or with the robots parked out of every transition's way) is
  /// kept while the next rounds' direct queries look for a shorter one
  bool best_fallback_ = false;
  std::optional<Schedule> best_schedule_;
  Millis best_ = std::numeric_limits<Millis>::max();
  std::string last_failure_ = "no task plan found";
  int fallback_round_ = 0;  ///< the round that found the first sequential plan
  std::optional<TransitionHistory> furthest_;
  std::string never_placeable_;
  std::vector<bool> checked_placeable_;  ///< [object] asked once: the answer never changes

  // this round's
  int feedbacks_ = 0;  ///< scheduling constraints fed back
  std::vector<TransitionHistory> failed_direct_;  ///< distinct direct task plans that failed
  std::uint64_t unconstrained_expansions_ = 0;    ///< of the last plan found without constraints
};

}  // namespace dashbed::planner
