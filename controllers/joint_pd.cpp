#include "controllers/joint_pd.h"

#include <algorithm>
#include <cmath>

#include "core/dynamics.h"

namespace dashbed::controllers {

JointPdController::JointPdController(const core::RobotModel& model, const core::ControllerSettings& settings,
                                     const Eigen::Vector3d& gravity_root)
    : model_(model), settings_(settings), gravity_root_(gravity_root) {
  for (int i = 0; i < 6; ++i) effort_limit_[i] = model.joints()[model.movableJoints()[i]].max_effort;
}

ArmTorques JointPdController::compute(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const JointReference& ref,
                                      const core::Payload* payload) const {
  Eigen::VectorXd qdd = Eigen::VectorXd::Zero(q.size());
  for (int i = 0; i < 6; ++i) {
    qdd[i] = ref.qdd[i] + settings_.kp[i] * (ref.q[i] - q[i]) + settings_.kd[i] * (ref.qd[i] - qd[i]);
  }
  const Eigen::VectorXd tau = core::inverseDynamics(model_, q, qd, qdd, gravity_root_, payload);
  ArmTorques out;
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(tau[i])) {  // a diverged state: no torque, and saturated, so it is reported
      out.saturated = true;
      out.tau[i] = 0.0;
      continue;
    }
    const double ratio = std::abs(tau[i]) / effort_limit_[i];
    out.max_effort_ratio = std::max(out.max_effort_ratio, ratio);
    if (ratio >= 1.0) out.saturated = true;
    out.tau[i] = std::clamp(tau[i], -effort_limit_[i], effort_limit_[i]);
  }
  return out;
}

}  // namespace dashbed::controllers
