#include "core/kinematics.h"

#include <stdexcept>
#include <string>

namespace dashbed::core {
namespace {

/// Pose of the child link in the parent link for joint value `value`.
Pose jointTransform(const JointModel& joint, double value) {
  switch (joint.type) {
    case JointType::kFixed:
      return joint.X_PJ;
    case JointType::kRevolute:
      return joint.X_PJ * Eigen::AngleAxisd(value, joint.axis);
    case JointType::kPrismatic:
      return joint.X_PJ * Eigen::Translation3d(value * joint.axis);
  }
  return joint.X_PJ;
}

void requireSize(const RobotModel& model, const Eigen::VectorXd& q) {
  if (q.size() != model.numPositions()) {
    throw std::invalid_argument("robot model '" + model.name() + "' expects " +
                                std::to_string(model.numPositions()) + " joint positions, got " +
                                std::to_string(q.size()));
  }
}

}  // namespace

void linkPoses(const RobotModel& model, const Eigen::VectorXd& q, std::vector<Pose>& X_RL) {
  requireSize(model, q);
  const auto& links = model.links();
  X_RL.resize(links.size());
  // links are in topological order: a parent always precedes its children
  for (std::size_t i = 0; i < links.size(); ++i) {
    const int j = links[i].parent_joint;
    if (j < 0) {
      X_RL[i] = Pose::Identity();
      continue;
    }
    const JointModel& joint = model.joints()[j];
    const double value = joint.q_index >= 0 ? q[joint.q_index] : 0.0;
    X_RL[i] = X_RL[joint.parent_link] * jointTransform(joint, value);
  }
}

std::vector<Pose> linkPoses(const RobotModel& model, const Eigen::VectorXd& q) {
  std::vector<Pose> X_RL;
  linkPoses(model, q, X_RL);
  return X_RL;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(const RobotModel& model, const Eigen::VectorXd& q,
                                                  int link, const Eigen::Vector3d& p_LP) {
  if (link < 0 || link >= static_cast<int>(model.links().size())) {
    throw std::invalid_argument("jacobian: link index out of range");
  }
  const std::vector<Pose> X_RL = linkPoses(model, q);
  const Eigen::Vector3d p_RP = X_RL[link] * p_LP;
  Eigen::Matrix<double, 6, Eigen::Dynamic> J = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, q.size());
  // walk from the link to the root; every movable joint on the way moves P
  for (int l = link; model.links()[l].parent_joint >= 0;) {
    const JointModel& joint = model.joints()[model.links()[l].parent_joint];
    if (joint.q_index >= 0) {
      // the joint frame coincides with the child link frame up to the joint motion, which
      // leaves the axis and (for revolute joints) the origin unchanged
      const Pose& X_RC = X_RL[l];
      const Eigen::Vector3d axis_R = X_RC.linear() * joint.axis;
      if (joint.type == JointType::kRevolute) {
        J.col(joint.q_index).head<3>() = axis_R.cross(p_RP - X_RC.translation());
        J.col(joint.q_index).tail<3>() = axis_R;
      } else {
        J.col(joint.q_index).head<3>() = axis_R;
      }
    }
    l = joint.parent_link;
  }
  return J;
}

}  // namespace dashbed::core
