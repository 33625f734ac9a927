#pragma once
// Closed-form kinematics of Universal Robots arms in UR's standard DH convention, and the
// arm-level IK of a RobotModel's TCP built on it.
//
// DH: T_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i), alpha = (pi/2, 0, 0, pi/2, -pi/2, 0);
// frame 0 = UR "base", frame 6 = tool0. The six-angle inverse follows the classic
// decomposition (wrist-centre -> shoulder pan, wrist angles from the rotation, planar
// two-link shoulder/elbow) and yields up to 8 solutions.

#include <array>
#include <optional>
#include <vector>

#include "core/pose.h"
#include "core/robot_model.h"

namespace dashbed::core {

using ArmConfig = std::array<double, 6>;  ///< the six arm joint angles [rad]

/// Non-zero DH lengths of a UR arm [m]; alpha is fixed by the UR design.
struct UrDhParameters {
  double d1;
  double a2;
  double a3;
  double d4;
  double d5;
  double d6;
};

/// UR5e, from Universal Robots' published DH table (UR's DH-parameters page, universal-robots.com).
inline constexpr UrDhParameters kUr5eDh{0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996};

/// T_06: pose of tool0 in the DH base frame.
Pose urForwardKinematics(const UrDhParameters& dh, const ArmConfig& q);

/// Every solution q with urForwardKinematics(dh, q) = T_06, each angle in (-pi, pi].
/// At a wrist singularity (sin q5 = 0) q6 is set to 0. Empty when the pose is unreachable.
std::vector<ArmConfig> urInverseKinematics(const UrDhParameters& dh, const Pose& T_06);

/// TCP inverse kinematics of a UR arm described by a RobotModel.
///
/// The model must contain links `base` (DH frame 0), `tool0` (DH frame 6) and the TCP link,
/// and its six arm joints must be the first six entries of q. The constructor checks that
/// the URDF chain reproduces the DH model (throws std::invalid_argument otherwise).
class UrArmIk {
 public:
  explicit UrArmIk(const RobotModel& model, const UrDhParameters& dh = kUr5eDh,
                   std::string_view tcp_link = "tcp");

  /// X_RT: pose of the TCP in the model root frame for arm configuration q.
  Pose tcpPose(const ArmConfig& q) const;

  /// All solutions reaching X_RT (TCP in the root frame) that lie within the joint limits.
  /// Each angle is the representative of its 2*pi class that lies within the limits and is
  /// closest to zero.
  std::vector<ArmConfig> solve(const Pose& X_RT) const;

  /// All solutions within limits, each angle moved by multiples of 2*pi to the value within
  /// the limits nearest to `seed`, sorted by Euclidean distance to the seed (nearest first).
  std::vector<ArmConfig> solveNearest(const Pose& X_RT, const ArmConfig& seed) const;

  /// The solution nearest to `seed`, or nullopt when the pose is unreachable within limits.
  std::optional<ArmConfig> nearest(const Pose& X_RT, const ArmConfig& seed) const;

  const std::array<double, 6>& lower() const { return lower_; }
  const std::array<double, 6>& upper() const { return upper_; }

 private:
  /// Moves `angle` by multiples of 2*pi into [lower, upper], to the value nearest `target`.
  /// Returns false when no such value exists.
  bool wrapIntoLimits(int joint, double target, double& angle) const;

  UrDhParameters dh_;
  Pose X_RBase_;   // DH base frame in the root frame
  Pose X_Tool0T_;  // TCP in tool0
  std::array<double, 6> lower_{};
  std::array<double, 6> upper_{};
};

}  // namespace dashbed::core
