#include "planner/search/hyperpath_search.h"

#include <algorithm>
#include <limits>
#include <map>
#include <queue>
#include <tuple>

namespace dashbed::planner {

/// A transition that can extend a history, with the key the greedy query orders by.
struct HyperpathSearch::Candidate {
  int transition = -1;
  Millis start = 0;       ///< lower bound of the start (estimate), or the exact start once evaluated
  Millis remaining = 0;   ///< the object's cost to go before the transition (critical path first)
  bool exact = false;
  /// the object has to wait for another one to be placed first (placedBefore)
  bool waits = false;
  /// it sets the object aside, the last resort: after every other way on from the history
  bool set_aside = false;

  auto key() const { return std::make_tuple(set_aside, waits, start, -remaining, transition); }
};

/// The A*-like query's frontier, kept between nextBest() calls.
struct HyperpathSearch::AStarState {
  struct Entry {
    Millis f;
    std::uint64_t order;  // insertion order: ties pop first-in first
    std::size_t node;
    bool operator>(const Entry& other) const { return std::tie(f, order) > std::tie(other.f, other.order); }
  };
  std::vector<TransitionHistory> nodes;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> frontier;
  std::uint64_t pushed = 0;
  std::uint64_t keyed_version = 0;  ///< the cost-to-go version the frontier's keys come from
  /// Dominance: histories with the same key (nextBest's signature: the bodies' vertices and what
  /// decides which transitions may follow), by their times.
  std::map<std::vector<long long>, std::vector<std::vector<Millis>>> seen;
};

namespace {

constexpr Millis kUnreachable = -1;
/// Samples per hyperarc and grasp the A*-like query branches on (the fastest ones).
constexpr std::size_t kAStarSamplesPerHyperarc = 2;

/// The site a place hyperarc puts its object down at: its goal or set-aside site.
int placeSite(const TransitionHyperarc& arc) {
  return arc.rest_pose == RestPose::kAside ? ObjectSites::asideSite(arc.object) : ObjectSites::goalSite(arc.object);
}

}  // namespace

HyperpathSearch::HyperpathSearch(MotionHypergraph& graph, QueryMode mode, Relays relays)
    : graph_(&graph),
      mode_(mode),
      relays_(keepsClearOfIdle(mode) ? relays : Relays::kOff),
      final_occupancy_(graph.sites().numSites()),
      placed_before_(static_cast<std::size_t>(graph.taskSpace().numObjects())) {
  for (int o = 0; o < graph.sites().numObjects(); ++o) {
    final_occupancy_.set(graph.sites().goal[o] ? ObjectSites::goalSite(o) : ObjectSites::startSite(o));
  }
  const TaskSpaceHypergraph& ts = graph.taskSpace();
  place_hyperarc_.assign(static_cast<std::size_t>(ts.numRobots() * ts.numObjects()), -1);
  for (std::size_t h = 0; h < ts.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = ts.hyperarcs()[h];
    int& place = place_hyperarc_[static_cast<std::size_t>(arc.robot * ts.numObjects() + arc.object)];
    if (arc.kind == TransitionKind::kPlace && arc.rest_pose == RestPose::kGoal && place < 0) place = static_cast<int>(h);
  }
  updateCostToGo();
}
HyperpathSearch::~HyperpathSearch() = default;

std::optional<TransitionHistory> HyperpathSearch::source() {
  TransitionHistory history = TransitionHistory::source(*graph_);
  history.sequential = isSequential(mode_);
  history.idle = idlePose();
  if (history.sequential && history.idle == IdlePose::kFolded) {
    // every robot folds at once (conflict resolution orders them if they meet); the first step
    // waits for all of them
    const SiteSet occupied = history.occupied(graph_->sites().numSites());
    for (std::size_t r = 0; r < history.robots.size(); ++r) {
      TransitionHistory::RobotState& robot = history.robots[r];
      const core::ArmConfig& folded = graph_->idleConfiguration(static_cast<int>(r), IdlePose::kFolded);
      const Move* fold = folded == robot.q ? nullptr : graph_->move(static_cast<int>(r), -1, -1, robot.q, folded, occupied);
      if (folded != robot.q && fold == nullptr) return std::nullopt;
      history.fold_moves.push_back(fold);
      if (fold != nullptr) robot = {folded, fold->duration, -1, -1};
    }
  }
  return history;
}

IdlePose HyperpathSearch::idlePose() const {
  return mode_ == QueryMode::kSequentialFolded ? IdlePose::kFolded : IdlePose::kHome;
}

void HyperpathSearch::updatePlacementOrder() {
  if (placement_order_transitions_ == graph_->numTransitions()) return;
  placement_order_transitions_ = graph_->numTransitions();
  const int objects = graph_->taskSpace().numObjects();
  placed_before_.assign(static_cast<std::size_t>(objects), {});
  // the place samples so far (none is sampled for this alone) that a plan may use
  std::vector<std::vector<int>> places(static_cast<std::size_t>(objects));
  for (int id = 0; id < static_cast<int>(placement_order_transitions_); ++id) {
    const TransitionSample& sample = graph_->transition(id).sample;
    if (restPose(sample) == RestPose::kGoal && !knownUnusable(id)) places[sample.object].push_back(id);
  }
  for (int first = 0; first < objects; ++first) {
    if (places[first].empty()) continue;
    for (int then = 0; then < objects; ++then) {
      if (then == first || !graph_->sites().goal[then]) continue;
      const bool blocked = std::all_of(places[first].begin(), places[first].end(), [&](int id) {
        return graph_->transition(id).sample.touches.test(ObjectSites::goalSite(then));
      });
      if (blocked) placed_before_[then].push_back(first);
    }
  }
}

const std::vector<int>& HyperpathSearch::placedBefore(int object) {
  updatePlacementOrder();
  return placed_before_.at(static_cast<std::size_t>(object));
}

Millis HyperpathSearch::costToGo(int object, int task_vertex) const {
  return cost_to_go_.at(object).at(task_vertex);
}

Millis HyperpathSearch::costToGo(const TransitionHistory& history, int object) const {
  const TransitionHistory::ObjectState& state = history.objects.at(static_cast<std::size_t>(object));
  switch (state.place) {
    case ObjectPlace::kStart: return costToGo(object, graph_->taskSpace().objectRestingVertex(object));
    case ObjectPlace::kHeld: return costToGo(object, graph_->taskSpace().holdingVertex(state.holder, object));
    case ObjectPlace::kAside: return aside_cost_to_go_.at(static_cast<std::size_t>(object));
    case ObjectPlace::kGoal: break;
  }
  return 0;
}

RestPose HyperpathSearch::restPose(const TransitionSample& sample) const {
  return graph_->taskSpace().hyperarcs().at(static_cast<std::size_t>(sample.hyperarc)).rest_pose;
}

void HyperpathSearch::updateCostToGo() {
  if (!cost_to_go_.empty() && graph_->numTransitions() == cost_to_go_transitions_) return;
  const TaskSpaceHypergraph& ts = graph_->taskSpace();
  const ObjectSites& sites = graph_->sites();
  const Millis dwell = ceilMillis(graph_->settings().transitions.gripper_dwell);
  const auto duration = [&](int h) { return graph_->bestDuration(h).value_or(dwell); };
  cost_to_go_transitions_ = graph_->numTransitions();
  const std::vector<std::vector<Millis>> before = std::move(cost_to_go_);
  const std::vector<Millis> aside_before = std::move(aside_cost_to_go_);
  cost_to_go_.assign(ts.numObjects(), std::vector<Millis>(ts.numVertices(), kUnreachable));
  aside_cost_to_go_.assign(ts.numObjects(), kUnreachable);
  for (int o = 0; o < ts.numObjects(); ++o) {
    std::vector<Millis>& cost = cost_to_go_[o];
    if (!sites.goal[o]) {
      cost[ts.objectRestingVertex(o)] = 0;  // stays where it is
      continue;
    }
    const auto relax = [&](int v, Millis c) {
      if (cost[v] == kUnreachable || c < cost[v]) {
        cost[v] = c;
        return true;
      }
      return false;
    };
    // Bellman-Ford backwards from the goal over this object's vertices (at most n robots deep),
    // without setting it aside (the resting vertex stands for its start here)
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t h = 0; h < ts.numHyperarcs(); ++h) {
        const TransitionHyperarc& arc = ts.hyperarcs()[h];
        if (arc.object != o || arc.rest_pose == RestPose::kAside) continue;
        const int hi = static_cast<int>(h);
        if (arc.kind == TransitionKind::kPlace) {
          changed |= relax(ts.holdingVertex(arc.robot, o), duration(hi));
        } else if (arc.kind == TransitionKind::kHandoff) {
          const Millis after = cost[ts.holdingVertex(arc.receiver, o)];
          if (after != kUnreachable) changed |= relax(ts.holdingVertex(arc.robot, o), duration(hi) + after);
        } else {
          const Millis after = cost[ts.holdingVertex(arc.robot, o)];
          if (after != kUnreachable) changed |= relax(ts.objectRestingVertex(o), duration(hi) + after);
        }
      }
    }
    // set aside: picked up again from there
    for (std::size_t h = 0; h < ts.numHyperarcs(); ++h) {
      const TransitionHyperarc& arc = ts.hyperarcs()[h];
      if (arc.object != o || arc.kind != TransitionKind::kPick || arc.rest_pose != RestPose::kAside) continue;
      const Millis after = cost[ts.holdingVertex(arc.robot, o)];
      Millis& aside = aside_cost_to_go_[static_cast<std::size_t>(o)];
      if (after != kUnreachable && (aside == kUnreachable || duration(static_cast<int>(h)) + after < aside)) {
        aside = duration(static_cast<int>(h)) + after;
      }
    }
  }
  if (cost_to_go_ != before || aside_cost_to_go_ != aside_before) ++cost_to_go_version_;
}

