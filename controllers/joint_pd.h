#pragma once
// Joint-space PD of a UR arm with gravity compensation and inverse-dynamics feed-forward
// (computed-torque form), producing torques clamped to the joints' effort limits.

#include <array>

#include <Eigen/Core>

#include "core/trajectory_interpolator.h"
#include "core/dynamics.h"
#include "core/robot_model.h"
#include "core/world.h"

namespace dashbed::controllers {

using core::JointReference;
using core::Vector6;

struct ArmTorques {
  Vector6 tau{};                ///< [Nm] applied, after clamping
  bool saturated = false;       ///< some joint hit its effort limit
  double max_effort_ratio = 0;  ///< max |tau_unclamped| / limit
};

class JointPdController {
 public:
  /// `gravity_root`: gravity in the robot's root frame [m/s^2]. The model (arm joints first
  /// in q) must outlive the controller.
  JointPdController(const core::RobotModel& model, const core::ControllerSettings& settings,
                    const Eigen::Vector3d& gravity_root);

  /// tau = M(q) (qdd_ref + kp (q_ref - q) + kd (qd_ref - qd)) + c(q, qd) + g(q) for the six
  /// arm joints; q and qd hold all the model's joints (the fingers' accelerations are taken
  /// as zero). With a payload (the object in the gripper, as a UR controller is told with
  /// set_payload) M, c and g include it. Each torque is clamped to +-max_effort of its joint;
  /// one that is not finite (a diverged state) is 0, and the result counts as saturated.
  ArmTorques compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const JointReference& ref,
                     const core::Payload* payload = nullptr) const;

 private:
  const core::RobotModel& model_;
  core::ControllerSettings settings_;
  Eigen::Vector3d gravity_root_;
  Vector6 effort_limit_{};
};

}  // namespace dashbed::controllers
