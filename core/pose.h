#pragma once
// Rigid transforms and the URDF roll-pitch-yaw convention.
//
// Naming follows the monogram notation: X_AB is the pose of frame B expressed in frame A,
// p_AB the position of B's origin in A. All lengths in metres, angles in radians.

#include <Eigen/Geometry>

namespace dashbed::core {

using Pose = Eigen::Isometry3d;

/// Rotation from URDF fixed-axis roll-pitch-yaw: R = Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy);

/// Inverse of rotationFromRpy; pitch in [-pi/2, pi/2], roll and yaw in (-pi, pi].
Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R);

/// Pose from a translation and URDF roll-pitch-yaw angles.
Pose makePose(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy);

/// Pose from a translation and a rotation about +z (yaw).
Pose makePoseXyzYaw(const Eigen::Vector3d& xyz, double yaw);

/// The shortest rotation turning the direction of `from` onto that of `to` (about their common
/// normal); half a turn about an axis normal to `from` when they are opposite. Neither may be zero.
Eigen::Matrix3d rotationBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

/// Wraps an angle to (-pi, pi].
double wrapToPi(double angle);

}  // namespace dashbed::core
