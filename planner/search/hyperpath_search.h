#pragma once
// Hyperpath queries on the implicit transition-extended hypergraph (paper: Method >
// Transition-extended Hypergraph, Alg. 4; Method Variants > Task Planning).
//
// A search node is a transition history (its "head": the motion vertex of every body and the
// time it gets there). Its successors append one transition hyperarc whose tail is complete in
// the history — the robots and the object it needs are at the right task-space vertices, and
// for places and handoffs the object is held in the grasp the sample needs — preceded by the
// move hyperarcs bringing each robot to the sample's start. The transition starts at the latest
// of its tail's times (tail weight = max). Transitions that would touch an occupied object site
// are not available (vertex-hyperarc scheduling constraints); the site stays "busy" for the
// time the motion runs so that a later placement there waits for it. Nor is a transition that a
// scheduling constraint from conflict resolution pairs with one the history holds
// (MotionHypergraph::addSchedulingConstraint; a query started before a constraint was added may
// still hold histories that break it: start a new query).
//
// Route pruning. An object is only moved along its task-space route: picked by a robot from
// which its goal can be reached, handed to a robot nearer its goal (by the cost-to-go below)
// or, out of a hand that cannot place it, to one that has not held it yet. A place is only
// taken when its robot can go home afterwards around every object where the plan leaves them
// (every plan ends with the moves home; a place deep in a shelf can leave the arm where the
// roadmap cannot get it out). A history is abandoned when a holding robot cannot progress: it
// has no place or handoff sample for the grasp it holds the object in that keeps clear of the
// goal sites filled so far, or holding robots wait on each other in a cycle (each needs to
// hand its object to another holding robot); and when its last place took a goal site that
// every place sample of another object touches (a front slot filled before its back one), or
// that every pick sample of an object still at its start reaches over.
//
// Setting objects aside. An object with a set-aside site (ObjectSites::aside) may be set down
// there once and picked up again later, e.g. a shelf item standing where every pick of the one
// behind it reaches over it, that must go in only after that one (into the slot in front of
// it): a robot holding it would wait with it. The greedy query sets an object aside only after
// every other way on from a history, unless it waits for another to be placed (then with that
// object's other transitions, see greedy()); a holding robot that can set its object aside
// progresses (the dead-end check below).
//
// Cost-to-go (the A*-like query's heuristic): for each object and task-space vertex, the
// cheapest sum of sampled transition durations to its goal on the task-space hypergraph
// (objects only, robots assumed free: a lower bound on the remaining makespan for that
// object); unsampled hyperarcs count with the gripper dwell, a lower bound of any transition.
//
//  greedy()    Greedy hyperpath query: builds one history a hyperarc at a time, choosing the
//              transition that can start earliest (list scheduling; ties: fewer remaining
//              cost, then ids), with backtracking (depth first) when a history cannot be
//              completed. Transitions of an object whose goal site another object's places
//              all touch come after all others while that object is not placed: a robot that
//              picks a front object early holds it until the back one is in, and when the
//              back one needs that robot the history is a dead end found only deep down.
//  nextBest()  A*-like hyperpath query ordered by f = max(robot times, object time + cost to
//              go); successive calls return complete histories in order of nondecreasing
//              optimistic makespan (the next-best task plan of Next-Best Search, Alg. 5).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/motion/motion_hypergraph.h"
#include "planner/search/transition_history.h"

