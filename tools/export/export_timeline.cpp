#include "tools/export/export_timeline.h"

#include <algorithm>
#include <cmath>

#include "core/hande.h"

namespace dashbed::exporting {
namespace {

/// Sample times closer than this are one [s].
constexpr double kSameTime = 1e-6;

}  // namespace

ExportTimeline exportTimeline(const core::Plan& plan, const core::World& world) {
  ExportTimeline timeline;
  timeline.world = world.name;
  timeline.end = plan.duration();

  // sync points: the common start, then each handoff's start for its two robots
  SyncPoint start{0, 0.0, {}, "start"};
  for (const core::RobotTrajectory& trajectory : plan.trajectories) start.robots.push_back(trajectory.robot);
  timeline.syncs.push_back(start);
  std::vector<const core::PlanAction*> handoffs;
  for (const core::PlanAction& a : plan.actions) {
    if (a.type == core::ActionType::kHandoff) handoffs.push_back(&a);
  }
  std::stable_sort(handoffs.begin(), handoffs.end(),
                   [](const core::PlanAction* a, const core::PlanAction* b) { return a->start < b->start; });
  for (const core::PlanAction* a : handoffs) {
    SyncPoint sync{static_cast<int>(timeline.syncs.size()), a->start, {a->robot, a->receiver},
                   "handoff " + a->object + " " + a->robot + " -> " + a->receiver};
    std::sort(sync.robots.begin(), sync.robots.end(), [&](const std::string& x, const std::string& y) {
      return world.findRobot(x) < world.findRobot(y);  // the world's order
    });
    timeline.syncs.push_back(sync);
  }

  for (const core::RobotTrajectory& trajectory : plan.trajectories) {
    RobotTimeline robot;
    robot.robot = trajectory.robot;
    robot.joint_names = trajectory.joint_names;
    const core::TrajectoryInterpolator curve(trajectory.points);
    for (const core::TrajectoryPoint& p : trajectory.points) robot.points.push_back({p.t, p.q, curve.at(p.t).qd});
    for (const core::GripperCommand& c : plan.gripper) {
      if (c.robot != trajectory.robot) continue;
      const bool close = c.action == core::GripperAction::kClose;
      robot.gripper.push_back({c.t, c.action, close ? 0.0 : core::kHandeMaxOpening,
                               c.force > 0.0 ? c.force : world.controller.grip_force, world.controller.finger_speed});
    }
    std::stable_sort(robot.gripper.begin(), robot.gripper.end(),
                     [](const GripperStep& a, const GripperStep& b) { return a.t < b.t; });
    for (const SyncPoint& sync : timeline.syncs) {
      if (std::find(sync.robots.begin(), sync.robots.end(), robot.robot) != sync.robots.end()) robot.syncs.push_back(sync);
    }
    timeline.robots.push_back(std::move(robot));
  }
  return timeline;
}

std::vector<double> sampleTimes(const std::vector<core::TrajectoryPoint>& points, double step) {
  std::vector<double> own;  // the points' times, strictly increasing
  for (const core::TrajectoryPoint& p : points) own.push_back(p.t);
  std::vector<double> times = own;
  if (own.empty()) return times;
  const auto steps = static_cast<long>(std::floor((own.back() - own.front()) / step + kSameTime));
  for (long k = 1; k <= steps; ++k) {
    const double t = own.front() + static_cast<double>(k) * step;
    const auto next = std::lower_bound(own.begin(), own.end(), t);
    const bool near_next = next != own.end() && *next - t <= kSameTime;
    const bool near_previous = next != own.begin() && t - *(next - 1) <= kSameTime;
    if (!near_next && !near_previous) times.push_back(t);
  }
  std::sort(times.begin(), times.end());
  return times;
}

}  // namespace dashbed::exporting
