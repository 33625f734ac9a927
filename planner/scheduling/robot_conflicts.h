#pragma once
// Robot against robot, continuously in time: the check of a schedule that conflict resolution
// (scheduled_cbs.h) runs on each of its nodes, and that tests run to confirm a result.
//
// Each pair of robots whose bases are near enough to touch is checked at both robots' exact
// configurations — a move on its time-optimal profile, a transition on the cubic through its
// keys that the simulator's interpolator follows (core::TrajectoryInterpolator, at rest
// at the first and last key; ScheduleView) — at a grid of times fine enough that no point of
// either robot (held object included) moves more than the collision scene's motion_step
// between two checks, so the margin covers the motion in between: the times of every segment
// and key, plus a 20 ms grid, each interval split into the larger of the two robots'
// CollisionScene::motionSteps times its peak over mean speed there (1 while cruising, up to 2
// on a move's ramp from or to rest, up to 3 between keys, where each joint is monotone).
// Samples, and whole intervals, within the clearance of the last sample measured
// (CollisionChecker::robotsClearance) are free and are not evaluated; so are the two robots of
// a handoff during it (checked against each other when it was sampled). The robot pairs are
// checked side by side along time (a second at a time), so that none is checked much beyond
// the earliest conflict.

#include <optional>
#include <vector>

#include "planner/scheduling/schedule_view.h"

namespace dashbed::planner {

/// Where two robots first collide: the time [s], the robots and what each was doing.
struct RobotConflict {
  double t = 0.0;
  int robot_a = -1, robot_b = -1;
  /// the robot's k-th segment (counted along that robot's timeline, not an index into
  /// Schedule::segments), or -1 - k for standing still before its k-th segment
  int item_a = -1, item_b = -1;
};

/// Checks a schedule robot against robot; returns the first colliding time and robots, or
/// std::nullopt when none collide. `from` [s]: the schedule is known to be free before it (only
/// intervals ending after it are checked).
std::optional<RobotConflict> firstConflict(const MotionHypergraph& graph, const Schedule& schedule, double from = 0.0);

/// What a search node knows about its schedule per robot pair (index a * robots + b, a < b),
/// from checking its parent's.
struct PairKnowledge {
  std::vector<double> checked;  ///< [s] every interval ending by then is free in the schedule checked
  std::vector<double> same;     ///< [s] the two robots do the same as there before then
};

/// firstConflict on `view` (of `schedule`), with what a search node knows: `known` (may be
/// null) lists intervals already known free, an interval [t0, t1] of pair ab being skipped when
/// t1 <= known->checked[ab] and t1 < known->same[ab] (below `same` the two robots do what they
/// did in the schedule that was checked, whose grid it shares). `checked` (may be null)
/// receives per pair the time up to which every interval was found free (the start of the
/// first interval not checked or colliding; infinity when all were free). Of two conflicts at
/// the same time, the first pair's (in the order of a, then b) is returned.
std::optional<RobotConflict> firstConflictPairs(const MotionHypergraph& graph, const ScheduleView& view,
                                                const Schedule& schedule, double from, const PairKnowledge* known,
                                                std::vector<double>* checked);

}  // namespace dashbed::planner
