// ROS 2: a control_msgs/FollowJointTrajectory goal per robot, with positions, velocities and
// accelerations of the plan's curve at its samples, and the gripper timeline beside it.
#include <cmath>
#include <sstream>

#include "core/number_text.h"
#include "tools/export/plan_export.h"
#include "tools/export/robotiq.h"

namespace dashbed::exporting {
namespace {

std::string list(const core::Vector6& v) {
  std::string text = "[";
  for (int j = 0; j < 6; ++j) text += (j ? ", " : "") + core::shortestText(v[j]);
  return text + "]";
}

/// builtin_interfaces/Duration of t [s], to the nanosecond.
std::string duration(double t) {
  const long long ns = std::llround(t * 1e9);
  return "{sec: " + std::to_string(ns / 1000000000) + ", nanosec: " + std::to_string(ns % 1000000000) + "}";
}

void header(std::ostringstream& out, const ExportTimeline& timeline, const RobotTimeline& robot,
            const ExportOptions& o, const std::string& what) {
  out << "# dashbed: " << what << " for robot " << robot.robot << " of world " << timeline.world << "\n";
  for (const std::string& line : o.header) out << "# " << line << "\n";
}

std::string trajectoryGoal(const ExportTimeline& timeline, const RobotTimeline& robot, const ExportOptions& o) {
  std::ostringstream out;
  header(out, timeline, robot, o, "control_msgs/action/FollowJointTrajectory goal");
  out << "# Samples of the plan's curve every " << core::shortestText(o.sample_step)
      << " s and at its own points; send it with docs/export.md.\n"
      << "trajectory:\n"
      << "  joint_names: [";
  for (int j = 0; j < 6; ++j) out << (j ? ", " : "") << robot.joint_names[j];
  out << "]\n"
      << "  points:\n";
  const core::TrajectoryInterpolator curve(robot.points);
  for (const double t : sampleTimes(robot.points, o.sample_step)) {
    const core::JointReference ref = curve.at(t);
    out << "    - positions: " << list(ref.q) << "\n"
        << "      velocities: " << list(ref.qd) << "\n"
        << "      accelerations: " << list(ref.qdd) << "\n"
        << "      time_from_start: " << duration(t) << "\n";
  }
  out << "goal_time_tolerance: " << duration(0.5) << "\n";
  return out.str();
}

std::string gripperTimeline(const ExportTimeline& timeline, const RobotTimeline& robot, const ExportOptions& o) {
  std::ostringstream out;
  header(out, timeline, robot, o, "Robotiq Hand-E command timeline");
  out << "# position: opening between the fingers [m]; speed [m/s]; force [N]; robotiq: the same as\n"
      << "# Hand-E registers 0-255 (docs/export.md).\n"
      << "gripper:\n";
  for (const GripperStep& g : robot.gripper) {
    out << "  - time_from_start: " << duration(g.t) << "\n"
        << "    command: " << (g.action == core::GripperAction::kClose ? "close" : "open") << "\n"
        << "    position: " << core::shortestText(g.position) << "\n"
        << "    speed: " << core::shortestText(g.speed) << "\n"
        << "    force: " << core::shortestText(g.force) << "\n"
        << "    robotiq: {position: " << robotiqPosition(g.position) << ", speed: " << robotiqSpeed(g.speed)
        << ", force: " << robotiqForce(g.force) << "}\n";
  }
  out << "sync:\n";
  for (const SyncPoint& s : robot.syncs) {
    out << "  - {index: " << s.index << ", time_from_start: " << duration(s.t) << ", robots: [";
    for (std::size_t r = 0; r < s.robots.size(); ++r) out << (r ? ", " : "") << s.robots[r];
    out << "], why: \"" << s.why << "\"}\n";
  }
  return out.str();
}

}  // namespace

std::vector<ExportFile> exportRos2(const ExportTimeline& timeline, const ExportOptions& options) {
  std::vector<ExportFile> files;
  for (const RobotTimeline& robot : timeline.robots) {
    files.push_back({robot.robot + ".trajectory.yaml", trajectoryGoal(timeline, robot, options)});
    files.push_back({robot.robot + ".gripper.yaml", gripperTimeline(timeline, robot, options)});
  }
  return files;
}

}  // namespace dashbed::exporting
