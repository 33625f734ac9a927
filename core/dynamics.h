#pragma once
// Rigid-body dynamics of a RobotModel with a fixed root: recursive Newton-Euler inverse
// dynamics, the joint-space mass matrix and gravity torques. Used by the joint controllers
// for gravity compensation and inverse-dynamics feed-forward.

#include <Eigen/Core>

#include "core/robot_model.h"

namespace dashbed::core {

/// A rigid body carried by a link (an object in the gripper): its mass, inertial frame in the
/// link frame and inertia about its centre of mass in that frame.
struct Payload {
  int link = -1;
  double mass = 0.0;                                  ///< [kg]
  Pose X_LCom = Pose::Identity();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< [kg m^2]
};

/// tau = M(q) qdd + C(q, qd) qd + g(q): the joint efforts [Nm or N] that produce the joint
/// accelerations qdd at state (q, qd) under gravity `gravity_R` (expressed in the root frame,
/// e.g. (0, 0, -9.81) for an upright robot), with `payload` (if given) rigidly added to its
/// link. Recursive Newton-Euler.
Eigen::VectorXd inverseDynamics(const RobotModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                const Eigen::VectorXd& qdd, const Eigen::Vector3d& gravity_R,
                                const Payload* payload = nullptr);

/// The efforts that hold the robot still at q against gravity.
Eigen::VectorXd gravityTorques(const RobotModel& model, const Eigen::VectorXd& q, const Eigen::Vector3d& gravity_R);

/// Joint-space mass matrix M(q) (symmetric positive definite), one RNEA pass per column.
Eigen::MatrixXd massMatrix(const RobotModel& model, const Eigen::VectorXd& q);

/// Kinetic energy of the robot moving at qd, summed over the links' spatial motions (an
/// independent check of massMatrix: 0.5 qd^T M qd).
double kineticEnergy(const RobotModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

}  // namespace dashbed::core
