#pragma once
// A plan as programs for the real robots (`dashbed export`): per robot a URScript program, a
// ROS 2 FollowJointTrajectory goal with a gripper timeline, or a CSV table. Each follows the
// plan's interpolated curve (core::TrajectoryInterpolator), the one the simulator tracked and
// the readiness check judged. Formats and how to run them: docs/export.md.

#include <string>
#include <vector>

#include "tools/export/export_timeline.h"

namespace dashbed::exporting {

struct ExportOptions {
  /// Spacing of the ROS 2 and CSV samples [s], besides the plan's own points; finer follows the
  /// curve closer between samples, in longer files.
  double sample_step = 0.008;
  /// servoj period [s]: the e-Series control period, 500 Hz (UR's ROS 2 driver, ur5e_update_rate.yaml).
  double servo_period = 0.002;
  /// servoj lookahead_time [s], 0.03-0.2 (URScript manual): longer smooths the tracking, lags more.
  double lookahead = 0.1;
  /// servoj gain, 100-2000 (URScript manual): higher tracks tighter, risks oscillation.
  double gain = 300.0;
  /// The synchronisation server the URScript programs connect to (tools/export/dashbed_sync.py).
  std::string sync_host = "127.0.0.1";
  int sync_port = 30700;
  /// Lines for the header comment of every file (world, plan, the checks it passed).
  std::vector<std::string> header;
};

/// One file of an export: its name within the output directory and its text.
struct ExportFile {
  std::string name;
  std::string text;
};

/// Per robot ROBOT.script; and sync.json, the synchronisation points for the server.
std::vector<ExportFile> exportUrScript(const ExportTimeline& timeline, const ExportOptions& options);
/// Per robot ROBOT.trajectory.yaml (a control_msgs/FollowJointTrajectory goal) and
/// ROBOT.gripper.yaml (the gripper timeline and synchronisation points).
std::vector<ExportFile> exportRos2(const ExportTimeline& timeline, const ExportOptions& options);
/// Per robot ROBOT.csv: time, joint positions and velocities, the gripper's commanded opening
/// and force.
std::vector<ExportFile> exportCsv(const ExportTimeline& timeline, const ExportOptions& options);

/// The JSON list of synchronisation points: [{"index", "t", "robots", "why"}, ...].
std::string syncJson(const ExportTimeline& timeline);

}  // namespace dashbed::exporting
