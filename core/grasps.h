#pragma once
// Parallel-jaw grasps of box-shaped objects: where the TCP can be for a Hand-E to hold a box.

#include <vector>

#include <Eigen/Core>

#include "core/pose.h"

namespace dashbed::core {

/// Widest box face pair the Hand-E can close on: 2 x 25 mm stroke (reference file, S4-S7).
inline constexpr double kHandeMaxOpening = 0.050;

enum class GraspApproach { kTop, kSide };

/// A grasp of a box: the TCP pose in the object's frame (z = approach direction, x = closing
/// axis, TCP at the box centre) and how the gripper comes in.
struct BoxGrasp {
  Pose X_OT = Pose::Identity();
  GraspApproach approach = GraspApproach::kTop;
};

/// The grasps of a box of `size` resting upright: from above with the closing axis along each
/// horizontal face normal (4), and from each horizontal side with a horizontal closing axis
/// (8). Face pairs wider than the gripper opening minus `clearance` are left out.
std::vector<BoxGrasp> boxGrasps(const Eigen::Vector3d& size, double clearance = 0.005);

}  // namespace dashbed::core
