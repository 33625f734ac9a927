#include "planner/scheduling/scheduled_cbs.h"

#include <algorithm>
#include <limits>
#include <sstream>
#include <tuple>

#include "planner/scheduling/robot_conflicts.h"
#include "planner/scheduling/temporal_network.h"

namespace dashbed::planner {
namespace {

constexpr Millis kObstacleStep = 100;    // [ms] how often the other robot is sampled for a detour
constexpr std::size_t kMaxObstacles = 30;  // more distinct states than this for a detour: the
                                           // other robot is moving through, ordering is the remedy
constexpr std::size_t kMaxParkingObstacles = 120;  // a parking is checked per configuration only

/// A scheduling constraint of the high level: a point of segment `from` (its start, or its end)
/// comes no later than a point of segment `to`. Kept symbolic, as detours change durations.
struct Precedence {
  int from = -1;
  bool from_end = false;
  int to = -1;
  bool to_end = false;
  bool operator==(const Precedence&) const = default;
};

TemporalEdge edgeOf(const Precedence& p, const std::vector<ScheduleSegment>& segments) {
  return {p.from, p.to, (p.from_end ? segments[p.from].duration : 0) - (p.to_end ? segments[p.to].duration : 0)};
}

/// Another robot's configuration (with its fingers) and held object, for a detour to avoid.
using Obstacle = StandingRobot;

bool sameObstacle(const Obstacle& x, const Obstacle& y) {
  return x.robot == y.robot && x.q == y.q && sameHeld(x.held, y.held);
}

/// Whether `states` holds `o` already.
bool listed(const std::vector<Obstacle>& states, const Obstacle& o) {
  return std::any_of(states.begin(), states.end(), [&](const Obstacle& x) { return sameObstacle(x, o); });
}

/// The low level's constraint: move segment `segment` takes a path on its roadmap that keeps
/// clear of `avoid` (the other robot where it stood or passed during the segment).
struct DetourConstraint {
  int segment = -1;
  const Move* original = nullptr;  ///< the move planned without them
  std::vector<Obstacle> avoid;
};

/// The segment list with move k split at a parking (k goes there, k + 1 on to the old end):
/// indices from k on shift by one, so what constrained the move now constrains its second part
/// and the way to the parking is free to go early.
void splitIndex(int k, int& segment) {
  if (segment >= k) ++segment;
}

Millis makespanOf(const Schedule& schedule) {
  Millis end = 0;
  for (std::size_t s = 0; s < schedule.segments.size(); ++s) end = std::max(end, schedule.start[s] + schedule.segments[s].duration);
  return end;
}

/// Segments of a history: per robot in order, the robots one after another.
std::vector<ScheduleSegment> segmentsOf(const MotionHypergraph& graph, const TransitionHistory& history) {
  const auto move_segment = [&](int robot, const Move* move, int step) {
    ScheduleSegment seg;
    seg.robot = robot;
    seg.move = move;
    seg.step = step;
    seg.duration = move->duration;
    if (move->object >= 0) {
      const Grasp& grasp = graph.graspsOf(move->object).at(move->grasp);
      seg.held = HeldObject{move->object, grasp.X_OT.inverse(), true};
      seg.finger = grasp.finger;
    }
    return seg;
  };
  std::vector<ScheduleSegment> segments;
  const int steps = static_cast<int>(history.steps.size());
  for (std::size_t r = 0; r < history.robots.size(); ++r) {
    const int robot = static_cast<int>(r);
    if (r < history.fold_moves.size() && history.fold_moves[r] != nullptr) {
      segments.push_back(move_segment(robot, history.fold_moves[r], -1));
      segments.back().phase = -1;
    }
    int last = -1;  // the robot's last transition so far
    for (std::size_t i = 0; i < history.steps.size(); ++i) {
      const ScheduledTransition& step = history.steps[i];
      const TransitionSample& sample = graph.transition(step.transition).sample;
      const int here = static_cast<int>(i);
      for (std::size_t m = 0; m < sample.motions.size(); ++m) {
        if (sample.motions[m].robot != robot) continue;
        const std::vector<const Move*>& moves = step.moves[m];
        for (std::size_t k = 0; k < moves.size(); ++k) {
          if (moves[k]->duration == 0) continue;
          segments.push_back(move_segment(robot, moves[k], here));
          segments.back().phase = k + 1 < moves.size() ? last : here;  // parking at home on the way
        }
        ScheduleSegment seg;
        seg.robot = robot;
        seg.motion = &sample.motions[m];
        seg.step = seg.phase = last = here;
        seg.duration = sample.duration;
        segments.push_back(seg);
      }
    }
    if (history.final_moves[r] != nullptr && history.final_moves[r]->duration > 0) {
      segments.push_back(move_segment(robot, history.final_moves[r], -1));
      segments.back().phase = last;
    }
    if (r < history.unfold_moves.size() && history.unfold_moves[r] != nullptr) {
      segments.push_back(move_segment(robot, history.unfold_moves[r], -1));
      segments.back().phase = steps;
    }
  }
  return segments;
}

/// The temporal network of a history's segments (see the header).
std::vector<TemporalEdge> baseConstraints(const MotionHypergraph& graph, const TransitionHistory& history,
                                          const std::vector<ScheduleSegment>& segments, SequentialSteps steps) {
  std::vector<TemporalEdge> edges;
  const int n = static_cast<int>(segments.size());
  // each object's pick and place segment (the transition parts), and where it is set aside,
  // its segments setting it down and taking it up again
  const std::size_t m = history.objects.size();
  std::vector<int> pick_of(m, -1), place_of(m, -1), set_down_of(m, -1), pick_up_of(m, -1);
  std::vector<std::vector<int>> step_parts(history.steps.size());
  for (int s = 0; s < n; ++s) {
    if (s + 1 < n && segments[s + 1].robot == segments[s].robot) {
      edges.push_back({s, s + 1, segments[s].duration});
      // a move into a transition arrives just in time: the robot waits where it was, not in
      // front of the transition, where it could block the robot it is waiting for
      if (segments[s].move != nullptr && segments[s + 1].motion != nullptr && !segments[s].early) {
        edges.push_back({s + 1, s, -segments[s].duration, true});
      }
    }
    if (segments[s].motion == nullptr) continue;
    const TransitionSample& sample = graph.transition(history.steps[segments[s].step].transition).sample;
    step_parts[segments[s].step].push_back(s);
    const bool aside = graph.taskSpace().hyperarcs().at(static_cast<std::size_t>(sample.hyperarc)).rest_pose == RestPose::kAside;
    if (sample.kind == TransitionKind::kPick) (aside ? pick_up_of : pick_of)[sample.object] = s;
    if (sample.kind == TransitionKind::kPlace) (aside ? set_down_of : place_of)[sample.object] = s;
  }
  for (const std::vector<int>& parts : step_parts) {  // a handoff's robots start together
    for (std::size_t k = 1; k < parts.size(); ++k) {
      edges.push_back({parts[0], parts[k], 0});
      edges.push_back({parts[k], parts[0], 0});
    }
  }
  for (int s = 0; s < n; ++s) {
    const ScheduleSegment& seg = segments[s];
    const SiteSet& touches =
        seg.move != nullptr ? seg.move->touches : graph.transition(history.steps[seg.step].transition).sample.touches;
    for (int b = 0; b < static_cast<int>(history.objects.size()); ++b) {
      if (touches.test(ObjectSites::startSite(b)) && pick_of[b] >= 0 && pick_of[b] != s) {
        edges.push_back({pick_of[b], s, segments[pick_of[b]].duration});
      }
      if (touches.test(ObjectSites::goalSite(b)) && place_of[b] >= 0 && place_of[b] != s) {
        edges.push_back({s, place_of[b], seg.duration});
      }
      // through the set-aside site: before it is set down there (as the history has it: by its
      // step, or folding at the start), else after it is taken up again
      const int down = set_down_of[b], up = pick_up_of[b];
      if (touches.test(ObjectSites::asideSite(b)) && down >= 0 && s != down && s != up) {
        const bool before = seg.step >= 0 ? seg.step <= segments[down].step : seg.phase == -1;
        if (before) edges.push_back({s, down, seg.duration});
        if (!before && up >= 0) edges.push_back({up, s, segments[up].duration});
      }
    }
  }
  for (std::size_t b = 0; b < m; ++b) {  // set down before it is taken up again
    if (set_down_of[b] >= 0 && pick_up_of[b] >= 0) {
      edges.push_back({set_down_of[b], pick_up_of[b], segments[set_down_of[b]].duration});
    }
  }
  if (history.sequential && steps == SequentialSteps::kOneAfterAnother) {
    // each phase after the one before: folding, the steps, unfolding
    std::vector<std::vector<int>> phases(history.steps.size() + 2);
    for (int s = 0; s < n; ++s) phases.at(static_cast<std::size_t>(segments[s].phase + 1)).push_back(s);
    std::erase_if(phases, [](const std::vector<int>& phase) { return phase.empty(); });
    for (std::size_t k = 1; k < phases.size(); ++k) {
      for (const int before : phases[k - 1]) {
        for (const int after : phases[k]) edges.push_back({before, after, segments[before].duration});
      }
    }
  }
  return edges;
}

/// The precedence "item a of robot ra ends before item b of robot rb starts", or std::nullopt
/// when impossible (an item standing still forever, or from time 0).
std::optional<Precedence> precedence(const ScheduleView& view, int ra, int item_a, int rb, int item_b) {
  const Timeline& a = view.timeline(ra);
  const Timeline& b = view.timeline(rb);
  Precedence p;
  if (item_a >= 0) {  // the end of segment A
    p.from = a.segments[item_a];
    p.from_end = true;
  } else {  // standing still until segment k starts
    const int k = -1 - item_a;
    if (k >= static_cast<int>(a.segments.size())) return std::nullopt;
    p.from = a.segments[k];
  }
  if (item_b >= 0) {  // the start of segment B
    p.to = b.segments[item_b];
  } else {  // standing still from the end of segment k - 1
    const int k = -1 - item_b;
    if (k == 0) return std::nullopt;
    p.to = b.segments[k - 1];
    p.to_end = true;
  }
  return p;
}

/// Where `other` stands or passes while segment `segment` of the schedule runs, sampled every
/// kObstacleStep (ends included), distinct states only.
std::vector<Obstacle> obstaclesDuring(const ScheduleView& view, const Schedule& schedule, int segment, int other) {
  const Millis t0 = schedule.start[segment], t1 = t0 + schedule.segments[segment].duration;
  std::vector<Obstacle> states;
  for (Millis t = t0;; t = std::min(t + kObstacleStep, t1)) {
    const RobotState state = view.at(other, toSeconds(t), true);
    Obstacle o{other, view.full(other, state), state.held};
    if (!listed(states, o)) states.push_back(std::move(o));
    if (t == t1) break;
  }
  return states;
}

/// The transition (MotionTransition id) a robot's conflicting item belongs to (see
/// ConflictResult::unordered), or -1.
int transitionOf(const TransitionHistory& history, const Schedule& schedule, const Timeline& line, int item) {
  const int k = item >= 0 ? item : -2 - item;  // standing still before segment k: the segment before
  if (k < 0 || k >= static_cast<int>(line.segments.size())) return -1;
  const int step = schedule.segments[line.segments[k]].step;
  return step < 0 ? -1 : history.steps[step].transition;
}

/// What a robot does on `item` of its timeline (RobotConflict's items), in words: "handoff
/// cube_3 by r3 to r4", "on its way to pick cube_1 by r2", "waiting for place cube_1 by r2"...
std::string describeItem(const MotionHypergraph& graph, const TransitionHistory& history, const Schedule& schedule,
                         const Timeline& line, int item) {
  const int k = item >= 0 ? item : -1 - item;  // its segment, or the one it waits for
  if (k >= static_cast<int>(line.segments.size())) return "done";
  const ScheduleSegment& seg = schedule.segments[line.segments[k]];
  const auto transition = [&] {
    return describeHyperarc(*graph.world().world, graph.taskSpace(),
                            graph.transition(history.steps[seg.step].transition).sample.hyperarc);
  };
  if (item < 0) return k == 0 ? "at home" : seg.step >= 0 ? "waiting for " + transition() : "waiting";
  if (seg.motion != nullptr) return transition();
  if (seg.step >= 0) return (seg.to_parking ? "parking on its way to " : "on its way to ") + transition();
  return seg.phase < 0 ? "folding" : seg.phase >= static_cast<int>(history.steps.size()) ? "unfolding" : "on its way to rest";
}

/// "r2 (waiting for handoff cube_10 by r5 to r2) and r3 (handoff cube_3 by r3 to r4) collide at t = 28.04 s"
std::string describe(const MotionHypergraph& graph, const TransitionHistory& history, const ScheduleView& view,
                     const Schedule& schedule, const RobotConflict& c) {
  const auto robot = [&](int r, int item) {
    return graph.world().world->robots[r].name + " (" + describeItem(graph, history, schedule, view.timeline(r), item) + ")";
  };
  std::ostringstream out;
  out << robot(c.robot_a, c.item_a) << " and " << robot(c.robot_b, c.item_b) << " collide at t = " << c.t << " s";
  return out.str();
}

/// The indices of `robot`'s segments in `schedule`, in order.
std::vector<std::size_t> segmentsOfRobot(const Schedule& schedule, int robot) {
  std::vector<std::size_t> result;
  for (std::size_t s = 0; s < schedule.segments.size(); ++s) {
    if (schedule.segments[s].robot == robot) result.push_back(s);
  }
  return result;
}

/// Per robot, the earliest time [s] at which it does something else in `b` than in `a`: up to
/// then a child's schedule repeats its parent's, which was checked free before its conflict.
std::vector<double> firstDifferences(const Schedule& a, const Schedule& b, int robots) {
  std::vector<double> result(static_cast<std::size_t>(robots), std::numeric_limits<double>::infinity());
  for (int r = 0; r < robots; ++r) {
    double& t = result[static_cast<std::size_t>(r)];
    const std::vector<std::size_t> in_a = segmentsOfRobot(a, r), in_b = segmentsOfRobot(b, r);
    for (std::size_t k = 0; k < std::max(in_a.size(), in_b.size()); ++k) {
      if (k >= in_a.size() || k >= in_b.size()) {
        t = std::min(t, toSeconds(k < in_a.size() ? a.start[in_a[k]] : b.start[in_b[k]]));
        break;
      }
      const ScheduleSegment& x = a.segments[in_a[k]];
      const ScheduleSegment& y = b.segments[in_b[k]];
      const Millis sx = a.start[in_a[k]], sy = b.start[in_b[k]];
      if (sx != sy || x.move != y.move || x.motion != y.motion || x.duration != y.duration) {
        t = std::min(t, toSeconds(std::min(sx, sy)));
        break;
      }
    }
  }
  return result;
}

/// A node of the high level: the precedences, detours and parkings added on the way to it and
/// the schedule they give.
struct Node {
  std::vector<Precedence> extra;
  std::vector<DetourConstraint> detours;
  int parkings = 0;
  bool folded = false;  ///< a robot was folded out of the way on the way here
  Schedule schedule;
  std::uint64_t order = 0;
  double clear_until = 0.0;  ///< [s] no conflict before this time
  double resolves = 0.0;     ///< [s] when the conflict it was made to resolve (its parent's first) happens
  std::optional<PairKnowledge> known;  ///< per robot pair, intervals known free
  std::size_t constraints() const { return extra.size() + detours.size() + static_cast<std::size_t>(parkings); }
};

using MoveParts = std::pair<const Move*, const Move*>;  // a detour: the first only

/// A reroute already tried, by kind (detour or parking), move and states to keep clear of (in
/// any order): the same conflict comes back in many nodes, and asked again a reroute takes the
/// answer found before (a new search could differ only where the roadmap grew meanwhile). Only
/// new ones count against max_reroutes: the nodes below a folded robot's and the others each
/// have that many, so that the search behind a fold does not use up those of a way without one.
struct Reroute {
  bool parking = false;
  const Move* move = nullptr;
  std::vector<Obstacle> avoid;
  std::optional<MoveParts> parts;
  bool folded = false;  ///< asked for below a fold
};

/// Scheduled CBS on one task plan (paper: Method > Conflict Resolution). The high level
/// branches on the first robot-robot conflict of a node's schedule: in time, one item before
/// the other (ordering); where no order holds, in space, a detour or a parking planned on the
/// roadmaps (the low level). Conflicts no order resolves are fed back as scheduling constraints.
class ConflictSearch {
 public:
  ConflictSearch(MotionHypergraph& graph, const TransitionHistory& history, const ConflictResolutionBudget& budget,
                 SequentialSteps steps)
      : graph_(graph),
        history_(history),
        budget_(budget),
        steps_(steps),
        checker_(graph.scene()),
        robots_(static_cast<int>(graph.world().world->robots.size())) {}