void HyperpathSearch::rekeyFrontier() {
  AStarState& a = *astar_;
  std::vector<AStarState::Entry> entries;
  for (; !a.frontier.empty(); a.frontier.pop()) entries.push_back(a.frontier.top());
  for (AStarState::Entry& entry : entries) {
    // a complete history's key is its makespan; the others' bounds move with the cost-to-go
    // (down for a faster sample, up where a hyperarc's first sample replaces the dwell time)
    if (a.nodes[entry.node].final_moves.empty()) entry.f = lowerBound(a.nodes[entry.node]);
    a.frontier.push(entry);
  }
  a.keyed_version = cost_to_go_version_;
}

std::vector<HyperpathSearch::Candidate> HyperpathSearch::candidates(const TransitionHistory& history) {
  const TaskSpaceHypergraph& ts = graph_->taskSpace();
  const ObjectSites& sites = graph_->sites();
  const SiteSet occupied = history.occupied(sites.numSites());
  updatePlacementOrder();
  const bool holding = std::any_of(history.robots.begin(), history.robots.end(),
                                   [](const TransitionHistory::RobotState& r) { return r.object >= 0; });
  const auto waits_for_others = [&](int o) {  // an object whose goal needs another placed first
    return std::any_of(placed_before_[o].begin(), placed_before_[o].end(), [&](int first) {
      return history.objects[first].place != ObjectPlace::kGoal;
    });
  };
  // in a sequential history a second object goes on the move only for an object in hand that
  // must wait for it (a shelf item whose pick sweeps over the start of one that goes in after
  // it): an object in hand that could go on but finds no way is a dead end, not a reason to
  // start on another (the search would order every step after it before finding out)
  const bool second_pick = !history.sequential || std::all_of(history.robots.begin(), history.robots.end(),
                                                              [&](const TransitionHistory::RobotState& r) {
                                                                return r.object < 0 || waits_for_others(r.object);
                                                              });
  std::vector<Candidate> result;
  for (std::size_t h = 0; h < ts.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = ts.hyperarcs()[h];
    const int o = arc.object;
    if (!sites.goal[o]) continue;
    const TransitionHistory::ObjectState& object = history.objects[o];
    const TransitionHistory::RobotState& robot = history.robots[arc.robot];
    // after the others: an object whose goal needs another placed first, and in a sequential
    // history a second object on the move
    const bool waits = waits_for_others(o) || (history.sequential && arc.kind == TransitionKind::kPick && holding);
    const bool aside = arc.rest_pose == RestPose::kAside;
    // setting an object aside is the last resort, except for one that waits for others (it comes
    // after the others' transitions, as its other ones do)
    const bool last_resort = aside && arc.kind == TransitionKind::kPlace && !waits_for_others(o);
    int grasp = -1;
    const Millis before = costToGo(history, o);  // the object's cost to go before the transition
    switch (arc.kind) {
      case TransitionKind::kPick:
        if (object.place != (aside ? ObjectPlace::kAside : ObjectPlace::kStart) || robot.object != -1 || !second_pick) continue;
        if (costToGo(o, ts.holdingVertex(arc.robot, o)) == kUnreachable) continue;
        break;
      case TransitionKind::kPlace:
        if (robot.object != o || (aside && object.set_aside)) continue;
        grasp = robot.grasp;
        break;
      case TransitionKind::kHandoff:
        if (robot.object != o || history.robots[arc.receiver].object != -1) continue;
        grasp = robot.grasp;
        if (before == kUnreachable || !handoffAllowed(history, arc)) continue;
        break;
    }
    for (const int id : graph_->transitionsOf(static_cast<int>(h), grasp)) {
      const TransitionSample& sample = graph_->transition(id).sample;
      if (sample.touches.intersects(occupied) || excluded(history, id)) continue;
      Millis start = object.since;
      for (const TransitionMotion& motion : sample.motions) {
        const TransitionHistory::RobotState& r = history.robots[motion.robot];
        start = std::max(start, r.free + restToRestDuration(r.q, motion.start(), graph_->timing()));
      }
      if (arc.kind == TransitionKind::kPlace) start = std::max(start, history.site_busy[placeSite(arc)]);
      result.push_back({id, start, before, false, waits, last_resort});
    }
  }
  return result;
}