namespace dashbed::planner {

/// Limits of one query. Iteration caps make tests reproducible; users add a deadline.
struct SearchBudget {
  /// Histories one query may expand before it returns kBudget.
  std::uint64_t max_expansions = 100000;
  std::function<bool()> stop;  ///< returns true when time is up (may be empty)
};

enum class SearchStatus {
  kFound,      ///< a complete history (task plan) was found
  kExhausted,  ///< the current representation holds no (further) complete history
  kBudget,     ///< the budget ran out first
};

struct SearchResult {
  SearchStatus status = SearchStatus::kExhausted;
  std::optional<TransitionHistory> plan;  ///< complete, with the moves home
  std::uint64_t expansions = 0;
  /// greedy() without a plan: the first history it reached with the most objects at their
  /// goals, to say how far it got and which objects it left.
  std::optional<TransitionHistory> furthest;
};

/// How the robots of a plan share the workspace. The later modes are fallbacks for when conflict
/// resolution cannot order the robots of the plans before them.
enum class QueryMode {
  kDirect,      ///< every robot goes straight from one transition to the next
  kParkAtHome,  ///< a robot without an object goes home between transitions, to wait out of the way
  /// kParkAtHome with every transition keeping clear of the robots it does not need standing at
  /// home: a robot waiting there holds up no transition (conflict resolution orders the moves
  /// past it), so robots crowding each other's workspaces still work at once; a row of robots
  /// relays objects through the ones in between (Relays)
  kParkClearOfHomes,
  /// the steps run one after another (TransitionHistory::sequential): only the robots of one
  /// step move at any time, the others wait at home (holding their object, if any); a second
  /// object is picked up only when no other choice is left (conflict resolution may then let
  /// the steps of different robots overlap, see SequentialSteps)
  kSequential,
  /// kSequential with the waiting robots folded back (IdlePose::kFolded), out of the way of
  /// the others where their homes reach into the shared workspace: every robot folds at the
  /// start and unfolds at the end
  kSequentialFolded,
};

/// The steps of a history in this mode run one after another.
inline bool isSequential(QueryMode mode) {
  return mode == QueryMode::kSequential || mode == QueryMode::kSequentialFolded;
}

/// The transitions of a plan in this mode keep clear of the robots standing idle (in the
/// sequential modes, the moves too: HyperpathSearch::aroundIdle).
inline bool keepsClearOfIdle(QueryMode mode) { return mode == QueryMode::kParkClearOfHomes || isSequential(mode); }

class HyperpathSearch {
 public:
  /// Keeping clear of idle robots, kAroundIdleRobots lets a robot whose every handoff nearer the
  /// goal runs into them hand the object to one no nearer (a fallback: it lengthens plans).
  enum class Relays { kOff, kAroundIdleRobots };
  /// `graph` is extended on demand (transitions sampled, moves planned) and must outlive the
  /// search.
  explicit HyperpathSearch(MotionHypergraph& graph, QueryMode mode = QueryMode::kDirect, Relays relays = Relays::kOff);
  ~HyperpathSearch();

  SearchResult greedy(const SearchBudget& budget);
  /// The next-best complete history of the A*-like query (the frontier is kept between calls).
  SearchResult nextBest(const SearchBudget& budget);

  /// Cost-to-go of object o at task-space vertex v [ms] (infinite: -1); at the resting vertex,
  /// from its start.
  Millis costToGo(int object, int task_vertex) const;
  /// Cost-to-go of an object where a history has it (0 at its goal; infinite: -1).
  Millis costToGo(const TransitionHistory& history, int object) const;
  /// The objects that go before `object` (see greedy()): every usable place sample of theirs
  /// so far touches its goal site, as a place into the back of a shelf passes through the
  /// front slot. Samples nothing for this.
  const std::vector<int>& placedBefore(int object);

