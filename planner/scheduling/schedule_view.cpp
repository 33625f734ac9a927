#include "planner/scheduling/schedule_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "planner/sampling/key_curve.h"

namespace dashbed::planner {
namespace {

/// `ms` rounded to the whole millisecond it misses by a rounding error only.
double snapToMillis(double ms) {
  const double whole = std::round(ms);
  return std::abs(ms - whole) < 1e-6 ? whole : ms;
}

/// Local times of the points of a segment (path waypoints or transition keys) [ms].
std::vector<Millis> pointTimes(const ScheduleSegment& seg, const MotionHypergraph& graph) {
  std::vector<Millis> times;
  if (seg.motion != nullptr) {
    for (const TransitionMotion::Key& key : seg.motion->keys) times.push_back(key.t);
    return times;
  }
  times.push_back(0);
  for (std::size_t i = 1; i < seg.move->path.size(); ++i) {
    times.push_back(times.back() +
                    restToRestDuration(seg.move->path[i - 1], seg.move->path[i], graph.pieceTiming(*seg.move, i - 1)));
  }
  return times;
}

/// The piece i of a segment with point times `times` with times[i] <= tau < times[i + 1] (or
/// <= with !after), tau [s] from the segment's start; tau, a difference of seconds, may miss a
/// whole-millisecond key by a rounding error (1.009 s is 1008.9999... ms): at a key it counts
/// as the key.
std::size_t pieceAt(const std::vector<Millis>& times, double tau, bool after) {
  const double tau_ms = snapToMillis(tau * 1000.0);
  const auto next = after ? std::upper_bound(times.begin() + 1, times.end(), tau_ms,
                                             [](double v, Millis x) { return v < static_cast<double>(x); })
                          : std::lower_bound(times.begin() + 1, times.end(), tau_ms,
                                             [](Millis x, double v) { return static_cast<double>(x) < v; });
  return std::min<std::size_t>(static_cast<std::size_t>(next - times.begin()) - 1,
                               times.size() >= 2 ? times.size() - 2 : 0);
}

}  // namespace

bool sameHeld(const std::optional<HeldObject>& x, const std::optional<HeldObject>& y) {
  return x.has_value() == y.has_value() && (!x || (x->object == y->object && x->X_TO.isApprox(y->X_TO, 0.0)));
}

bool sameState(const RobotState& x, const RobotState& y) {
  return x.q == y.q && x.finger == y.finger && sameHeld(x.held, y.held);
}

ScheduleView::ScheduleView(const MotionHypergraph& graph, const Schedule& schedule)
    : graph_(&graph), schedule_(&schedule) {
  timelines_.resize(graph.world().world->robots.size());
  starts_.resize(timelines_.size());
  ends_.resize(timelines_.size());
  for (std::size_t s = 0; s < schedule.segments.size(); ++s) {
    const int robot = schedule.segments[s].robot;
    timelines_[robot].segments.push_back(static_cast<int>(s));
    timelines_[robot].times.push_back(pointTimes(schedule.segments[s], graph));
    const TransitionMotion* motion = schedule.segments[s].motion;
    timelines_[robot].curves.push_back(motion != nullptr ? std::optional(keyCurve(*motion)) : std::nullopt);
    starts_[robot].push_back(toSeconds(schedule.start[s]));
    // from whole milliseconds: the same double as the key time it ends at, with no rounding
    // error of a sum of seconds
    ends_[robot].push_back(toSeconds(schedule.start[s] + schedule.segments[s].duration));
  }
}

RobotState ScheduleView::at(int robot, double t, bool after) const {
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

double ScheduleView::peakOverMeanSpeed(int robot, int item, double t0, double t1) const {
  if (item < 0) return 1.0;
  const ScheduleSegment& seg = schedule_->segments[timelines_[robot].segments[item]];
  const std::vector<Millis>& times = timelines_[robot].times[item];
  const double start = starts_[robot][item];
  if (seg.motion != nullptr) return curvePeakOverMean(*timelines_[robot].curves[item], t0 - start, t1 - start);
  if (seg.move->path.size() < 2) return 1.0;
  const std::size_t i = pieceAt(times, t0 - start, true);
  const double piece_start = start + toSeconds(times[i]);
  return restToRestPeakOverMean(seg.move->path[i], seg.move->path[i + 1], times[i + 1] - times[i],
                                t0 - piece_start, t1 - piece_start, graph_->pieceTiming(*seg.move, i));
}

Eigen::VectorXd ScheduleView::full(int robot, const RobotState& state) const {
  return graph_->scene().configuration(robot, state.q, state.finger);
}

void ScheduleView::evaluate(const ScheduleSegment& seg, const std::vector<Millis>& times,
                            const std::optional<core::TrajectoryInterpolator>& curve, double tau, bool after,
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
  state.q = restToRestAt(path[i], path[i + 1], times[i + 1] - times[i], tau - toSeconds(times[i]),
                         graph_->pieceTiming(*seg.move, i))
                .first;
}

core::ArmConfig scheduledArm(const MotionHypergraph& graph, const Schedule& schedule, int robot, double t) {
  if (robot < 0 || static_cast<std::size_t>(robot) >= graph.world().world->robots.size()) {
    throw std::out_of_range("scheduledArm: no robot " + std::to_string(robot));
  }
  return ScheduleView(graph, schedule).at(robot, t, true).q;
}

}  // namespace dashbed::planner