bool HyperpathSearch::handoffAllowed(const TransitionHistory& history, const TransitionHyperarc& arc) const {
  const TaskSpaceHypergraph& ts = graph_->taskSpace();
  const int o = arc.object;
  const Millis before = costToGo(o, ts.holdingVertex(arc.robot, o));
  const Millis after = costToGo(o, ts.holdingVertex(arc.receiver, o));
  if (after == kUnreachable) return false;
  if (after < before) return true;
  // away from the goal only out of a hand that cannot place the object (nor, where it has no
  // place hyperarc, hand it nearer the goal), and never back to a robot that held it before
  // (the two would hand it back and forth)
  if (!placeBlocked(history, arc.robot, o, history.robots[arc.robot].grasp) &&
      !nearerHandoffsBlocked(history, arc.robot, o, history.robots[arc.robot].grasp)) {
    return false;
  }
  return std::none_of(history.steps.begin(), history.steps.end(), [&](const ScheduledTransition& step) {
    const TransitionSample& sample = graph_->transition(step.transition).sample;
    return sample.object == o && sample.holderAfter() == arc.receiver;
  });
}

bool HyperpathSearch::restReachable(int robot, const core::ArmConfig& q) {
  const std::optional<IdlePose> around = aroundIdle();
  const core::ArmConfig& rest = graph_->idleConfiguration(robot, around.value_or(IdlePose::kHome));
  return q == rest || graph_->move(robot, -1, -1, q, rest, final_occupancy_, around) != nullptr;
}