  ConflictResult run() {
    if (!pushRoot()) return result_;
    while (!open_.empty()) {
      if (result_.nodes >= budget_.max_nodes || (budget_.stop && budget_.stop())) {
        result_.status = ConflictStatus::kBudget;
        return result_;
      }
      Node node = takeNext();
      ++result_.nodes;
      const ScheduleView view(graph_, node.schedule);
      std::vector<double> checked;
      const std::optional<RobotConflict> conflict = firstConflictPairs(
          graph_, view, node.schedule, node.clear_until, node.known ? &*node.known : nullptr, &checked);
      if (!conflict) {
        result_.status = ConflictStatus::kResolved;
        result_.constraints = static_cast<int>(node.constraints());
        result_.schedule = std::move(node.schedule);
        return result_;
      }
      result_.reason = describe(graph_, history_, view, node.schedule, *conflict);
      const Expansion expansion{node, view, *conflict, checked};
      if (orderChildren(expansion)) continue;
      feedBackUnordered(expansion);
      rerouteChildren(expansion);
    }
    result_.status = ConflictStatus::kUnresolvable;
    return result_;
  }

 private:
  /// The node being expanded and its first conflict.
  struct Expansion {
    const Node& node;
    const ScheduleView& view;
    const RobotConflict& conflict;
    const std::vector<double>& checked;  ///< per robot pair, checked free up to (firstConflictPairs)
  };

