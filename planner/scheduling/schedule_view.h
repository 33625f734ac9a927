#pragma once
// A schedule seen along time: where each robot is at any time t — its arm configuration on a
// move's time-optimal profile or on a transition's key curve (the one the simulator's
// interpolator follows), its fingers and its held object — and how fast it moves there.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/trajectory_interpolator.h"
#include "planner/scheduling/schedule.h"

namespace dashbed::planner {

/// Holding the same object in the same grasp (or both nothing).
bool sameHeld(const std::optional<HeldObject>& x, const std::optional<HeldObject>& y);

/// The robot's timeline in a schedule: its segments (global indices), their point times (path
/// waypoints or transition keys, from the segment's start) and, for transitions, their key curves.
struct Timeline {
  std::vector<int> segments;
  std::vector<std::vector<Millis>> times;
  std::vector<std::optional<core::TrajectoryInterpolator>> curves;
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
bool sameState(const RobotState& x, const RobotState& y);

class ScheduleView {
 public:
  /// `graph` and `schedule` must outlive the view.
  ScheduleView(const MotionHypergraph& graph, const Schedule& schedule);

  const Timeline& timeline(int robot) const { return timelines_[robot]; }

  /// The state of `robot` at time t [s]. At an instant where two pieces meet, `after` picks the
  /// later one's fingers and held object.
  RobotState at(int robot, double t, bool after) const;

  /// Over [t0, t1], which no point time of `robot` lies strictly within and during which it is
  /// on `item` (RobotState::item at t0): its peak speed over its mean speed
  /// (restToRestPeakOverMean on a move's piece, curvePeakOverMean between a transition's keys;
  /// 1 standing).
  double peakOverMeanSpeed(int robot, int item, double t0, double t1) const;

  /// Whether `robot` follows a transition's key curve on `item` (RobotState::item).
  bool onCurve(int robot, int item) const { return item >= 0 && timelines_[robot].curves[item].has_value(); }

  /// The configuration the collision checker wants for `robot` in `state`.
  Eigen::VectorXd full(int robot, const RobotState& state) const;

 private:
  /// `curve`: a transition's key curve (keyCurve).
  void evaluate(const ScheduleSegment& seg, const std::vector<Millis>& times,
                const std::optional<core::TrajectoryInterpolator>& curve, double tau, bool after,
                RobotState& state) const;

  const MotionHypergraph* graph_;
  const Schedule* schedule_;
  std::vector<Timeline> timelines_;
  std::vector<std::vector<double>> starts_;  // [robot][k] start of its segment k [s]
  std::vector<std::vector<double>> ends_;    // [robot][k] end of its segment k [s]
};

/// The arm configuration of `robot` at time t [s] of a schedule, as the robots are checked
/// against each other (at an instant where two segments meet, the later one's).
core::ArmConfig scheduledArm(const MotionHypergraph& graph, const Schedule& schedule, int robot, double t);

}  // namespace dashbed::planner
