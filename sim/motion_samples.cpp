#include "sim/motion_samples.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "sim/plan_executor.h"
#include "sim/simulation.h"

namespace dashbed::sim {
namespace {

constexpr double kSampleTimeTolerance = 1e-9;  // [s] a step at 0.999999999 s takes the sample of 1 s

void appendPose(std::vector<double>& out, const core::Pose& X) {
  Eigen::Quaterniond q(X.linear());
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // one of q and -q: the same rotation
  const Eigen::Vector3d p = X.translation();
  out.insert(out.end(), {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()});
}

}  // namespace

MotionSampler::MotionSampler(const core::World& world, const core::RobotSet& robots, double rate) {
  if (!(rate > 0.0) || !std::isfinite(rate) || rate * world.physics.time_step > 1.0 + kSampleTimeTolerance) {
    throw std::invalid_argument("sample rate must be in (0, " + std::to_string(1.0 / world.physics.time_step) +
                                "] Hz (the simulation's step rate), got " + std::to_string(rate));
  }
  samples_.rate = rate;
  for (const core::RobotSpec& robot : world.robots) samples_.robots.push_back(robot.name);
  for (const core::ObjectSpec& object : world.objects) samples_.objects.push_back(object.name);
  if (robots.size() > 0) {
    const core::RobotModel& model = *robots[0].model;
    for (const int joint : model.movableJoints()) samples_.joints.push_back(model.joints()[joint].name);
    for (const core::LinkModel& link : model.links()) samples_.links.push_back(link.name);
    for (std::size_t j = 0; j < 6; ++j) effort_limits_[j] = model.joints()[model.movableJoints()[j]].max_effort;
    for (std::size_t f = 0; f < 2 && 6 + f < model.movableJoints().size(); ++f) {
      finger_links_[f] = model.joints()[model.movableJoints()[6 + f]].child_link;
    }
  }
}

void MotionSampler::onStep(const StepState& step) {
  const Simulation& simulation = step.simulation;
  const double plan_time = step.plan_time;
  const double due = static_cast<double>(samples_.times.size()) / samples_.rate;
  if (plan_time < 0.0 || plan_time + kSampleTimeTolerance < due) return;
  samples_.times.push_back(plan_time);
  // each finger's normal force on objects, per robot
  std::vector<std::array<double, 2>> squeeze(samples_.robots.size(), {0.0, 0.0});
  for (const Contact& contact : simulation.contacts()) {
    for (const auto& [finger, other] : {std::pair(contact.a, contact.b), std::pair(contact.b, contact.a)}) {
      if (finger.kind != BodyRef::Kind::kRobot || other.kind != BodyRef::Kind::kObject) continue;
      for (std::size_t f = 0; f < 2; ++f) {
        if (finger.link == finger_links_[f]) squeeze[static_cast<std::size_t>(finger.index)][f] += contact.normal_force;
      }
    }
  }
  for (std::size_t r = 0; r < samples_.robots.size(); ++r) {
    const int robot = static_cast<int>(r);
    const Eigen::VectorXd q = simulation.jointPositions(robot);
    const core::JointReference reference = step.executor.reference(robot);
    const std::array<double, 6>& tau = simulation.armTorques(robot);
    double error = 0.0, effort = 0.0;
    for (std::size_t j = 0; j < 6; ++j) {
      error = std::max(error, std::abs(reference.q[static_cast<Eigen::Index>(j)] - q[static_cast<Eigen::Index>(j)]));
      if (effort_limits_[j] > 0.0) effort = std::max(effort, std::abs(tau[j]) / effort_limits_[j]);
    }
    samples_.tracking_error.push_back(error);
    samples_.effort_ratio.push_back(effort);
    samples_.grip_force.push_back(0.5 * (squeeze[r][0] + squeeze[r][1]));
    samples_.joint_positions.insert(samples_.joint_positions.end(), q.data(), q.data() + q.size());
    for (std::size_t l = 0; l < samples_.links.size(); ++l) {
      appendPose(samples_.link_poses, simulation.linkPose(static_cast<int>(r), static_cast<int>(l)));
    }
  }
  for (std::size_t o = 0; o < samples_.objects.size(); ++o) {
    appendPose(samples_.object_poses, simulation.objectPose(static_cast<int>(o)));
  }
}

}  // namespace dashbed::sim
