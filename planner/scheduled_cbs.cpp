#include "planner/scheduled_cbs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "planner/key_curve.h"

namespace dashbed::planner {
namespace {

constexpr Millis kGridStep = 20;         // [ms] extra check times between key times
constexpr double kFarApart = 2.6;        // [m] bases farther apart than twice the reach + tool: never touch
constexpr Millis kObstacleStep = 100;    // [ms] how often the other robot is sampled for a detour
constexpr std::size_t kMaxObstacles = 30;  // more distinct states than this for a detour: the
                                           // other robot is moving through, ordering is the remedy
constexpr std::size_t kMaxParkingObstacles = 120;  // a parking is checked per configuration only
constexpr double kClearanceSlack = 1e-4;  // [m] a robot check skipped by clearance keeps this in hand
constexpr double kCheckWindow = 1.0;      // [s] robot pairs are checked side by side this much at a time

/// A precedence S[to] >= S[from] + lag.
struct Edge {
  int from = -1, to = -1;
  Millis lag = 0;
};

/// `ms` rounded to the whole millisecond it misses by a rounding error only.
double snapToMillis(double ms) {
  const double whole = std::round(ms);
  return std::abs(ms - whole) < 1e-6 ? whole : ms;
}

/// Holding the same object in the same grasp (or both nothing).
bool sameHeld(const std::optional<HeldObject>& x, const std::optional<HeldObject>& y) {
  return x.has_value() == y.has_value() && (!x || (x->object == y->object && x->X_TO.isApprox(y->X_TO, 0.0)));
}

/// A scheduling constraint of the high level: a point of segment `from` (its start, or its end)
/// comes no later than a point of segment `to`. Kept symbolic, as detours change durations.
struct Precedence {
  int from = -1;
  bool from_end = false;
  int to = -1;
  bool to_end = false;
  bool operator==(const Precedence&) const = default;
};

Edge edgeOf(const Precedence& p, const std::vector<ScheduleSegment>& segments) {
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

/// Local times of the points of a segment (path waypoints or transition keys) [ms].
std::vector<Millis> pointTimes(const ScheduleSegment& seg, const TimingLimits& limits) {
  std::vector<Millis> times;
  if (seg.motion != nullptr) {
    for (const TransitionMotion::Key& key : seg.motion->keys) times.push_back(key.t);
    return times;
  }
  times.push_back(0);
  for (std::size_t i = 1; i < seg.move->path.size(); ++i) {
    times.push_back(times.back() + restToRestDuration(seg.move->path[i - 1], seg.move->path[i], limits));
  }
  return times;
}

/// The robot's timeline in a schedule: its segments (global indices), their point times and,
/// for transitions, their key curves.
struct Timeline {
  std::vector<int> segments;
  std::vector<std::vector<Millis>> times;
  std::vector<std::optional<controllers::TrajectoryInterpolator>> curves;
};

/// Where a robot is at time t: arm configuration, finger position, held object, and the item
/// (segment index into Timeline::segments, or -1 - k when standing still before segment k).
struct RobotState {
  core::ArmConfig q{};
  double finger = kFingersOpen;
  std::optional<HeldObject> held;
  int item = 0;
};

/// Same configuration, fingers and held object (same grasp).
bool sameState(const RobotState& x, const RobotState& y) {
  return x.q == y.q && x.finger == y.finger && sameHeld(x.held, y.held);
}

class ScheduleView {
 public:
  ScheduleView(const MotionHypergraph& graph, const Schedule& schedule) : graph_(&graph), schedule_(&schedule) {
    timelines_.resize(graph.world().world->robots.size());
    starts_.resize(timelines_.size());
    ends_.resize(timelines_.size());
    for (std::size_t s = 0; s < schedule.segments.size(); ++s) {
      const int robot = schedule.segments[s].robot;
      timelines_[robot].segments.push_back(static_cast<int>(s));
      timelines_[robot].times.push_back(pointTimes(schedule.segments[s], graph.timing()));
      const TransitionMotion* motion = schedule.segments[s].motion;
      timelines_[robot].curves.push_back(motion != nullptr ? std::optional(keyCurve(*motion)) : std::nullopt);
      starts_[robot].push_back(toSeconds(schedule.start[s]));
      // from whole milliseconds: the same double as the key time it ends at, with no rounding
      // error of a sum of seconds
      ends_[robot].push_back(toSeconds(schedule.start[s] + schedule.segments[s].duration));
    }
  }

  const Timeline& timeline(int robot) const { return timelines_[robot]; }

  /// The state of `robot` at time t [s]. At an instant where two pieces meet, `after` picks the
  /// later one's fingers and held object.
  RobotState at(int robot, double t, bool after) const {
    const Timeline& line = timelines_[robot];
    const std::vector<double>& starts = starts_[robot];
    // k: segments started by t (at t itself only when `after`)
    const std::size_t k = static_cast<std::size_t>(
        (after ? std::upper_bound(starts.begin(), starts.end(), t) : std::lower_bound(starts.begin(), starts.end(), t)) -
        starts.begin());
    RobotState state;
    state.item = -1 - static_cast<int>(k);
    if (k == 0) {
      state.q = graph_->world().world->robots[robot].home;
      return state;
    }
    const ScheduleSegment& seg = schedule_->segments[line.segments[k - 1]];
    const double end = ends_[robot][k - 1];
    const auto& curve = line.curves[k - 1];
    if (t < end || (t == end && !after)) {
      evaluate(seg, line.times[k - 1], curve, t - starts[k - 1], after, state);
      state.item = static_cast<int>(k - 1);
    } else {
      evaluate(seg, line.times[k - 1], curve, toSeconds(seg.duration), false, state);  // standing at its end
    }
    return state;
  }

  /// Over [t0, t1], which no point time of `robot` lies strictly within and during which it is
  /// on `item` (RobotState::item at t0): its peak speed over its mean speed
  /// (restToRestPeakOverMean on a move's piece, curvePeakOverMean between a transition's keys;
  /// 1 standing).
  double peakOverMeanSpeed(int robot, int item, double t0, double t1) const {
    if (item < 0) return 1.0;
    const ScheduleSegment& seg = schedule_->segments[timelines_[robot].segments[item]];
    const std::vector<Millis>& times = timelines_[robot].times[item];
    const double start = starts_[robot][item];
    if (seg.motion != nullptr) return curvePeakOverMean(*timelines_[robot].curves[item], t0 - start, t1 - start);
    if (seg.move->path.size() < 2) return 1.0;
    const std::size_t i = pieceAt(times, t0 - start, true);
    const double piece_start = start + toSeconds(times[i]);
    return restToRestPeakOverMean(seg.move->path[i], seg.move->path[i + 1], times[i + 1] - times[i],
                                  t0 - piece_start, t1 - piece_start, graph_->timing());
  }

  /// Whether `robot` follows a transition's key curve on `item` (RobotState::item).
  bool onCurve(int robot, int item) const { return item >= 0 && timelines_[robot].curves[item].has_value(); }

  /// The configuration the collision checker wants for `robot` in `state`.
  Eigen::VectorXd full(int robot, const RobotState& state) const {
    return graph_->scene().configuration(robot, state.q, state.finger);
  }

 private:
  /// The piece i of a segment with point times `times` with times[i] <= tau < times[i + 1] (or
  /// <= with !after), tau [s] from the segment's start; tau, a difference of seconds, may miss a
  /// whole-millisecond key by a rounding error (1.009 s is 1008.9999... ms): at a key it counts
  /// as the key.
  static std::size_t pieceAt(const std::vector<Millis>& times, double tau, bool after) {
    const double tau_ms = snapToMillis(tau * 1000.0);
    const auto next = after ? std::upper_bound(times.begin() + 1, times.end(), tau_ms,
                                               [](double v, Millis x) { return v < static_cast<double>(x); })
                            : std::lower_bound(times.begin() + 1, times.end(), tau_ms,
                                               [](Millis x, double v) { return static_cast<double>(x) < v; });
    return std::min<std::size_t>(static_cast<std::size_t>(next - times.begin()) - 1,
                                 times.size() >= 2 ? times.size() - 2 : 0);
  }

  /// `curve`: a transition's key curve (keyCurve).
  void evaluate(const ScheduleSegment& seg, const std::vector<Millis>& times,
                const std::optional<controllers::TrajectoryInterpolator>& curve, double tau, bool after,
                RobotState& state) const {
    const std::size_t i = pieceAt(times, tau, after);
    if (seg.motion != nullptr) {
      const TransitionMotion& m = *seg.motion;
      state.q = curve->position(tau);
      state.finger = m.finger[i];
      state.held = m.held[i];
      return;
    }
    const std::vector<core::ArmConfig>& path = seg.move->path;
    state.finger = seg.finger;
    state.held = seg.held;
    if (path.size() == 1) {
      state.q = path[0];
      return;
    }
    state.q = restToRestAt(path[i], path[i + 1], times[i + 1] - times[i], tau - toSeconds(times[i]), graph_->timing()).first;
  }

  const MotionHypergraph* graph_;
  const Schedule* schedule_;
  std::vector<Timeline> timelines_;
  std::vector<std::vector<double>> starts_;  // [robot][k] start of its segment k [s]
  std::vector<std::vector<double>> ends_;    // [robot][k] end of its segment k [s]
};

/// The earliest schedule satisfying `edges`, or std::nullopt for a positive cycle.
std::optional<std::vector<Millis>> earliestStarts(std::size_t count, const std::vector<Edge>& edges) {
  std::vector<Millis> start(count, 0);
  for (std::size_t round = 0; round <= count; ++round) {
    bool changed = false;
    for (const Edge& e : edges) {
      if (start[e.from] + e.lag > start[e.to]) {
        start[e.to] = start[e.from] + e.lag;
        changed = true;
      }
    }
    if (!changed) return start;
  }
  return std::nullopt;
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
std::vector<Edge> baseConstraints(const MotionHypergraph& graph, const TransitionHistory& history,
                                  const std::vector<ScheduleSegment>& segments, SequentialSteps steps) {
  std::vector<Edge> edges;
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
        edges.push_back({s + 1, s, -segments[s].duration});
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

/// Two boxes (min, max corners), each grown by its own distance, do not overlap.
bool boxesApart(const std::pair<Eigen::Vector3d, Eigen::Vector3d>& a, double grow_a,
                const std::pair<Eigen::Vector3d, Eigen::Vector3d>& b, double grow_b) {
  const double grow = grow_a + grow_b;
  return ((a.first.array() - grow > b.second.array()) || (b.first.array() - grow > a.second.array())).any();
}

std::string describe(const MotionHypergraph& graph, const RobotConflict& c) {
  std::ostringstream out;
  out << graph.world().world->robots[c.robot_a].name << " and " << graph.world().world->robots[c.robot_b].name
      << " collide at t = " << c.t << " s";
  return out.str();
}

/// What a conflict search node knows about its schedule per robot pair (see firstConflictPairs).
struct PairKnowledge {
  std::vector<double> checked;  ///< [s] every interval ending by then is free in the schedule checked
  std::vector<double> same;     ///< [s] the two robots do the same as there before then
};

/// Whether an interval of robot pair `pair` ending at t1 [s] is known free: before `from`, or
/// where `known` (may be null) says so (true for all t1 up to some time, false after it).
struct KnownFree {
  double from = 0.0;
  const PairKnowledge* known = nullptr;
  std::size_t pair = 0;
  bool operator()(double t1) const {
    return t1 <= from || (known != nullptr && t1 <= known->checked[pair] && t1 < known->same[pair]);
  }
};

/// One robot pair's part of firstConflictPairs: the intervals between its check times (every
/// point time of both robots and a regular grid), checked in order from the first one not known
/// free, as far as the caller asks at a time.
class PairCheck {
 public:
  PairCheck(const ScheduleView& view, const Schedule& schedule, const CollisionScene& scene, CollisionChecker& checker,
            int a, int b, KnownFree known_free)
      : view_(&view), schedule_(&schedule), scene_(&scene), checker_(&checker), a_(a), b_(b), known_free_(known_free) {
    if (known_free_(toSeconds(schedule.makespan))) {
      start_ = schedule.makespan;
      return;
    }
    // the grid starts at its last regular time up to which all is known free: the intervals
    // before it end by then
    Millis lo = 0, hi = schedule.makespan / kGridStep;  // known free up to lo's time (t1 = 0 is)
    while (lo < hi) {
      const Millis mid = lo + (hi - lo + 1) / 2;
      if (known_free_(toSeconds(mid * kGridStep))) {
        lo = mid;
      } else {
        hi = mid - 1;
      }
    }
    const Millis begin = lo * kGridStep;
    // the two robots' point times from there on (a robot's segments run one after another);
    // the regular grid's times come in as the intervals are walked
    std::array<std::vector<Millis>, 2> lists;
    for (const int r : {a, b}) {
      std::vector<Millis>& times = lists[r == a ? 0 : 1];
      const Timeline& line = view.timeline(r);
      for (std::size_t k = 0; k < line.segments.size(); ++k) {
        for (const Millis t : line.times[k]) {
          if (schedule.start[line.segments[k]] + t > begin) times.push_back(schedule.start[line.segments[k]] + t);
        }
      }
      if (!std::is_sorted(times.begin(), times.end())) std::sort(times.begin(), times.end());
    }
    points_.reserve(lists[0].size() + lists[1].size());
    std::merge(lists[0].begin(), lists[0].end(), lists[1].begin(), lists[1].end(), std::back_inserter(points_));
    start_ = begin;
  }

  /// Checks the next intervals that start before `until` and no later than `latest` [s]. The
  /// pair's first conflict when one of them has it (the pair is then done).
  std::optional<RobotConflict> advance(double until, double latest) {
    for (; !done(); start_ = nextTime()) {
      const double t0 = toSeconds(start_);
      if (t0 >= until) return std::nullopt;
      if (t0 > latest) {
        checked_ = t0;
        break;
      }
      if (std::optional<RobotConflict> conflict = check(t0, toSeconds(nextTime()))) {
        checked_ = t0;
        start_ = schedule_->makespan;
        return conflict;
      }
    }
    start_ = schedule_->makespan;
    return std::nullopt;
  }

  bool done() const { return start_ >= schedule_->makespan; }
  /// [s] The start of the first interval not found free (when not done: the next one).
  double checkedUntil() const { return done() ? checked_ : toSeconds(start_); }

 private:
  /// The check time after start_: the next point time of either robot or of the grid.
  Millis nextTime() {
    while (point_ < points_.size() && points_[point_] <= start_) ++point_;
    const Millis grid = (start_ / kGridStep + 1) * kGridStep;
    return std::min({grid, schedule_->makespan, point_ < points_.size() ? points_[point_] : grid});
  }

  /// The first colliding sample in [t0, t1], or none.
  std::optional<RobotConflict> check(double t0, double t1) {
    if (known_free_(t1)) return std::nullopt;
    const ScheduleView& view = *view_;
    const Schedule& schedule = *schedule_;
    const CollisionScene& scene = *scene_;
    const int a = a_, b = b_;
    const RobotState a0 = view.at(a, t0, true), b0 = view.at(b, t0, true);
    // a handoff's two robots were checked against each other when it was sampled
    const auto in_step = [&](int r, const RobotState& s) {
      const Timeline& line = view.timeline(r);
      return s.item >= 0 && schedule.segments[line.segments[s.item]].motion != nullptr
                 ? schedule.segments[line.segments[s.item]].step
                 : -2;
    };
    if (in_step(a, a0) >= 0 && in_step(a, a0) == in_step(b, b0)) return std::nullopt;
    const RobotState a1 = view.at(a, t1, false), b1 = view.at(b, t1, false);
    const bool still = sameState(a0, a1) && sameState(b0, b1);
    if (still && standing_ && sameState(a0, standing_->first) && sameState(b0, standing_->second)) return std::nullopt;
    const Eigen::VectorXd qa0 = view.full(a, a0), qb0 = view.full(b, b0);
    if (withinMeasured(a0, qa0, a1, b0, qb0, b1)) {
      standing_ = still ? std::optional(std::pair{a0, b0}) : std::nullopt;
      return std::nullopt;
    }
    const int steps_a = scene.motionSteps(a, qa0, view.full(a, a1), a0.held);
    const int steps_b = scene.motionSteps(b, qb0, view.full(b, b1), b0.held);
    // no point moves farther than its steps' motion_step within the interval: robots whose
    // bounding boxes at its start stay apart by that much are free throughout
    // (the gap between the boxes is a clearance as well: the robots' points stay inside)
    const auto bounds_a = checker_->robotBounds(a, qa0, a0.held), bounds_b = checker_->robotBounds(b, qb0, b0.held);
    const double step = scene.settings().motion_step;
    if (boxesApart(bounds_a, steps_a * step, bounds_b, steps_b * step)) {
      measured_ = {qa0, qb0, a0.held, b0.held, boxesGap(bounds_a, bounds_b)};
      standing_ = still ? std::optional(std::pair{a0, b0}) : std::nullopt;
      return std::nullopt;
    }
    // evenly in time, so that no point moves more than motion_step between samples where
    // the robot moves fastest within the interval
    const int steps = static_cast<int>(std::ceil(std::max(view.peakOverMeanSpeed(a, a0.item, t0, t1) * steps_a,
                                                          view.peakOverMeanSpeed(b, b0.item, t0, t1) * steps_b) -
                                                 1e-9));
    // the interval's own fingers and held objects, also at its end
    const auto state_at = [&](int r, int k, const RobotState& s0, const RobotState& s1) {
      const RobotState s = k == 0 ? s0 : k == steps ? s1 : view.at(r, t0 + (t1 - t0) * k / steps, true);
      return view.full(r, {s.q, s0.finger, s0.held, 0});
    };
    // Samples are checked in order; after a free one, the samples up to which the robots'
    // points together travel less than their clearance there are free as well (each joint
    // moves monotonically within the interval), and are skipped.
    Eigen::VectorXd qa = state_at(a, 0, a0, a1), qb = state_at(b, 0, b0, b1);
    for (int k = 0; k <= steps;) {
      const double t = t0 + (t1 - t0) * k / steps;
      const double clearance = checker_->robotsClearance(a, qa, a0.held, b, qb, b0.held);
      if (clearance < 0.0) return RobotConflict{t, a, b, a0.item, b0.item};
      measured_ = {qa, qb, a0.held, b0.held, clearance};
      // The next sample checked is the first the robots may reach within the clearance.
      // Their travel from sample k grows with the samples after it (each joint moves
      // monotonically), so it is found by doubling the stride, then halving it.
      Eigen::VectorXd reach_a, reach_b;  // the states at the first sample found to reach
      const auto reaches = [&](int n) {
        Eigen::VectorXd na = state_at(a, n, a0, a1), nb = state_at(b, n, b0, b1);
        const double travel = scene.motionTravel(a, qa, na, a0.held) + scene.motionTravel(b, qb, nb, b0.held);
        if (travel + kClearanceSlack < clearance) return false;
        reach_a = std::move(na);
        reach_b = std::move(nb);
        return true;
      };
      int short_of = k, next = k + 1;  // short_of: not reaching (or k); next: the candidate
      while (next <= steps && !reaches(next)) {
        short_of = next;
        next = k + 2 * (next - k);
      }
      if (next > steps) next = short_of < steps && reaches(steps) ? steps : steps + 1;
      while (next <= steps && next - short_of > 1) {
        const int mid = short_of + (next - short_of) / 2;
        (reaches(mid) ? next : short_of) = mid;
      }
      k = next;
      qa = std::move(reach_a);
      qb = std::move(reach_b);
    }
    standing_ = still ? std::optional(std::pair{a0, b0}) : std::nullopt;
    return std::nullopt;
  }

  /// The interval's pieces lie within the clearance of measured_ (the travel from a point is a
  /// weighted sum of |dq|: along a move's straight piece it is largest at one of the piece's
  /// ends; along a transition's cubic, whose joints each move monotonically, at the corner of
  /// the box between the ends farthest from the point). q0: the interval's start configurations.
  bool withinMeasured(const RobotState& a0, const Eigen::VectorXd& qa0, const RobotState& a1, const RobotState& b0,
                      const Eigen::VectorXd& qb0, const RobotState& b1) const {
    if (measured_.clearance <= 0.0 || !sameHeld(measured_.held_a, a0.held) || !sameHeld(measured_.held_b, b0.held)) {
      return false;
    }
    const CollisionScene& scene = *scene_;
    const auto travel = [&](int r, const Eigen::VectorXd& q, const RobotState& s0, const Eigen::VectorXd& q0,
                            const RobotState& s1) {
      const Eigen::VectorXd q1 = view_->full(r, {s1.q, s0.finger, s0.held, 0});
      if (!view_->onCurve(r, s0.item)) {
        return std::max(scene.motionTravel(r, q, q0, s0.held), scene.motionTravel(r, q, q1, s0.held));
      }
      const Eigen::VectorXd corner = ((q - q0).cwiseAbs().array() >= (q - q1).cwiseAbs().array()).select(q0, q1);
      return scene.motionTravel(r, q, corner, s0.held);
    };
    return travel(a_, measured_.qa, a0, qa0, a1) + travel(b_, measured_.qb, b0, qb0, b1) + kClearanceSlack <
           measured_.clearance;
  }

  const ScheduleView* view_;
  const Schedule* schedule_;
  const CollisionScene* scene_;
  CollisionChecker* checker_;
  int a_, b_;
  KnownFree known_free_;
  std::vector<Millis> points_;  ///< both robots' point times after the first check time, sorted
  std::size_t point_ = 0;       ///< the first of points_ after start_ (or before)
  Millis start_ = 0;            ///< the next interval's start
  double checked_ = std::numeric_limits<double>::infinity();
  /// both robots standing as they stood in the last interval checked: nothing new to check
  std::optional<std::pair<RobotState, RobotState>> standing_;
  /// the last sample whose clearance was measured: robots that together travel less than it
  /// from there (holding the same) are free
  struct Measured {
    Eigen::VectorXd qa, qb;
    std::optional<HeldObject> held_a, held_b;
    double clearance = -1.0;
  } measured_;
};

/// firstConflict, with what a search node knows per robot pair (index a * robots + b, a < b):
/// `known` (may be null) lists intervals already known free, an interval [t0, t1] of pair ab
/// being skipped when t1 <= known->checked[ab] and t1 < known->same[ab] (below `same` the two
/// robots do what they did in the schedule that was checked, whose grid it shares). `checked`
/// (may be null) receives per pair the time up to which every interval was found free (the
/// start of the first interval not checked or colliding; infinity when all were free).
/// The pairs are checked side by side along time, kCheckWindow at a time, so that none is
/// checked far beyond the earliest conflict; of two at the same time, the first pair's counts.
std::optional<RobotConflict> firstConflictPairs(const MotionHypergraph& graph, const ScheduleView& view,
                                                const Schedule& schedule, double from, const PairKnowledge* known,
                                                std::vector<double>* checked) {
  CollisionChecker checker(graph.scene());
  const std::size_t robots = graph.world().world->robots.size();
  std::vector<PairCheck> pairs;
  std::vector<std::size_t> index;  // of each pair: a * robots + b
  for (std::size_t ra = 0; ra < robots; ++ra) {
    for (std::size_t rb = ra + 1; rb < robots; ++rb) {
      const auto& spec_a = graph.world().world->robots[ra];
      const auto& spec_b = graph.world().world->robots[rb];
      if ((spec_a.X_WBase.translation() - spec_b.X_WBase.translation()).norm() > kFarApart) continue;
      const std::size_t pair = ra * robots + rb;
      pairs.emplace_back(view, schedule, graph.scene(), checker, static_cast<int>(ra), static_cast<int>(rb),
                         KnownFree{from, known, pair});
      index.push_back(pair);
    }
  }
  std::optional<RobotConflict> first;
  std::size_t first_pair = 0;
  for (double until = from + kCheckWindow;; until += kCheckWindow) {
    bool open = false;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (pairs[p].done()) continue;
      const std::optional<RobotConflict> conflict =
          pairs[p].advance(until, first ? first->t : std::numeric_limits<double>::infinity());
      if (conflict && (!first || conflict->t < first->t || (conflict->t == first->t && p < first_pair))) {
        first = conflict;
        first_pair = p;
      }
      open = open || !pairs[p].done();
    }
    if (!open || (first && until > first->t)) break;
  }
  if (checked != nullptr) {
    checked->assign(robots * robots, std::numeric_limits<double>::infinity());
    for (std::size_t p = 0; p < pairs.size(); ++p) (*checked)[index[p]] = pairs[p].checkedUntil();
  }
  return first;
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

}  // namespace

std::optional<RobotConflict> firstConflict(const MotionHypergraph& graph, const Schedule& schedule, double from) {
  return firstConflictPairs(graph, ScheduleView(graph, schedule), schedule, from, nullptr, nullptr);
}

core::ArmConfig scheduledArm(const MotionHypergraph& graph, const Schedule& schedule, int robot, double t) {
  if (robot < 0 || static_cast<std::size_t>(robot) >= graph.world().world->robots.size()) {
    throw std::out_of_range("scheduledArm: no robot " + std::to_string(robot));
  }
  return ScheduleView(graph, schedule).at(robot, t, true).q;
}

ConflictResult resolveConflicts(MotionHypergraph& graph, const TransitionHistory& history,
                                const ConflictResolutionBudget& budget, SequentialSteps steps) {
  ConflictResult result;
  const std::vector<ScheduleSegment> base = segmentsOf(graph, history);
  CollisionChecker checker(graph.scene());
  const int robots = static_cast<int>(graph.world().world->robots.size());

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
  // which open node comes next: along time, the one free of conflicts for longest (ties: the
  // shortest); by makespan the same, among those at most focal_weight times the shortest; depth
  // first, the one made to resolve the latest conflict, so that the children of the node that
  // got furthest come first (ties as along time)
  const bool depth_first = budget.order == NodeOrder::kDepthFirst;
  const auto deeper = [depth_first](const Node& x, const Node& y) {
    const auto key = [&](const Node& n) {
      return std::make_tuple(depth_first ? -n.resolves : 0.0, -n.clear_until, n.schedule.makespan, n.constraints(),
                             n.order);
    };
    return key(x) < key(y);
  };
  std::vector<Node> open;
  const auto take_next = [&]() {
    // the shortest always qualifies, whatever the weight
    std::size_t next = 0;
    double bound = std::numeric_limits<double>::infinity();
    if (budget.order == NodeOrder::kMakespan) {
      next = static_cast<std::size_t>(std::min_element(open.begin(), open.end(), [](const Node& x, const Node& y) {
                                        return x.schedule.makespan < y.schedule.makespan;
                                      }) -
                                      open.begin());
      bound = budget.focal_weight * static_cast<double>(open[next].schedule.makespan);
    }
    for (std::size_t i = 0; i < open.size(); ++i) {
      if (static_cast<double>(open[i].schedule.makespan) <= bound && deeper(open[i], open[next])) next = i;
    }
    Node node = std::move(open[next]);
    if (next + 1 != open.size()) open[next] = std::move(open.back());
    open.pop_back();
    return node;
  };
  std::uint64_t created = 0;
  // a node: its segments at the earliest times their temporal network allows
  const auto make = [&](std::vector<ScheduleSegment> segments, std::vector<Precedence> extra,
                        std::vector<DetourConstraint> detours, int parkings, bool folded) -> std::optional<Node> {
    std::vector<Edge> edges = baseConstraints(graph, history, segments, steps);
    for (const Precedence& p : extra) edges.push_back(edgeOf(p, segments));
    std::optional<std::vector<Millis>> start = earliestStarts(segments.size(), edges);
    if (!start) return std::nullopt;
    Schedule schedule;
    schedule.segments = std::move(segments);
    schedule.start = std::move(*start);
    schedule.makespan = makespanOf(schedule);
    return Node{std::move(extra), std::move(detours), parkings, folded, std::move(schedule), created++, 0.0, 0.0,
                std::nullopt};
  };
  // Reroutes already tried, by kind (detour or parking), move and states to keep clear of (in
  // any order): the same conflict comes back in many nodes, and asked again a reroute takes the
  // answer found before (a new search could differ only where the roadmap grew meanwhile). Only
  // new ones count against max_reroutes: the nodes below a folded robot's and the others each
  // have that many, so that the search behind a fold does not use up those of a way without one.
  using MoveParts = std::pair<const Move*, const Move*>;  // a detour: the first only
  struct Reroute {
    bool parking = false;
    const Move* move = nullptr;
    std::vector<Obstacle> avoid;
    std::optional<MoveParts> parts;
    bool folded = false;  ///< asked for below a fold
  };
  std::vector<Reroute> tried;
  const auto reroute = [&](const Node& node, bool parking, const Move& move, const std::vector<Obstacle>& avoid,
                           const std::function<std::optional<MoveParts>()>& plan) -> std::optional<MoveParts> {
    const auto known = std::find_if(tried.begin(), tried.end(), [&](const Reroute& r) {
      return r.parking == parking && r.move == &move && r.avoid.size() == avoid.size() &&
             std::is_permutation(avoid.begin(), avoid.end(), r.avoid.begin(), sameObstacle);
    });
    if (known != tried.end()) return known->parts;
    const auto same_side = [&](const Reroute& r) { return r.folded == node.folded; };
    if (std::count_if(tried.begin(), tried.end(), same_side) >= budget.max_reroutes) return std::nullopt;
    tried.push_back({parking, &move, avoid, plan(), node.folded});
    return tried.back().parts;
  };
  // the child whose move `segment` takes a path on its roadmap that also keeps clear of `avoid`
  const auto detoured = [&](const Node& node, int segment, std::vector<Obstacle> avoid) -> std::optional<Node> {
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
      const Move* move = graph.detour(*it->original, [&](const core::ArmConfig& a, const core::ArmConfig& b) {
        return checker.motionClearOf(seg.robot, graph.scene().configuration(seg.robot, a, seg.finger),
                                     graph.scene().configuration(seg.robot, b, seg.finger), seg.held, obstacles);
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
  };
  // the child where the robot, instead of standing where move `segment` starts, goes early to a
  // configuration clear of `avoid` and waits there: the move split in two at that parking. A
  // parking is the nearest roadmap node clear of `avoid` or, with `fold` (a robot alone), its
  // folded configuration, further off but out of the shared workspace, where the next robot
  // coming through does not meet it either. Folding is two moves move() caches, not a roadmap
  // search for `avoid`: it is not counted against max_reroutes.
  const auto parked = [&](const Node& node, int segment, const std::vector<Obstacle>& avoid,
                          bool fold) -> std::optional<Node> {
    const ScheduleSegment& seg = node.schedule.segments[segment];
    // a robot's way to a parking is not parked again: it would only go somewhere else first, in
    // a chain of parkings that stand in the same robot's way
    if (seg.to_parking || avoid.size() > kMaxParkingObstacles || (fold && seg.held)) return std::nullopt;
    const auto clear = [&](const core::ArmConfig& q) {
      const Eigen::VectorXd f = graph.scene().configuration(seg.robot, q, seg.finger);
      return std::all_of(avoid.begin(), avoid.end(), [&](const Obstacle& o) {
        return checker.robotsFree(seg.robot, f, seg.held, o.robot, o.q, o.held);
      });
    };
    const core::ArmConfig& folded = graph.idleConfiguration(seg.robot, IdlePose::kFolded);
    const std::optional<MoveParts> split =
        !fold ? reroute(node, true, *seg.move, avoid, [&] { return graph.parking(*seg.move, clear); })
        : clear(folded) ? graph.parkingAt(*seg.move, folded)
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
  };

  if (std::optional<Node> root = make(base, {}, {}, 0, false)) {
    result.unresolved_makespan = root->schedule.makespan;
    if (budget.makespan_below && root->schedule.makespan >= *budget.makespan_below) {
      result.reason = "no schedule is shorter than " + std::to_string(*budget.makespan_below) + " ms";
      return result;
    }
    open.push_back(std::move(*root));
  } else {
    result.reason = "the schedule's own precedences contradict each other";
    return result;
  }
  while (!open.empty()) {
    if (result.nodes >= budget.max_nodes || (budget.stop && budget.stop())) {
      result.status = ConflictStatus::kBudget;
      return result;
    }
    Node node = take_next();
    ++result.nodes;
    const ScheduleView view(graph, node.schedule);
    std::vector<double> checked;
    const std::optional<RobotConflict> conflict =
        firstConflictPairs(graph, view, node.schedule, node.clear_until, node.known ? &*node.known : nullptr, &checked);
    if (!conflict) {
      result.status = ConflictStatus::kResolved;
      result.constraints = static_cast<int>(node.constraints());
      result.schedule = std::move(node.schedule);
      return result;
    }
    result.reason = describe(graph, *conflict);
    const int ra = conflict->robot_a, rb = conflict->robot_b;
    // a child repeats this schedule, free before the conflict, until their first difference
    const auto push = [&](Node child) {
      if (budget.makespan_below && child.schedule.makespan >= *budget.makespan_below) return false;
      const std::vector<double> differ = firstDifferences(node.schedule, child.schedule, robots);
      child.clear_until = std::min(conflict->t, *std::min_element(differ.begin(), differ.end()));
      child.resolves = conflict->t;
      // per robot pair: what this node found free, as long as both robots do the same
      PairKnowledge known{checked, std::vector<double>(checked.size(), 0.0)};
      for (int a = 0; a < robots; ++a) {
        for (int b = a + 1; b < robots; ++b) known.same[a * robots + b] = std::min(differ[a], differ[b]);
      }
      child.known = std::move(known);
      open.push_back(std::move(child));
      return true;
    };
    // time: A before B, B before A
    bool ordered = false;
    for (const bool a_first : {true, false}) {
      const std::optional<Precedence> p = a_first ? precedence(view, ra, conflict->item_a, rb, conflict->item_b)
                                                  : precedence(view, rb, conflict->item_b, ra, conflict->item_a);
      if (!p || std::find(node.extra.begin(), node.extra.end(), *p) != node.extra.end()) continue;
      std::vector<Precedence> extra = node.extra;
      extra.push_back(*p);
      std::optional<Node> child = make(node.schedule.segments, extra, node.detours, node.parkings, node.folded);
      // a move into a transition that cannot end before the other starts just in time (both
      // robots going into one handoff) may arrive early and wait in front of it
      const std::vector<ScheduleSegment>& segments = node.schedule.segments;
      const int a = p->from;
      if (!child && p->from_end && segments[a].move != nullptr && !segments[a].early &&
          a + 1 < static_cast<int>(segments.size()) && segments[a + 1].robot == segments[a].robot &&
          segments[a + 1].motion != nullptr) {
        std::vector<ScheduleSegment> early = segments;
        early[a].early = true;
        child = make(std::move(early), std::move(extra), node.detours, node.parkings, node.folded);
      }
      // an order whose schedule is not below the bound leaves the conflict to a reroute
      if (child && push(std::move(*child))) ordered = true;
    }
    // space, when time cannot help: a robot on a move takes a detour around where the other one
    // is meanwhile; a robot standing before a move waits somewhere out of the other one's way
    if (ordered) continue;
    const int ta = transitionOf(history, node.schedule, view.timeline(ra), conflict->item_a);
    const int tb = transitionOf(history, node.schedule, view.timeline(rb), conflict->item_b);
    if (ta >= 0 && tb >= 0 && ta != tb) {
      const std::pair<int, int> pair = std::minmax(ta, tb);
      if (std::find(result.unordered.begin(), result.unordered.end(), pair) == result.unordered.end()) {
        result.unordered.push_back(pair);
      }
    }
    // standing at home before its first segment (item -1) — in a sequential history, standing
    // at home at all: the other's transition meets home
    const auto at_home = [&](int robot, int item) {
      return item == -1 || (history.sequential && item < 0 &&
                            view.at(robot, conflict->t, false).q == graph.world().world->robots[robot].home);
    };
    for (const auto& [transition, item, robot] : {std::tuple{ta, conflict->item_b, rb}, std::tuple{tb, conflict->item_a, ra}}) {
      const std::pair<int, int> blocked{transition, robot};
      if (transition >= 0 && at_home(robot, item) &&
          std::find(result.home_blocked.begin(), result.home_blocked.end(), blocked) == result.home_blocked.end()) {
        result.home_blocked.push_back(blocked);
      }
    }
    const std::vector<ScheduleSegment>& segments = node.schedule.segments;
    for (const auto& [robot, item, other, other_item] :
         {std::tuple{ra, conflict->item_a, rb, conflict->item_b}, std::tuple{rb, conflict->item_b, ra, conflict->item_a}}) {
      const Timeline& line = view.timeline(robot);
      if (item >= 0) {
        const int segment = line.segments[item];
        if (segments[segment].move == nullptr) continue;
        if (std::optional<Node> child = detoured(node, segment, obstaclesDuring(view, node.schedule, segment, other))) {
          push(std::move(*child));
        }
      } else if (const int k = -1 - item; k < static_cast<int>(line.segments.size()) && other_item >= 0) {
        const int segment = line.segments[k];
        if (segments[segment].move == nullptr) continue;
        // standing no time at all: the conflict is where the segment before ends, no parking helps
        if (k > 0) {
          const int before = line.segments[k - 1];
          if (node.schedule.start[before] + segments[before].duration >= node.schedule.start[segment]) continue;
        }
        const int busy = view.timeline(other).segments[other_item];
        const std::vector<Obstacle> avoid = obstaclesDuring(view, node.schedule, busy, other);
        for (const bool fold : {false, true}) {
          if (std::optional<Node> child = parked(node, segment, avoid, fold)) push(std::move(*child));
        }
      }
    }
  }
  result.status = ConflictStatus::kUnresolvable;
  return result;
}

}  // namespace dashbed::planner