  /// The root: the history's own schedule. False (with the reason) when its precedences
  /// contradict each other or it is not below makespan_below.
  bool pushRoot() {
    std::optional<Node> root = make(segmentsOf(graph_, history_), {}, {}, 0, false);
    if (!root) {
      result_.reason = "the schedule's own precedences contradict each other";
      return false;
    }
    result_.unresolved_makespan = root->schedule.makespan;
    if (budget_.makespan_below && root->schedule.makespan >= *budget_.makespan_below) {
      result_.reason = "no schedule is shorter than " + std::to_string(*budget_.makespan_below) + " ms";
      return false;
    }
    open_.push_back(std::move(*root));
    return true;
  }

  /// Which open node comes next: along time, the one free of conflicts for longest (ties: the
  /// shortest); by makespan the same, among those at most focal_weight times the shortest; depth
  /// first, the one made to resolve the latest conflict, so that the children of the node that
  /// got furthest come first (ties as along time).
  bool deeper(const Node& x, const Node& y) const {
    const bool depth_first = budget_.order == NodeOrder::kDepthFirst;
    const auto key = [&](const Node& n) {
      return std::make_tuple(depth_first ? -n.resolves : 0.0, -n.clear_until, n.schedule.makespan, n.constraints(),
                             n.order);
    };
    return key(x) < key(y);
  }