signed char& HyperpathSearch::usableEntry(int transition) const {
  if (usable_round_ != graph_->rounds()) {  // a new round: new roadmaps, new moves
    usable_.clear();
    usable_round_ = graph_->rounds();
  }
  if (usable_.size() <= static_cast<std::size_t>(transition)) usable_.resize(static_cast<std::size_t>(transition) + 1, -1);
  return usable_[static_cast<std::size_t>(transition)];
}

bool HyperpathSearch::usable(int transition) {
  const TransitionSample& sample = graph_->transition(transition).sample;
  if (sample.kind != TransitionKind::kPlace) return true;
  signed char& known = usableEntry(transition);
  if (known < 0) known = restReachable(sample.motions[0].robot, sample.motions[0].end()) ? 1 : 0;
  return known == 1;
}

bool HyperpathSearch::knownUnusable(int transition) const { return usableEntry(transition) == 0; }

bool HyperpathSearch::placeBlocked(const TransitionHistory& history, int robot, int object, int grasp) const {
  const int place = place_hyperarc_[static_cast<std::size_t>(robot * graph_->taskSpace().numObjects() + object)];
  // no place hyperarc: the cost to go says where the object should go
  if (place < 0) return false;
  const SiteSet filled = history.filledGoals(graph_->sites().numSites());
  const std::vector<int>& ids = graph_->transitionsOf(place, grasp);
  return std::none_of(ids.begin(), ids.end(), [&](int id) { return stillUsable(id, filled); });
}

bool HyperpathSearch::nearerHandoffsBlocked(const TransitionHistory& history, int robot, int object, int grasp) const {
  const TaskSpaceHypergraph& ts = graph_->taskSpace();
  if (relays_ == Relays::kOff || place_hyperarc_[static_cast<std::size_t>(robot * ts.numObjects() + object)] >= 0) {
    return false;
  }
  const Millis before = costToGo(object, ts.holdingVertex(robot, object));
  const SiteSet filled = history.filledGoals(graph_->sites().numSites());
  for (std::size_t h = 0; h < ts.numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = ts.hyperarcs()[h];
    if (arc.kind != TransitionKind::kHandoff || arc.robot != robot || arc.object != object) continue;
    const Millis after = costToGo(object, ts.holdingVertex(arc.receiver, object));
    if (after == kUnreachable || after >= before) continue;
    const std::vector<int>& ids = graph_->transitionsOf(static_cast<int>(h), grasp);
    if (std::any_of(ids.begin(), ids.end(), [&](int id) { return stillUsable(id, filled); })) return false;
  }
  return true;
}

bool HyperpathSearch::stillUsable(int transition, const SiteSet& filled) const {
  return !graph_->transition(transition).sample.touches.intersects(filled) && !knownUnusable(transition) &&
         !blockedByIdleRobots(transition);
}

std::optional<IdlePose> HyperpathSearch::aroundIdle() const {
  return isSequential(mode_) ? std::optional(idlePose()) : std::nullopt;
}

bool HyperpathSearch::blockedByIdleRobots(int transition) const {
  if (!keepsClearOfIdle(mode_)) return false;
  const std::vector<TransitionMotion>& motions = graph_->transition(transition).sample.motions;
  for (int r = 0; r < graph_->scene().numRobots(); ++r) {
    const bool idle = std::none_of(motions.begin(), motions.end(), [&](const TransitionMotion& m) { return m.robot == r; });
    if (idle && !graph_->clearOfIdle(transition, r, idlePose())) return true;
  }
  return false;
}

