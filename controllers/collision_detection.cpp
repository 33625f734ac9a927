#include "controllers/collision_detection.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "core/kinematics.h"
#include "core/number_text.h"

namespace dashbed::controllers {

std::string describeTrip(const ProtectiveStopTrip& trip, const std::string& joint_name) {
  const auto text = [](double x) { return core::significantText(x, 4); };
  switch (trip.cause) {
    case ProtectiveStopTrip::Cause::kExternalTorque:
      return joint_name + " external torque " + text(trip.value) + " Nm > " + text(trip.limit) + " Nm";
    case ProtectiveStopTrip::Cause::kTcpForce:
      return "external TCP force " + text(trip.value) + " N > " + text(trip.limit) + " N";
    case ProtectiveStopTrip::Cause::kPathDeviation:
      return joint_name + " deviates from its path by " + text(trip.value) + " rad > " + text(trip.limit) + " rad";
  }
  return {};
}

CollisionDetector::CollisionDetector(const core::RobotModel& model, const core::SafetySettings& safety,
                                     const Eigen::Vector3d& gravity_root, int tcp_link, double time_step)
    : model_(model),
      gravity_root_(gravity_root),
      tcp_link_(tcp_link),
      time_step_(time_step),
      tcp_force_limit_(safety.tcp_force) {
  for (int i = 0; i < 6; ++i) {
    torque_limit_[i] = safety.external_torque * model.joints()[model.movableJoints()[i]].max_effort;
  }
}

const ExternalLoad& CollisionDetector::update(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                              const core::Vector6& tau, const Eigen::VectorXd& qd_next,
                                              const core::Payload* payload) {
  // the acceleration the step made (the integrator's own: qd_next = qd + h qdd), all joints
  const Eigen::VectorXd qdd = (qd_next - qd) / time_step_;
  const Eigen::VectorXd needed = core::inverseDynamics(model_, q, qd, qdd, gravity_root_, payload);
  const double alpha = std::min(1.0, kObserverGain * time_step_);
  Eigen::Matrix<double, 6, 1> filtered;
  for (int i = 0; i < 6; ++i) {
    const double raw = std::isfinite(needed[i]) ? tau[i] - needed[i] : 0.0;
    load_.torque[i] += alpha * (raw - load_.torque[i]);
    filtered[i] = load_.torque[i];
  }
  // the TCP wrench w with J^T w = tau_ext, damped least squares
  const Eigen::Matrix<double, 6, 6> J = core::jacobian(model_, q, tcp_link_).leftCols<6>();
  const Eigen::Matrix<double, 6, 6> JJt =
      J * J.transpose() + kWrenchDamping * kWrenchDamping * Eigen::Matrix<double, 6, 6>::Identity();
  const Eigen::Matrix<double, 6, 1> wrench = JJt.ldlt().solve(J * filtered);
  load_.tcp_force = wrench.head<3>().norm();

  max_tcp_force_ = std::max(max_tcp_force_, load_.tcp_force);
  int worst = 0;
  double worst_ratio = 0.0;
  for (int i = 0; i < 6; ++i) {
    const double ratio = std::abs(load_.torque[i]) / torque_limit_[i];
    if (ratio > worst_ratio) worst_ratio = ratio, worst = i;
  }
  max_torque_ratio_ = std::max(max_torque_ratio_, worst_ratio);
  if (!trip_) {
    if (worst_ratio > 1.0) {
      trip_ = ProtectiveStopTrip{ProtectiveStopTrip::Cause::kExternalTorque, worst, std::abs(load_.torque[worst]),
                                 torque_limit_[worst]};
    } else if (load_.tcp_force > tcp_force_limit_) {
      trip_ = ProtectiveStopTrip{ProtectiveStopTrip::Cause::kTcpForce, -1, load_.tcp_force, tcp_force_limit_};
    }
  }
  return load_;
}

}  // namespace dashbed::controllers