  Node takeNext() {
    // the shortest always qualifies, whatever the weight
    std::size_t next = 0;
    double bound = std::numeric_limits<double>::infinity();
    if (budget_.order == NodeOrder::kMakespan) {
      next = static_cast<std::size_t>(std::min_element(open_.begin(), open_.end(), [](const Node& x, const Node& y) {
                                        return x.schedule.makespan < y.schedule.makespan;
                                      }) -
                                      open_.begin());
      bound = budget_.focal_weight * static_cast<double>(open_[next].schedule.makespan);
    }
    for (std::size_t i = 0; i < open_.size(); ++i) {
      if (static_cast<double>(open_[i].schedule.makespan) <= bound && deeper(open_[i], open_[next])) next = i;
    }
    Node node = std::move(open_[next]);
    if (next + 1 != open_.size()) open_[next] = std::move(open_.back());
    open_.pop_back();
    return node;
  }

  /// A node: its segments at the earliest times their temporal network allows. Where they
  /// cannot all hold and `arrive_early` is given, a move into a transition on the contradiction
  /// (a cycle of precedences) that arrives just in time may arrive early and wait in front of the
  /// transition instead (its segment is added to `arrive_early`): that robot cannot both wait
  /// where it was and be out of the way in time.
  std::optional<Node> make(std::vector<ScheduleSegment> segments, std::vector<Precedence> extra,
                           std::vector<DetourConstraint> detours, int parkings, bool folded,
                           std::vector<int>* arrive_early = nullptr) {
    std::optional<std::vector<Millis>> start;
    for (std::vector<std::size_t> cycle;;) {
      std::vector<TemporalEdge> edges = baseConstraints(graph_, history_, segments, steps_);
      for (const Precedence& p : extra) edges.push_back(edgeOf(p, segments));
      start = earliestStarts(segments.size(), edges, arrive_early != nullptr ? &cycle : nullptr);
      if (start) break;
      if (arrive_early == nullptr) return std::nullopt;
      const std::size_t known = arrive_early->size();
      for (const std::size_t e : cycle) {
        if (edges[e].arrival) {
          segments[edges[e].to].early = true;
          arrive_early->push_back(edges[e].to);
        }
      }
      if (arrive_early->size() == known) return std::nullopt;
    }
    Schedule schedule;
    schedule.segments = std::move(segments);
    schedule.start = std::move(*start);
    schedule.makespan = makespanOf(schedule);
    return Node{std::move(extra), std::move(detours), parkings, folded, std::move(schedule), created_++, 0.0, 0.0,
                std::nullopt};
  }

