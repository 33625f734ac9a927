#include "core/pose.h"

#include <cmath>
#include <numbers>

namespace dashbed::core {

Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R) {
  const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
  // near the pitch singularity roll and yaw are coupled; put everything in yaw
  if (std::abs(std::cos(pitch)) < 1e-12) {
    const double yaw = std::atan2(-R(0, 1), R(1, 1));
    return {0.0, pitch, yaw};
  }
  return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

Pose makePose(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy) {
  Pose X = Pose::Identity();
  X.linear() = rotationFromRpy(rpy);
  X.translation() = xyz;
  return X;
}

Pose makePoseXyzYaw(const Eigen::Vector3d& xyz, double yaw) {
  return makePose(xyz, Eigen::Vector3d(0.0, 0.0, yaw));
}

// The unit quaternion of the shortest rotation, written out: Quaterniond::FromTwoVectors gives
// the same but instantiates an SVD for the opposite case, seconds of compile time per file.
// With u, v the unit directions and c = u.v: w = cos(theta/2) = s/2 with s = sqrt(2 (1 + c)),
// and the vector part is sin(theta/2) (u x v)/|u x v| = (u x v)/s.
Eigen::Matrix3d rotationBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector3d u = from.normalized();
  const Eigen::Vector3d v = to.normalized();
  const double c = u.dot(v);
  if (c < -1.0 + 1e-12) {
    // opposite: half a turn about an axis normal to u (u x x, or u x y where u is near x)
    Eigen::Vector3d axis = u.cross(Eigen::Vector3d::Unit(0));
    if (axis.squaredNorm() < 0.5) axis = u.cross(Eigen::Vector3d::Unit(1));
    return Eigen::AngleAxisd(std::numbers::pi, axis.normalized()).toRotationMatrix();
  }
  const double s = std::sqrt(2.0 * (1.0 + c));
  const Eigen::Vector3d n = u.cross(v) / s;
  return Eigen::Quaterniond(0.5 * s, n.x(), n.y(), n.z()).toRotationMatrix();
}

double wrapToPi(double angle) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  // fmod returns an angle within (-2 pi, 2 pi) exactly as it is: no call needed (the IK and
  // the planner's angle comparisons wrap millions of such angles)
  double a = std::abs(angle) < kTwoPi ? angle : std::fmod(angle, kTwoPi);
  if (a <= -std::numbers::pi) a += kTwoPi;
  if (a > std::numbers::pi) a -= kTwoPi;
  return a;
}

}  // namespace dashbed::core
