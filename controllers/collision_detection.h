#pragma once
// Collision detection of a UR arm, as its controller does it: the external joint torques are
// the efforts applied beyond what the arm's model (with the payload it was told of) needs for
// the motion it made; filtered, they and the TCP force they imply are held to the safety
// limits. Crossing one is a protective stop.

#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/dynamics.h"
#include "core/robot_model.h"
#include "core/trajectory_interpolator.h"
#include "core/world.h"

namespace dashbed::controllers {

/// The filtered external load on one arm after a step.
struct ExternalLoad {
  core::Vector6 torque{};  ///< [Nm] per arm joint
  double tcp_force = 0.0;  ///< [N] magnitude of the force at the TCP that explains `torque`
};

/// What tripped a protective stop.
struct ProtectiveStopTrip {
  enum class Cause {
    kExternalTorque,  ///< a joint's external torque [Nm]
    kTcpForce,        ///< the external force at the TCP [N]
    kPathDeviation,   ///< a joint's distance from its reference [rad] ("position deviates from path")
  };
  Cause cause = Cause::kExternalTorque;
  int joint = -1;        ///< arm joint (0..5) concerned; -1 for the TCP force
  double value = 0.0;    ///< in the cause's unit
  double limit = 0.0;
};

/// "wrist_3_joint external torque 7.2 Nm > 7 Nm" and the like, with the joint's name given.
std::string describeTrip(const ProtectiveStopTrip& trip, const std::string& joint_name);

class CollisionDetector {
 public:
  /// Cut-off of the estimate's first-order filter [1/s], the gain of a generalized-momentum
  /// observer (De Luca and Mattone, ICRA 2005): a 10 ms time constant smooths the steps'
  /// contact impulses and still stops a sustained push within a few tens of milliseconds.
  static constexpr double kObserverGain = 100.0;
  /// Damping of the least-squares TCP wrench near singular configurations [m].
  static constexpr double kWrenchDamping = 0.01;

  /// `gravity_root`: gravity in the robot's root frame [m/s^2]; `tcp_link` the model link of the
  /// TCP. The model must outlive the detector.
  CollisionDetector(const core::RobotModel& model, const core::SafetySettings& safety,
                    const Eigen::Vector3d& gravity_root, int tcp_link, double time_step);

  /// Feeds one step: the state (q, qd) at its start, the arm torques applied over it, the
  /// velocities qd_next at its end and the payload the controller compensated. Returns the
  /// filtered load; a trip is kept from the first step that crosses a limit.
  const ExternalLoad& update(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const core::Vector6& tau,
                             const Eigen::VectorXd& qd_next, const core::Payload* payload);

  const ExternalLoad& load() const { return load_; }
  /// The first crossing, if any.
  const std::optional<ProtectiveStopTrip>& trip() const { return trip_; }
  /// Largest filtered TCP force and largest external torque over its joint's limit seen so far.
  double maxTcpForce() const { return max_tcp_force_; }
  double maxTorqueRatio() const { return max_torque_ratio_; }

 private:
  const core::RobotModel& model_;
  Eigen::Vector3d gravity_root_;
  int tcp_link_;
  double time_step_;
  double tcp_force_limit_;
  core::Vector6 torque_limit_{};
  ExternalLoad load_;
  std::optional<ProtectiveStopTrip> trip_;
  double max_tcp_force_ = 0.0;
  double max_torque_ratio_ = 0.0;
};

}  // namespace dashbed::controllers
