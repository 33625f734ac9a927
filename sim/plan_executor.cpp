#include "sim/plan_executor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dashbed::sim {

PlanExecutor::PlanExecutor(Simulation& sim, const core::Plan& plan, double plan_time_offset)
    : sim_(sim), offset_(plan_time_offset) {
  const core::World& world = sim.world();
  const std::size_t n = world.robots.size();
  trajectories_.resize(n);
  holds_.resize(n);
  stats_.resize(n);
  for (std::size_t r = 0; r < n; ++r) {
    const core::PlacedRobot& robot = sim.robots()[r];
    const Eigen::Vector3d gravity_root = robot.spec->X_WBase.linear().transpose() * world.physics.gravity;
    arm_controllers_.push_back(
        std::make_unique<controllers::JointPdController>(*robot.model, world.controller, gravity_root));
    grippers_.emplace_back(world.controller);
    holds_[r].q = robot.spec->home;
  }
  for (const core::RobotTrajectory& trajectory : plan.trajectories) {
    const auto it = std::find_if(world.robots.begin(), world.robots.end(),
                                 [&](const core::RobotSpec& spec) { return spec.name == trajectory.robot; });
    if (it == world.robots.end()) throw std::invalid_argument("plan names an unknown robot '" + trajectory.robot + "'");
    trajectories_[static_cast<std::size_t>(it - world.robots.begin())].emplace(trajectory.points);
  }
  gripper_commands_ = plan.gripper;
  std::stable_sort(gripper_commands_.begin(), gripper_commands_.end(),
                   [](const core::GripperCommand& a, const core::GripperCommand& b) { return a.t < b.t; });
  for (const core::GripperCommand& command : gripper_commands_) {
    if (world.findRobot(command.robot) == nullptr) {
      throw std::invalid_argument("plan commands the gripper of an unknown robot '" + command.robot + "'");
    }
  }
}

PlanExecutor::~PlanExecutor() = default;

double PlanExecutor::planTime() const { return sim_.time() - offset_; }

controllers::JointReference PlanExecutor::reference(int r) const {
  const auto& trajectory = trajectories_[r];
  return trajectory ? trajectory->at(planTime()) : holds_[r];
}

void PlanExecutor::step() {
  const core::World& world = sim_.world();
  // gripper commands due by now (a command at t acts from the first step at or after t)
  while (next_command_ < gripper_commands_.size() && gripper_commands_[next_command_].t <= planTime() + 1e-12) {
    const core::GripperCommand& command = gripper_commands_[next_command_++];
    for (std::size_t r = 0; r < world.robots.size(); ++r) {
      if (world.robots[r].name == command.robot) grippers_[r].command(command.action, command.force);
    }
  }
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    const int ri = static_cast<int>(r);
    const Eigen::VectorXd q = sim_.jointPositions(ri);
    const Eigen::VectorXd qd = sim_.jointVelocities(ri);
    const controllers::JointReference ref = reference(ri);
    const controllers::ArmTorques torques = arm_controllers_[r]->compute(q, qd, ref);
    sim_.setArmTorques(ri, torques.tau);
    sim_.setFingerServo(ri, grippers_[r].servo(0.5 * (q[6] + q[7])));

    TrackingStats& stats = stats_[r];
    for (int j = 0; j < 6; ++j) {
      const double error = std::abs(ref.q[j] - q[j]);
      stats.max_joint_error[j] = std::max(stats.max_joint_error[j], error);
      stats.max_tracking_error = std::max(stats.max_tracking_error, error);
    }
    stats.max_effort_ratio = std::max(stats.max_effort_ratio, torques.max_effort_ratio);
    if (torques.saturated) ++stats.saturated_steps;
    ++stats.steps;
  }
  sim_.step();
}

}  // namespace dashbed::sim