 private:
  struct Candidate;
  struct AStarState;
  /// The virtual source's history in this query's mode (with idle robots folded, after every
  /// robot has folded), or std::nullopt when a robot finds no way to fold.
  std::optional<TransitionHistory> source();
  /// The rest pose of a sample's hyperarc (start, goal, set-aside; none for a handoff).
  RestPose restPose(const TransitionSample& sample) const;
  std::vector<Candidate> candidates(const TransitionHistory& history);
  std::optional<TransitionHistory> apply(const TransitionHistory& history, const Candidate& candidate);
  std::optional<TransitionHistory> finish(const TransitionHistory& history);
  /// A scheduling constraint keeps `transition` out of the history: the history holds a
  /// transition paired with it, or a robot it must wait for still stands at home.
  bool excluded(const TransitionHistory& history, int transition) const;
  /// In this query's modes keeping clear of idle robots (keepsClearOfIdle): the motions of
  /// `transition` run into a robot it does not need, standing idle as it does while the
  /// transition runs (MotionHypergraph::clearOfIdle).
  bool blockedByIdleRobots(int transition) const;
  /// Where this query's robots wait between their steps (the parking and sequential modes).
  IdlePose idlePose() const;
  /// The robots this query's moves keep clear of, standing idle (keepsClearOfIdle), or none
  /// (MotionHypergraph::move's around_idle).
  std::optional<IdlePose> aroundIdle() const;
  bool deadlocked(const TransitionHistory& history) const;
  /// The handoff hyperarc `arc` may take the object from its giver: towards the goal (by the
  /// cost to go), or away from it (or no nearer) out of a hand that cannot place it
  /// (placeBlocked) or, with relays, hand it nearer (nearerHandoffsBlocked) to a robot that has
  /// not held it before.
  bool handoffAllowed(const TransitionHistory& history, const TransitionHyperarc& arc) const;
  /// `robot` can go to where it rests after a place from `q` once every object is where the
  /// plan leaves it (the moves of the current round's roadmaps): home, or in a sequential query
  /// where it waits, clear of the other robots waiting (a place it cannot leave would end every
  /// history through it without a final move, after the search has ordered all other steps).
  bool restReachable(int robot, const core::ArmConfig& q);
  /// A transition the plan can use: a place only when its robot can get to where it rests from
  /// where the place leaves it (restReachable; a robot placing into a shelf slot right in front
  /// of it may end in a pose the roadmap cannot bring back); picks and handoffs always. Asks the roadmap once per
  /// round and transition, when the search first applies it.
  bool usable(int transition);
  /// A place that usable() found unusable this round. Asks no roadmap: the deadlock check and
  /// placeBlocked run on every child, and their queries would spend the roadmaps' growth of the
  /// round on places the search may never try.
  bool knownUnusable(int transition) const;
  /// A sample a history with the goal sites `filled` may still take: it keeps clear of them, is
  /// not known to be unusable (knownUnusable; only places can be) and does not run into the
  /// robots standing idle (blockedByIdleRobots). Asks no roadmap.
  bool stillUsable(int transition, const SiteSet& filled) const;
  /// This round's entry of `transition` in usable_ (the cache is cleared when a round begins).
  signed char& usableEntry(int transition) const;
  /// `robot` has a place hyperarc for `object` but no sample of it for `grasp` (sampled on
  /// demand) that is not known to be unusable and keeps clear of the goal sites the history
  /// has filled (objects stay at their goals).
  bool placeBlocked(const TransitionHistory& history, int robot, int object, int grasp) const;
  /// With Relays::kAroundIdleRobots (in the modes keeping clear of idle robots): `robot` has no
  /// place hyperarc for `object`, and no sample (sampled on demand) of its handoffs of it in
  /// `grasp` to a robot nearer the goal (by the cost to go) keeps clear of the goal sites the
  /// history has filled and of the robots standing idle.
  /// With three robots in a row, an end robot's handoffs straight to the other end pass over the
  /// middle one waiting at home; the middle robot, by the fastest handoffs, is no nearer the
  /// goal, but relaying the object through it is the way on.
  bool nearerHandoffsBlocked(const TransitionHistory& history, int robot, int object, int grasp) const;
  Millis lowerBound(const TransitionHistory& history) const;
  /// cost_to_go_ from the fastest sample of every hyperarc, when transitions were sampled since
  /// it was made; cost_to_go_version_ counts its changes.
  void updateCostToGo();
  /// The A*-like query's frontier keyed again by lowerBound, after the cost-to-go changed.
  void rekeyFrontier();
  /// placed_before_ from the place samples so far, when there are new ones.
  void updatePlacementOrder();

  MotionHypergraph* graph_;
  QueryMode mode_;
  Relays relays_;
  SiteSet final_occupancy_;  ///< goal sites, and the start sites of objects without a goal
  std::vector<int> place_hyperarc_;  ///< [robot * objects + object] its place hyperarc, or -1
  std::vector<std::vector<Millis>> cost_to_go_;  // [object][task vertex], -1 = unreachable
  std::vector<Millis> aside_cost_to_go_;         // [object] from its set-aside site, -1 = unreachable
  std::size_t cost_to_go_transitions_ = 0;  ///< transitions sampled when cost_to_go_ was made
  std::uint64_t cost_to_go_version_ = 0;      ///< changes of cost_to_go_ so far
  std::vector<std::vector<int>> placed_before_;  ///< [object] see placedBefore()
  std::size_t placement_order_transitions_ = 0;  ///< transitions sampled when placed_before_ was made
  mutable std::vector<signed char> usable_;  ///< [transition] usable() this round: 1, 0, -1 unknown
  mutable int usable_round_ = 0;
  std::unique_ptr<AStarState> astar_;
};

}  // namespace dashbed::planner