bool HyperpathSearch::excluded(const TransitionHistory& history, int transition) const {
  const auto& robots = graph_->world().world->robots;
  const std::vector<TransitionMotion>& motions = graph_->transition(transition).sample.motions;
  if (blockedByIdleRobots(transition)) return true;
  for (std::size_t r = 0; r < history.robots.size(); ++r) {
    // a robot that has not acted yet stands at home; in a sequential history, every robot the
    // transition does not need waits there (or folded, where blockedByIdleRobots keeps it clear)
    const bool idle =
        std::none_of(motions.begin(), motions.end(), [&](const TransitionMotion& m) { return m.robot == static_cast<int>(r); });
    const bool at_home = history.sequential ? idle && history.idle == IdlePose::kHome
                                            : history.robots[r].free == 0 && history.robots[r].q == robots[r].home;
    if (at_home && graph_->homeConflict(transition, static_cast<int>(r))) return true;
  }
  return std::any_of(history.steps.begin(), history.steps.end(), [&](const ScheduledTransition& step) {
    return graph_->schedulingConflict(step.transition, transition);
  });
}

std::optional<TransitionHistory> HyperpathSearch::apply(const TransitionHistory& history, const Candidate& candidate) {
  const MotionTransition& transition = graph_->transition(candidate.transition);
  const TransitionSample& sample = transition.sample;
  if (!usable(candidate.transition)) return std::nullopt;
  const ObjectSites& sites = graph_->sites();
  const SiteSet occupied = history.occupied(sites.numSites());
  const int o = sample.object;
  TransitionHistory next = history;

  // objects whose start (or set-aside) sites a motion touches must have left them before it
  // starts
  const auto after_left = [&](const SiteSet& touches, Millis t) {
    for (int b = 0; b < sites.numObjects(); ++b) {
      const bool left_aside = history.objects[b].set_aside && touches.test(ObjectSites::asideSite(b));
      if (touches.test(ObjectSites::startSite(b)) || left_aside) t = std::max(t, history.objects[b].since);
    }
    return t;
  };
  // ... and goal and set-aside sites it touches stay busy until it ends
  const auto mark_busy = [&](const SiteSet& touches, Millis end) {
    for (int b = 0; b < sites.numObjects(); ++b) {
      for (const int s : {ObjectSites::goalSite(b), ObjectSites::asideSite(b)}) {
        if (touches.test(s)) next.site_busy[s] = std::max(next.site_busy[s], end);
      }
    }
  };

  ScheduledTransition step;
  step.transition = candidate.transition;
  Millis start = history.objects[o].since;
  for (const TransitionMotion& motion : sample.motions) {
    const TransitionHistory::RobotState& r = history.robots[motion.robot];
    // the way to the transition's start: direct, or home (folded) first to wait out of the way
    const core::ArmConfig& idle = graph_->idleConfiguration(motion.robot, idlePose());
    std::vector<core::ArmConfig> stops{r.q, motion.start()};
    // in a sequential history a robot waits idle (holding its object, if any) while other
    // robots' steps run: it went there after its last step unless it had the step just before
    bool park = mode_ != QueryMode::kDirect && r.object < 0;
    if (history.sequential && !history.steps.empty()) {
      const std::vector<TransitionMotion>& last = graph_->transition(history.steps.back().transition).sample.motions;
      park = std::none_of(last.begin(), last.end(), [&](const TransitionMotion& m) { return m.robot == motion.robot; });
    }
    if (park && r.q != idle && motion.start() != idle) stops = {r.q, idle, motion.start()};
    std::vector<const Move*> moves;
    Millis t = r.free;
    if (history.sequential) {  // once the step before has ended
      for (const TransitionHistory::RobotState& other : history.robots) t = std::max(t, other.free);
    }
    for (std::size_t k = 1; k < stops.size(); ++k) {
      const Move* move = graph_->move(motion.robot, r.object, r.grasp, stops[k - 1], stops[k], occupied, aroundIdle());
      if (move == nullptr) return std::nullopt;
      t = after_left(move->touches, t);
      mark_busy(move->touches, t + move->duration);
      t += move->duration;
      moves.push_back(move);
    }
    step.moves.push_back(std::move(moves));
    start = std::max(start, t);
  }
  const TransitionHyperarc& arc = graph_->taskSpace().hyperarcs().at(static_cast<std::size_t>(sample.hyperarc));
  if (sample.kind == TransitionKind::kPlace) start = std::max(start, history.site_busy[placeSite(arc)]);
  start = after_left(sample.touches, start);
  step.start = start;
  const Millis end = start + sample.duration;
  mark_busy(sample.touches, end);

  for (const TransitionMotion& motion : sample.motions) {
    next.robots[motion.robot].q = motion.end();
    next.robots[motion.robot].free = end;
  }
  const auto holder_grasp = [&](int head_index) { return graph_->vertex(transition.head[head_index]).grasp; };
  TransitionHistory::ObjectState& object = next.objects[o];
  object.since = end;
  switch (sample.kind) {
    case TransitionKind::kPick:
      object.place = ObjectPlace::kHeld;
      object.holder = sample.motions[0].robot;
      next.robots[object.holder].object = o;
      next.robots[object.holder].grasp = holder_grasp(0);
      break;
    case TransitionKind::kPlace:
      object.place = arc.rest_pose == RestPose::kAside ? ObjectPlace::kAside : ObjectPlace::kGoal;
      object.set_aside |= object.place == ObjectPlace::kAside;
      next.robots[object.holder].object = next.robots[object.holder].grasp = -1;
      object.holder = -1;
      break;
    case TransitionKind::kHandoff:
      next.robots[object.holder].object = next.robots[object.holder].grasp = -1;
      object.holder = sample.motions[1].robot;
      next.robots[object.holder].object = o;
      next.robots[object.holder].grasp = holder_grasp(1);
      break;
  }
  next.steps.push_back(std::move(step));
  return next;
}

