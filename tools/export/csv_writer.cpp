// CSV: per robot, the plan's curve at its samples and the gripper command in effect.
#include <sstream>

#include "core/hande.h"
#include "core/number_text.h"
#include "tools/export/plan_export.h"

namespace dashbed::exporting {
namespace {

std::string table(const RobotTimeline& robot, const ExportOptions& o) {
  std::ostringstream out;
  out << "t";
  for (const std::string& name : robot.joint_names) out << "," << name;
  for (const std::string& name : robot.joint_names) out << "," << name << "_velocity";
  out << ",gripper_opening,gripper_force\n";
  const core::TrajectoryInterpolator curve(robot.points);
  std::size_t command = 0;
  double opening = core::kHandeMaxOpening, force = 0.0;
  for (const double t : sampleTimes(robot.points, o.sample_step)) {
    for (; command < robot.gripper.size() && robot.gripper[command].t <= t; ++command) {
      opening = robot.gripper[command].position;
      force = robot.gripper[command].force;
    }
    const core::JointReference ref = curve.at(t);
    out << core::shortestText(t);
    for (const double q : ref.q) out << "," << core::shortestText(q);
    for (const double qd : ref.qd) out << "," << core::shortestText(qd);
    out << "," << core::shortestText(opening) << "," << core::shortestText(force) << "\n";
  }
  return out.str();
}

}  // namespace

std::vector<ExportFile> exportCsv(const ExportTimeline& timeline, const ExportOptions& options) {
  std::vector<ExportFile> files;
  for (const RobotTimeline& robot : timeline.robots) files.push_back({robot.robot + ".csv", table(robot, options)});
  return files;
}

}  // namespace dashbed::exporting
