#include "sim/motion_samples.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

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
  }
}

void MotionSampler::onStep(const Simulation& simulation, double plan_time) {
  const double due = static_cast<double>(samples_.times.size()) / samples_.rate;
  if (plan_time < 0.0 || plan_time + kSampleTimeTolerance < due) return;
  samples_.times.push_back(plan_time);
  for (std::size_t r = 0; r < samples_.robots.size(); ++r) {
    const Eigen::VectorXd q = simulation.jointPositions(static_cast<int>(r));
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