std::optional<TransitionHistory> HyperpathSearch::finish(const TransitionHistory& history) {
  TransitionHistory done = history;
  const SiteSet occupied = history.occupied(graph_->sites().numSites());
  const bool folded = history.sequential && history.idle == IdlePose::kFolded;
  for (std::size_t r = 0; r < history.robots.size(); ++r) {
    const int robot = static_cast<int>(r);
    const TransitionHistory::RobotState& state = history.robots[r];
    // home, or folded first while the others still finish, then home with all of them
    const core::ArmConfig& rest = graph_->idleConfiguration(robot, folded ? IdlePose::kFolded : IdlePose::kHome);
    const Move* move = state.q == rest ? nullptr : graph_->move(robot, -1, -1, state.q, rest, occupied, aroundIdle());
    if (state.q != rest && move == nullptr) return std::nullopt;
    done.final_moves.push_back(move);
    done.final_starts.push_back(state.free);
    if (!folded) continue;
    const core::ArmConfig& home = graph_->world().world->robots[r].home;
    const Move* unfold = rest == home ? nullptr : graph_->move(robot, -1, -1, rest, home, occupied);
    if (rest != home && unfold == nullptr) return std::nullopt;
    done.unfold_moves.push_back(unfold);
  }
  return done;
}

bool HyperpathSearch::deadlocked(const TransitionHistory& history) const {
  // A holding robot progresses when it can place its object, or hand it (towards the goal) to
  // a robot that is free or itself progresses, with a sample for the grasp it holds the object
  // in that keeps clear of the goal sites filled so far (an object stays at its goal). Holding
  // robots that cannot progress are a dead end: a pick in a grasp nothing continues from, or
  // robots waiting on each other in a cycle.
  // After a place: an object none of whose place samples (any robot, any grasp seen) avoids
  // the goal sites taken so far can never be placed.
  const TaskSpaceHypergraph& ts = graph_->taskSpace();
  const std::size_t n = history.robots.size();
  const SiteSet placed = history.filledGoals(graph_->sites().numSites());
  const auto available = [&](std::size_t h, int grasp) {
    const std::vector<int>& ids = graph_->transitionsOf(static_cast<int>(h), grasp);
    return std::any_of(ids.begin(), ids.end(), [&](int id) { return stillUsable(id, placed); });
  };
  std::vector<bool> progresses(n, false);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t h = 0; h < ts.numHyperarcs(); ++h) {
      const TransitionHyperarc& arc = ts.hyperarcs()[h];
      const int r = arc.robot;
      if (progresses[r] || history.robots[r].object != arc.object || arc.kind == TransitionKind::kPick) continue;
      // a place into the goal, or setting the object aside (once)
      bool ok = arc.kind == TransitionKind::kPlace &&
                (arc.rest_pose == RestPose::kGoal || !history.objects[arc.object].set_aside);
      if (arc.kind == TransitionKind::kHandoff) {
        ok = handoffAllowed(history, arc) &&
             (history.robots[arc.receiver].object == -1 || progresses[arc.receiver]);
      }
      if (ok && available(h, history.robots[r].grasp)) progresses[r] = changed = true;
    }
  }
  for (std::size_t r = 0; r < n; ++r) {
    if (history.robots[r].object != -1 && !progresses[r]) return true;
  }
  if (history.steps.empty() ||
      restPose(graph_->transition(history.steps.back().transition).sample) != RestPose::kGoal) {
    return false;
  }
  for (std::size_t o = 0; o < history.objects.size(); ++o) {
    const int oi = static_cast<int>(o);
    const ObjectPlace place = history.objects[o].place;
    if (!graph_->sites().goal[o] || place == ObjectPlace::kGoal) continue;
    if (place == ObjectPlace::kStart || place == ObjectPlace::kAside) {  // every pick reaches over a filled goal site
      const RestPose from = place == ObjectPlace::kStart ? RestPose::kStart : RestPose::kAside;
      bool pickable = false;
      for (std::size_t h = 0; h < ts.numHyperarcs() && !pickable; ++h) {
        const TransitionHyperarc& arc = ts.hyperarcs()[h];
        if (arc.kind == TransitionKind::kPick && arc.object == oi && arc.rest_pose == from) pickable = available(h, -1);
      }
      if (!pickable) return true;
    }
    bool placeable = false;
    for (std::size_t h = 0; h < ts.numHyperarcs() && !placeable; ++h) {
      const TransitionHyperarc& arc = ts.hyperarcs()[h];
      if (arc.kind != TransitionKind::kPlace || arc.object != oi || arc.rest_pose != RestPose::kGoal) continue;
      // by index: sampling may add grasps
      for (std::size_t g = 0; g < graph_->graspsOf(oi).size() && !placeable; ++g) {
        placeable = available(h, static_cast<int>(g));
      }
    }
    if (!placeable) return true;
  }
  return false;
}