  /// Opens `child` of the expanded node unless it is not below makespan_below: it repeats the
  /// parent's schedule, free before the conflict, until their first difference.
  bool push(const Expansion& x, Node child) {
    if (budget_.makespan_below && child.schedule.makespan >= *budget_.makespan_below) return false;
    const std::vector<double> differ = firstDifferences(x.node.schedule, child.schedule, robots_);
    child.clear_until = std::min(x.conflict.t, *std::min_element(differ.begin(), differ.end()));
    child.resolves = x.conflict.t;
    // per robot pair: what this node found free, as long as both robots do the same
    PairKnowledge known{x.checked, std::vector<double>(x.checked.size(), 0.0)};
    for (int a = 0; a < robots_; ++a) {
      for (int b = a + 1; b < robots_; ++b) known.same[a * robots_ + b] = std::min(differ[a], differ[b]);
    }
    child.known = std::move(known);
    open_.push_back(std::move(child));
    return true;
  }

  /// Time: A before B, B before A. A's move into a transition arriving early, where A cannot
  /// end before B starts just in time (both robots going into one handoff), orders them; true
  /// when such a child was opened, and the conflict needs nothing more. Otherwise the children
  /// where another robot arrives early to make room are opened, one more way beside the
  /// reroutes; an order whose schedule is not below the bound leaves the conflict to a reroute.
  bool orderChildren(const Expansion& x) {
    const Node& node = x.node;
    const int ra = x.conflict.robot_a, rb = x.conflict.robot_b;
    bool ordered = false;
    std::vector<Node> making_room;
    for (const bool a_first : {true, false}) {
      const std::optional<Precedence> p = a_first ? precedence(x.view, ra, x.conflict.item_a, rb, x.conflict.item_b)
                                                  : precedence(x.view, rb, x.conflict.item_b, ra, x.conflict.item_a);
      if (!p || std::find(node.extra.begin(), node.extra.end(), *p) != node.extra.end()) continue;
      std::vector<Precedence> extra = node.extra;
      extra.push_back(*p);
      std::vector<int> early;
      std::optional<Node> child = make(node.schedule.segments, extra, node.detours, node.parkings, node.folded, &early);
      const bool a_early = std::all_of(early.begin(), early.end(), [&](int s) { return p->from_end && s == p->from; });
      if (child && !a_early) making_room.push_back(std::move(*child));
      if (child && a_early && push(x, std::move(*child))) ordered = true;
    }
    if (ordered) return true;
    for (Node& child : making_room) push(x, std::move(child));
    return false;
  }

