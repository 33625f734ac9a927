#include "planner/plan_writer.h"

#include <algorithm>

namespace dashbed::planner {
namespace {

constexpr Millis kMoveSampleStep = 50;  // [ms] between written samples of a move

/// Appends a point unless the trajectory already has one at that time (segments meet there);
/// a velocity that point leaves to the interpolator is then taken from this one. So a
/// transition's last key, where the arm comes to rest, is written at rest even when a move
/// starts right there: interpolated, a joint going on the same way would not stop, and the arm
/// would leave the straight line the move was checked along.
void append(core::RobotTrajectory& trajectory, Millis t, const core::ArmConfig& q,
            const std::optional<core::ArmConfig>& qd) {
  const double seconds = toSeconds(t);
  if (!trajectory.points.empty() && trajectory.points.back().t >= seconds) {
    core::TrajectoryPoint& last = trajectory.points.back();
    if (last.t == seconds && !last.qd) last.qd = qd;
    return;
  }
  trajectory.points.push_back({seconds, q, qd});
}

core::ActionType actionType(TransitionKind kind) {
  switch (kind) {
    case TransitionKind::kPick:
      return core::ActionType::kPick;
    case TransitionKind::kPlace:
      return core::ActionType::kPlace;
    case TransitionKind::kHandoff:
      break;
  }
  return core::ActionType::kHandoff;
}

}  // namespace

core::Plan writePlan(const MotionHypergraph& graph, const TransitionHistory& history, const Schedule& schedule) {
  const core::World& world = *graph.world().world;
  core::Plan plan;
  plan.world = world.name;
  const core::ArmConfig at_rest{};
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    const core::RobotModel& model = *graph.world().robots->robots()[r].model;
    core::RobotTrajectory trajectory;
    trajectory.robot = world.robots[r].name;
    for (int j = 0; j < 6; ++j) trajectory.joint_names[j] = model.joints()[model.movableJoints()[j]].name;
    core::ArmConfig q = world.robots[r].home;
    append(trajectory, 0, q, at_rest);
    plan.gripper.push_back({world.robots[r].name, 0.0, core::GripperAction::kOpen, 0.0});
    for (std::size_t s = 0; s < schedule.segments.size(); ++s) {
      const ScheduleSegment& seg = schedule.segments[s];
      if (seg.robot != static_cast<int>(r)) continue;
      const Millis start = schedule.start[s];
      append(trajectory, start, q, at_rest);  // standing still until now
      if (seg.move != nullptr) {
        for (const TimedSample& sample : timePolyline(seg.move->path, graph.timing(), kMoveSampleStep, seg.move->speed_scale)) {
          append(trajectory, start + sample.t, sample.q, sample.qd);
        }
        q = seg.move->path.back();
        continue;
      }
      for (const TransitionMotion::Key& key : seg.motion->keys) append(trajectory, start + key.t, key.q, std::nullopt);
      for (const auto& [t, action] : seg.motion->grips) plan.gripper.push_back({world.robots[r].name, toSeconds(start + t), action, 0.0});
      q = seg.motion->end();
      // the robot holds its last key until the transition is over
      append(trajectory, start + seg.duration, q, at_rest);
    }
    plan.trajectories.push_back(std::move(trajectory));
  }

  // one action per transition, timed by the first of its segments
  for (std::size_t i = 0; i < history.steps.size(); ++i) {
    const TransitionSample& sample = graph.transition(history.steps[i].transition).sample;
    const TransitionHyperarc& arc = graph.taskSpace().hyperarcs().at(sample.hyperarc);
    Millis start = -1;
    for (std::size_t s = 0; s < schedule.segments.size() && start < 0; ++s) {
      if (schedule.segments[s].motion != nullptr && schedule.segments[s].step == static_cast<int>(i)) start = schedule.start[s];
    }
    core::PlanAction action;
    action.type = actionType(sample.kind);
    action.robot = world.robots[arc.robot].name;
    if (arc.kind == TransitionKind::kHandoff) action.receiver = world.robots[arc.receiver].name;
    action.object = world.objects[sample.object].name;
    if (arc.kind == TransitionKind::kPlace && arc.rest_pose == RestPose::kGoal) {
      action.region = world.regions[graph.sites().goal_region[sample.object]].name;
    }
    action.start = toSeconds(start + sample.action_start);
    action.end = toSeconds(start + sample.action_end);
    plan.actions.push_back(action);
  }
  const auto by_time = [](const auto& a, const auto& b) { return a.t < b.t; };
  std::stable_sort(plan.gripper.begin(), plan.gripper.end(), by_time);
  std::stable_sort(plan.actions.begin(), plan.actions.end(),
                   [](const core::PlanAction& a, const core::PlanAction& b) { return a.start < b.start; });
  return plan;
}

}  // namespace dashbed::planner
