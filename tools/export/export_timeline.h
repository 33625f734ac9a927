#pragma once
// What every export of a plan shares: the curve each robot follows (the plan's interpolated
// curve, core::TrajectoryInterpolator, the one the simulator tracks), each robot's gripper
// commands with their force and speed resolved, and the synchronisation points of the robots'
// programs (a common start, and the start of every handoff for its two robots).

#include <string>
#include <vector>

#include "core/plan.h"
#include "core/trajectory_interpolator.h"
#include "core/world.h"

namespace dashbed::exporting {

/// One gripper command with what the Hand-E is asked for.
struct GripperStep {
  double t = 0.0;           ///< plan time [s]
  core::GripperAction action = core::GripperAction::kOpen;
  double position = 0.0;    ///< target opening between the fingers [m]: the stroke (open) or 0 (close, until contact)
  double force = 0.0;       ///< grip force [N]: the command's, or the world's controller.grip_force
  double speed = 0.0;       ///< finger speed [m/s]: the world's controller.finger_speed
};

/// A point all the robots in `robots` reach before any goes on.
struct SyncPoint {
  int index = 0;                    ///< 0 = the common start
  double t = 0.0;                   ///< plan time [s]
  std::vector<std::string> robots;  ///< robot names, in the world's order
  std::string why;                  ///< "start", "handoff cube_2 r1 -> r0"
};

/// One robot's part of an exported plan.
struct RobotTimeline {
  std::string robot;
  std::array<std::string, 6> joint_names;
  std::vector<core::TrajectoryPoint> points;  ///< the plan's points, velocities filled in from the curve
  std::vector<GripperStep> gripper;           ///< in time order
  std::vector<SyncPoint> syncs;               ///< those the robot takes part in, in time order
};

/// Every robot's timeline, in the plan's robot order, and the plan's end time [s].
struct ExportTimeline {
  std::string world;
  double end = 0.0;
  std::vector<RobotTimeline> robots;
  std::vector<SyncPoint> syncs;  ///< all of them, in time order
};

/// Builds the timeline of `plan` (which must have passed core::validatePlan for `world`).
ExportTimeline exportTimeline(const core::Plan& plan, const core::World& world);

/// Times [s] at which the curve of `points` is written as samples: every `step` from the first
/// point's time, every point's own time, and the end; sorted, without duplicates (within 1 us).
std::vector<double> sampleTimes(const std::vector<core::TrajectoryPoint>& points, double step);

}  // namespace dashbed::exporting