  /// Scheduling constraints (paper: Transition-extended Hypergraph > Scheduling Constraints): the
  /// two transitions of a conflict no order resolves, and a transition meeting a robot that
  /// stands at home.
  void feedBackUnordered(const Expansion& x) {
    const RobotConflict& conflict = x.conflict;
    const int ta = transitionOf(history_, x.node.schedule, x.view.timeline(conflict.robot_a), conflict.item_a);
    const int tb = transitionOf(history_, x.node.schedule, x.view.timeline(conflict.robot_b), conflict.item_b);
    if (ta >= 0 && tb >= 0 && ta != tb) {
      const std::pair<int, int> pair = std::minmax(ta, tb);
      if (std::find(result_.unordered.begin(), result_.unordered.end(), pair) == result_.unordered.end()) {
        result_.unordered.push_back(pair);
      }
    }
    // standing at home before its first segment (item -1) — in a sequential history, standing
    // at home at all: the other's transition meets home
    const auto at_home = [&](int robot, int item) {
      return item == -1 || (history_.sequential && item < 0 &&
                            x.view.at(robot, conflict.t, false).q == graph_.world().world->robots[robot].home);
    };
    for (const auto& [transition, item, robot] :
         {std::tuple{ta, conflict.item_b, conflict.robot_b}, std::tuple{tb, conflict.item_a, conflict.robot_a}}) {
      const std::pair<int, int> blocked{transition, robot};
      if (transition >= 0 && at_home(robot, item) &&
          std::find(result_.home_blocked.begin(), result_.home_blocked.end(), blocked) == result_.home_blocked.end()) {
        result_.home_blocked.push_back(blocked);
      }
    }
  }