Millis HyperpathSearch::lowerBound(const TransitionHistory& history) const {
  Millis bound = 0;
  for (std::size_t r = 0; r < history.robots.size(); ++r) {
    const TransitionHistory::RobotState& robot = history.robots[r];
    bound = std::max(bound, robot.free + restToRestDuration(robot.q, graph_->world().world->robots[r].home,
                                                            graph_->timing()));
  }
  for (std::size_t o = 0; o < history.objects.size(); ++o) {
    const TransitionHistory::ObjectState& object = history.objects[o];
    const int oi = static_cast<int>(o);
    if (object.place == ObjectPlace::kGoal) continue;
    const Millis to_go = costToGo(history, oi);
    if (to_go == kUnreachable) return std::numeric_limits<Millis>::max();
    bound = std::max(bound, object.since + to_go);
  }
  return bound;
}

SearchResult HyperpathSearch::greedy(const SearchBudget& budget) {
  updateCostToGo();
  using Queue = std::vector<Candidate>;  // a heap ordered by Candidate::key, smallest first
  const auto later = [](const Candidate& a, const Candidate& b) { return a.key() > b.key(); };
  struct Frame {
    TransitionHistory history;
    Queue queue;
    bool expanded = false;
  };
  const ObjectSites& sites = graph_->sites();
  SearchResult result;
  std::vector<Frame> stack;
  if (std::optional<TransitionHistory> start = source()) stack.push_back({std::move(*start), {}, false});
  int most_placed = -1;  // objects at their goals in result.furthest
  while (!stack.empty()) {
    if (result.expansions >= budget.max_expansions || (budget.stop && budget.stop())) {
      result.status = SearchStatus::kBudget;
      return result;
    }
    Frame& frame = stack.back();
    if (!frame.expanded) {
      if (const int placed = frame.history.objectsAtGoal(); placed > most_placed) {
        most_placed = placed;
        result.furthest = frame.history;
      }
      if (frame.history.complete(sites)) {
        if (std::optional<TransitionHistory> done = finish(frame.history)) {
          result.status = SearchStatus::kFound;
          result.plan = std::move(done);
          result.furthest.reset();
          return result;
        }
        stack.pop_back();
        continue;
      }
      frame.queue = candidates(frame.history);
      std::make_heap(frame.queue.begin(), frame.queue.end(), later);
      frame.expanded = true;
      ++result.expansions;
    }
    // lazy evaluation: a candidate's exact start (with its moves) is computed when it comes
    // first; it is taken when it still comes first with the exact value
    std::optional<TransitionHistory> child;
    while (!frame.queue.empty() && !child) {
      std::pop_heap(frame.queue.begin(), frame.queue.end(), later);
      Candidate candidate = frame.queue.back();
      frame.queue.pop_back();
      std::optional<TransitionHistory> next = apply(frame.history, candidate);
      if (!next || deadlocked(*next)) continue;
      const Millis exact = next->steps.back().start;
      if (!candidate.exact && !frame.queue.empty() &&
          std::tie(candidate.set_aside, candidate.waits, exact) >
              std::tie(frame.queue.front().set_aside, frame.queue.front().waits, frame.queue.front().start)) {
        candidate.start = exact;
        candidate.exact = true;
        frame.queue.push_back(candidate);
        std::push_heap(frame.queue.begin(), frame.queue.end(), later);
        continue;
      }
      child = std::move(next);
    }
    if (!child) {
      stack.pop_back();  // backtrack
      continue;
    }
    stack.push_back({std::move(*child), {}, false});
  }
  result.status = SearchStatus::kExhausted;
  return result;
}

