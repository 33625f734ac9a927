#include "sim/plan_executor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dashbed::sim {

PlanExecutor::PlanExecutor(Simulation& sim, const core::Plan& plan, double plan_time_offset)
    : sim_(sim), offset_(plan_time_offset), deviation_limit_(sim.world().checks.tracking_error_limit), plan_(plan) {
  const core::World& world = sim.world();
  const std::size_t n = world.robots.size();
  trajectories_.resize(n);
  holds_.resize(n);
  stats_.resize(n);
  gripping_.assign(n, -1);
  payloads_.resize(n);
  for (std::size_t r = 0; r < n; ++r) {
    const core::PlacedRobot& robot = sim.robots()[r];
    tcp_.push_back(robot.model->requireLink("tcp"));
    const Eigen::Vector3d gravity_root = robot.spec->X_WBase.linear().transpose() * world.physics.gravity;
    arm_controllers_.push_back(
        std::make_unique<controllers::JointPdController>(*robot.model, world.controller, gravity_root));
    grippers_.emplace_back(world.controller);
    detectors_.emplace_back(*robot.model, world.safety, gravity_root, tcp_.back(), sim.timeStep());
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

core::JointReference PlanExecutor::reference(int r) const {
  const auto& trajectory = trajectories_[r];
  return trajectory && !stop_ ? trajectory->at(planTime()) : holds_[r];
}

void PlanExecutor::step() {
  const core::World& world = sim_.world();
  // gripper commands due by now (a command at t acts from the first step at or after t)
  while (!stop_ && next_command_ < gripper_commands_.size() &&
         gripper_commands_[next_command_].t <= planTime() + 1e-12) {
    const core::GripperCommand& command = gripper_commands_[next_command_++];
    for (std::size_t r = 0; r < world.robots.size(); ++r) {
      if (world.robots[r].name != command.robot) continue;
      grippers_[r].command(command.action, command.force);
      payloads_[r].reset();
      const bool close = command.action == core::GripperAction::kClose;
      gripping_[r] = close ? objectClosedOn(static_cast<int>(r), command.t) : -1;
    }
  }
  // a gripper closed on an object takes it as payload unless another robot still holds it
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    const int o = gripping_[r];
    if (o < 0 || payloads_[r]) continue;
    bool held_elsewhere = false;
    for (std::size_t k = 0; k < world.robots.size(); ++k) held_elsewhere |= payloads_[k] && gripping_[k] == o;
    if (!held_elsewhere) payloads_[r] = payloadOf(static_cast<int>(r), o);
  }
  const std::size_t n = world.robots.size();
  std::vector<Eigen::VectorXd> q(n), qd(n);
  std::vector<core::JointReference> ref(n);
  for (std::size_t r = 0; r < n; ++r) {
    q[r] = sim_.jointPositions(static_cast<int>(r));
    qd[r] = sim_.jointVelocities(static_cast<int>(r));
    ref[r] = reference(static_cast<int>(r));
  }
  // the controller's watch on the path: a joint too far from its reference stops the cell
  for (std::size_t r = 0; r < n && !stop_; ++r) {
    for (int j = 0; j < 6 && !stop_; ++j) {
      const double deviation = std::abs(ref[r].q[j] - q[r][j]);
      if (deviation > deviation_limit_) {
        stopCell(static_cast<int>(r), {controllers::ProtectiveStopTrip::Cause::kPathDeviation, j, deviation,
                                       deviation_limit_});
      }
    }
  }
  if (stop_) {
    for (std::size_t r = 0; r < n; ++r) ref[r] = reference(static_cast<int>(r));
  }
  std::vector<core::Vector6> tau(n);
  for (std::size_t r = 0; r < n; ++r) {
    const int ri = static_cast<int>(r);
    const core::Payload* payload = payloads_[r] ? &*payloads_[r] : nullptr;
    const controllers::ArmTorques torques = arm_controllers_[r]->compute(q[r], qd[r], ref[r], payload);
    tau[r] = torques.tau;
    sim_.setArmTorques(ri, torques.tau);
    sim_.setFingerServo(ri, grippers_[r].servo(0.5 * (q[r][6] + q[r][7])));

    TrackingStats& stats = stats_[r];
    for (int j = 0; j < 6; ++j) {
      stats.max_tracking_error = std::max(stats.max_tracking_error, std::abs(ref[r].q[j] - q[r][j]));
    }
    stats.max_effort_ratio = std::max(stats.max_effort_ratio, torques.max_effort_ratio);
    if (torques.saturated) ++stats.saturated_steps;
    ++stats.steps;
  }
  sim_.step();
  for (std::size_t r = 0; r < n; ++r) {
    const core::Payload* payload = payloads_[r] ? &*payloads_[r] : nullptr;
    controllers::CollisionDetector& detector = detectors_[r];
    detector.update(q[r], qd[r], tau[r], sim_.jointVelocities(static_cast<int>(r)), payload);
    if (!stop_ && detector.trip()) stopCell(static_cast<int>(r), *detector.trip());
  }
}

void PlanExecutor::stopCell(int r, const controllers::ProtectiveStopTrip& trip) {
  stop_ = ProtectiveStop{r, planTime(), trip, sim_.linkPose(r, tcp_[r]).translation()};
  for (std::size_t k = 0; k < holds_.size(); ++k) {
    const Eigen::VectorXd q = sim_.jointPositions(static_cast<int>(k));
    holds_[k] = core::JointReference{};
    for (int j = 0; j < 6; ++j) holds_[k].q[j] = q[j];
  }
}

int PlanExecutor::objectClosedOn(int r, double t) const {
  const core::World& world = sim_.world();
  const std::string& name = world.robots[static_cast<std::size_t>(r)].name;
  for (const core::PlanAction& action : plan_.actions) {
    const bool grasps = (action.type == core::ActionType::kPick && action.robot == name) ||
                        (action.type == core::ActionType::kHandoff && action.receiver == name);
    if (!grasps || t < action.start || t > action.end) continue;
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
      if (world.objects[o].name == action.object) return static_cast<int>(o);
    }
  }
  return -1;
}

core::Payload PlanExecutor::payloadOf(int r, int o) const {
  const core::ObjectSpec& object = sim_.world().objects[static_cast<std::size_t>(o)];
  const Eigen::Vector3d s2 = object.size.cwiseProduct(object.size);
  core::Payload payload;
  payload.link = tcp_[r];
  payload.mass = object.mass;
  payload.X_LCom = sim_.linkPose(r, tcp_[r]).inverse() * sim_.objectPose(o);
  // a solid box about its centre
  const Eigen::Vector3d moments(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
  payload.inertia = (object.mass / 12.0 * moments).asDiagonal();
  return payload;
}

}  // namespace dashbed::sim