  /// Space, when time cannot help: a robot on a move takes a detour around where the other one
  /// is meanwhile; a robot standing before a move waits somewhere out of the other one's way.
  void rerouteChildren(const Expansion& x) {
    const Node& node = x.node;
    const RobotConflict& conflict = x.conflict;
    const std::vector<ScheduleSegment>& segments = node.schedule.segments;
    for (const auto& [robot, item, other, other_item] :
         {std::tuple{conflict.robot_a, conflict.item_a, conflict.robot_b, conflict.item_b},
          std::tuple{conflict.robot_b, conflict.item_b, conflict.robot_a, conflict.item_a}}) {
      const Timeline& line = x.view.timeline(robot);
      if (item >= 0) {
        const int segment = line.segments[item];
        if (segments[segment].move == nullptr) continue;
        if (std::optional<Node> child = detoured(node, segment, obstaclesDuring(x.view, node.schedule, segment, other))) {
          push(x, std::move(*child));
        }
      } else if (const int k = -1 - item; k < static_cast<int>(line.segments.size()) && other_item >= 0) {
        const int segment = line.segments[k];
        if (segments[segment].move == nullptr) continue;
        // standing no time at all: the conflict is where the segment before ends, no parking helps
        if (k > 0) {
          const int before = line.segments[k - 1];
          if (node.schedule.start[before] + segments[before].duration >= node.schedule.start[segment]) continue;
        }
        const int busy = x.view.timeline(other).segments[other_item];
        const std::vector<Obstacle> avoid = obstaclesDuring(x.view, node.schedule, busy, other);
        for (const bool fold : {false, true}) {
          if (std::optional<Node> child = parked(node, segment, avoid, fold)) push(x, std::move(*child));
        }
      }
    }
  }

  /// A reroute (Reroute) planned by `plan` unless asked before or the budget of its side of the
  /// folds is used up.
  std::optional<MoveParts> reroute(const Node& node, bool parking, const Move& move, const std::vector<Obstacle>& avoid,
                                   const std::function<std::optional<MoveParts>()>& plan) {
    const auto known = std::find_if(tried_.begin(), tried_.end(), [&](const Reroute& r) {
      return r.parking == parking && r.move == &move && r.avoid.size() == avoid.size() &&
             std::is_permutation(avoid.begin(), avoid.end(), r.avoid.begin(), sameObstacle);
    });
    if (known != tried_.end()) return known->parts;
    const auto same_side = [&](const Reroute& r) { return r.folded == node.folded; };
    if (std::count_if(tried_.begin(), tried_.end(), same_side) >= budget_.max_reroutes) return std::nullopt;
    tried_.push_back({parking, &move, avoid, plan(), node.folded});
    return tried_.back().parts;
  }