SearchResult HyperpathSearch::nextBest(const SearchBudget& budget) {
  const ObjectSites& sites = graph_->sites();
  if (!astar_) {
    astar_ = std::make_unique<AStarState>();
    if (std::optional<TransitionHistory> start = source()) {
      astar_->nodes.push_back(std::move(*start));
      astar_->frontier.push({lowerBound(astar_->nodes.back()), astar_->pushed++, 0});
    }
    astar_->keyed_version = cost_to_go_version_;
  }
  AStarState& a = *astar_;
  // The dominance key: the bodies' vertices, and what else decides which transitions may come
  // next, so that a history with the same key and no later times has every successor the other
  // has: which robots have not acted yet (home constraints apply to them), each object's past
  // holders (never handed back to), the transitions held that are in scheduling constraints.
  // Then the times.
  const auto signature = [&](const TransitionHistory& h) {
    std::vector<long long> key;
    std::vector<Millis> times;
    for (const auto& r : h.robots) {
      key.push_back(r.object);
      key.push_back(r.grasp);
      key.push_back(r.free == 0);
      for (const double q : r.q) key.push_back(std::llround(q * 1e9));
      times.push_back(r.free);
    }
    static_assert(core::kMaxRobots < 64, "a bit per robot");
    std::vector<long long> held_by(h.objects.size(), 0);  // [object] bit per robot
    std::vector<long long> constrained;
    for (const ScheduledTransition& step : h.steps) {
      const TransitionSample& sample = graph_->transition(step.transition).sample;
      if (const int holder = sample.holderAfter(); holder >= 0) held_by[sample.object] |= 1LL << holder;
      if (graph_->schedulingConstrained(step.transition)) constrained.push_back(step.transition);
    }
    for (std::size_t o = 0; o < h.objects.size(); ++o) {
      key.push_back(static_cast<long long>(h.objects[o].place));
      key.push_back(h.objects[o].set_aside);
      key.push_back(h.objects[o].holder);
      key.push_back(held_by[o]);
      times.push_back(h.objects[o].since);
    }
    std::sort(constrained.begin(), constrained.end());
    key.insert(key.end(), constrained.begin(), constrained.end());  // last: the only part of varying length
    times.insert(times.end(), h.site_busy.begin(), h.site_busy.end());
    return std::make_pair(key, times);
  };
  const auto dominated = [&](const TransitionHistory& h) {
    auto [key, times] = signature(h);
    std::vector<std::vector<Millis>>& list = a.seen[key];
    for (const std::vector<Millis>& other : list) {
      if (std::equal(other.begin(), other.end(), times.begin(), [](Millis x, Millis y) { return x <= y; })) return true;
    }
    list.push_back(std::move(times));
    return false;
  };

  SearchResult result;
  while (!a.frontier.empty()) {
    if (result.expansions >= budget.max_expansions || (budget.stop && budget.stop())) {
      result.status = SearchStatus::kBudget;
      return result;
    }
    // transitions sampled by the last expansion (or since the last call) move the bounds: down
    // for a sample faster than any before, up where a hyperarc's first sample replaces the dwell
    updateCostToGo();
    if (a.keyed_version != cost_to_go_version_) rekeyFrontier();
    const AStarState::Entry entry = a.frontier.top();
    a.frontier.pop();
    if (!a.nodes[entry.node].final_moves.empty()) {  // a complete history: the next best
      result.status = SearchStatus::kFound;
      result.plan = a.nodes[entry.node];
      return result;
    }
    const TransitionHistory history = a.nodes[entry.node];
    ++result.expansions;
    // branch on the fastest samples of each hyperarc
    std::vector<Candidate> all = candidates(history);
    std::stable_sort(all.begin(), all.end(), [&](const Candidate& x, const Candidate& y) {
      const TransitionSample& sx = graph_->transition(x.transition).sample;
      const TransitionSample& sy = graph_->transition(y.transition).sample;
      return std::tie(sx.hyperarc, sx.duration, x.transition) < std::tie(sy.hyperarc, sy.duration, y.transition);
    });
    std::map<int, std::size_t> per_hyperarc;
    for (const Candidate& candidate : all) {
      if (per_hyperarc[graph_->transition(candidate.transition).sample.hyperarc]++ >= kAStarSamplesPerHyperarc) continue;
      std::optional<TransitionHistory> child = apply(history, candidate);
      if (!child || deadlocked(*child)) continue;
      Millis f = 0;
      if (child->complete(sites)) {
        child = finish(*child);
        if (!child) continue;
        f = child->makespan();
      } else {
        f = lowerBound(*child);
        if (f == std::numeric_limits<Millis>::max() || dominated(*child)) continue;
      }
      a.nodes.push_back(std::move(*child));
      a.frontier.push({f, a.pushed++, a.nodes.size() - 1});
    }
  }
  result.status = SearchStatus::kExhausted;
  return result;
}

}  // namespace dashbed::planner
