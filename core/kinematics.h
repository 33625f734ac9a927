#pragma once
// Forward kinematics and Jacobians of a RobotModel (free functions on the const model,
// in the spirit of Pinocchio's algorithms). Poses are expressed in the model's root frame R.

#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "core/robot_model.h"

namespace dashbed::core {

/// Pose of every link in the root frame, X_RL[i] for link i. q has model.numPositions()
/// entries (metres for prismatic, radians for revolute joints). Throws std::invalid_argument
/// on a wrong size.
std::vector<Pose> linkPoses(const RobotModel& model, const Eigen::VectorXd& q);

/// Same, writing into `X_RL` (resized to the number of links) to avoid allocation.
void linkPoses(const RobotModel& model, const Eigen::VectorXd& q, std::vector<Pose>& X_RL);

/// Geometric Jacobian of the point P fixed in link `link` (p_LP in that link's frame):
/// rows 0-2 the linear velocity of P, rows 3-5 the angular velocity of the link, both in R;
/// one column per entry of q. Joints that do not move the link give zero columns.
Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(const RobotModel& model, const Eigen::VectorXd& q,
                                                  int link,
                                                  const Eigen::Vector3d& p_LP = Eigen::Vector3d::Zero());

}  // namespace dashbed::core