  /// The child whose move `segment` takes a path on its roadmap that also keeps clear of `avoid`.
  std::optional<Node> detoured(const Node& node, int segment, std::vector<Obstacle> avoid) {
    const ScheduleSegment& seg = node.schedule.segments[segment];
    std::vector<DetourConstraint> detours = node.detours;
    auto it = std::find_if(detours.begin(), detours.end(), [&](const DetourConstraint& d) { return d.segment == segment; });
    if (it == detours.end()) it = detours.insert(detours.end(), DetourConstraint{segment, seg.move, {}});
    const std::size_t known = it->avoid.size();
    for (Obstacle& o : avoid) {
      if (!listed(it->avoid, o)) it->avoid.push_back(std::move(o));
    }
    if (it->avoid.size() == known || it->avoid.size() > kMaxObstacles) return std::nullopt;
    const std::vector<Obstacle>& obstacles = it->avoid;
    const std::optional<MoveParts> found = reroute(node, false, *it->original, obstacles, [&]() -> std::optional<MoveParts> {
      const Move* move = graph_.detour(*it->original, [&](const core::ArmConfig& a, const core::ArmConfig& b) {
        return checker_.motionClearOf(seg.robot, graph_.scene().configuration(seg.robot, a, seg.finger),
                                      graph_.scene().configuration(seg.robot, b, seg.finger), seg.held, obstacles);
      });
      if (move == nullptr) return std::nullopt;
      return MoveParts{move, nullptr};
    });
    if (!found) return std::nullopt;
    const Move* move = found->first;
    std::vector<ScheduleSegment> segments = node.schedule.segments;
    segments[segment].move = move;
    segments[segment].duration = move->duration;
    return make(std::move(segments), node.extra, std::move(detours), node.parkings, node.folded);
  }

  /// The child where the robot, instead of standing where move `segment` starts, goes early to a
  /// configuration clear of `avoid` and waits there: the move split in two at that parking. A
  /// parking is the nearest roadmap node clear of `avoid` or, with `fold` (a robot alone), its
  /// folded configuration, further off but out of the shared workspace, where the next robot
  /// coming through does not meet it either. Folding is two moves move() caches, not a roadmap
  /// search for `avoid`: it is not counted against max_reroutes.
  std::optional<Node> parked(const Node& node, int segment, const std::vector<Obstacle>& avoid, bool fold) {
    const ScheduleSegment& seg = node.schedule.segments[segment];
    // a robot's way to a parking is not parked again: it would only go somewhere else first, in
    // a chain of parkings that stand in the same robot's way
    if (seg.to_parking || avoid.size() > kMaxParkingObstacles || (fold && seg.held)) return std::nullopt;
    const auto clear = [&](const core::ArmConfig& q) {
      const Eigen::VectorXd f = graph_.scene().configuration(seg.robot, q, seg.finger);
      return std::all_of(avoid.begin(), avoid.end(), [&](const Obstacle& o) {
        return checker_.robotsFree(seg.robot, f, seg.held, o.robot, o.q, o.held);
      });
    };
    const core::ArmConfig& folded = graph_.idleConfiguration(seg.robot, IdlePose::kFolded);
    const std::optional<MoveParts> split =
        !fold ? reroute(node, true, *seg.move, avoid, [&] { return graph_.parking(*seg.move, clear); })
        : clear(folded) ? graph_.parkingAt(*seg.move, folded)
                        : std::nullopt;
    if (!split) return std::nullopt;
    std::vector<ScheduleSegment> segments = node.schedule.segments;
    ScheduleSegment second = segments[segment];
    segments[segment].move = split->first;
    segments[segment].duration = split->first->duration;
    segments[segment].to_parking = true;
    second.move = split->second;
    second.duration = split->second->duration;
    segments.insert(segments.begin() + segment + 1, second);
    std::vector<Precedence> extra = node.extra;
    for (Precedence& p : extra) {
      splitIndex(segment, p.from);
      splitIndex(segment, p.to);
    }
    std::vector<DetourConstraint> detours;
    for (DetourConstraint d : node.detours) {
      if (d.segment == segment) continue;  // that move is replaced
      splitIndex(segment, d.segment);
      detours.push_back(std::move(d));
    }
    return make(std::move(segments), std::move(extra), std::move(detours), node.parkings + 1, node.folded || fold);
  }

  MotionHypergraph& graph_;
  const TransitionHistory& history_;
  const ConflictResolutionBudget& budget_;
  SequentialSteps steps_;
  CollisionChecker checker_;
  int robots_;
  std::vector<Node> open_;
  std::uint64_t created_ = 0;
  std::vector<Reroute> tried_;  ///< reroutes asked for so far
  ConflictResult result_;
};

}  // namespace

ConflictResult resolveConflicts(MotionHypergraph& graph, const TransitionHistory& history,
                                const ConflictResolutionBudget& budget, SequentialSteps steps) {
  return ConflictSearch(graph, history, budget, steps).run();
}

}  // namespace dashbed::planner
