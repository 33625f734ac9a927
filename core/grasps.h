#pragma once
// Parallel-jaw grasps of box-shaped objects: where the TCP can be for a Hand-E to hold a box
// that rests upright on a surface.

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/hande.h"
#include "core/pose.h"

namespace dashbed::core {

/// The opening a grasp keeps to spare around the box, and the fingertips above the surface [m].
inline constexpr double kGraspClearance = 0.005;
/// How far the fingertips reach beyond the TCP along the approach axis: tip end 145.5 mm vs
/// TCP 132.5 mm from the Hand-E mounting face (Robotiq Hand-E ROS 2 description,
/// github.com/robotiq/ros; github.com/AGH-CEAI/robotiq_hande_description).
inline constexpr double kFingertipBeyondTcp = 0.013;
/// Half the Hand-E body's width (75 mm envelope, Robotiq's Hand-E Isaac Sim assets,
/// github.com/robotiq/isaacsim_assets): from the side, the body passes this far
/// below the TCP.
inline constexpr double kHandeBodyHalfWidth = 0.0375;

enum class GraspApproach { kTop, kSide };

/// A grasp of a box: the TCP pose in the object's frame (z = approach direction, x = closing
/// axis) and how the gripper comes in.
struct BoxGrasp {
  Pose X_OT = Pose::Identity();
  GraspApproach approach = GraspApproach::kTop;
};

/// The grasps of a box of `size` resting upright on a surface:
///  - from above, closing along each horizontal face normal (4), with the TCP at the box
///    centre, or raised so the fingertips stay `clearance` above the surface, or so the box
///    reaches at most `top_reach` above the TCP (a tall box, whose top would otherwise reach
///    into the gripper housing);
///  - from each horizontal side with a horizontal closing axis (8), only where the box is tall
///    enough to hold the TCP high enough for the gripper body to clear the surface while the
///    pads still overlap the box by at least 10 mm.
/// Face pairs wider than the gripper opening minus `clearance` are left out.
std::vector<BoxGrasp> boxGrasps(const Eigen::Vector3d& size, double clearance = kGraspClearance,
                                double top_reach = std::numeric_limits<double>::infinity());

/// The heaviest object [kg] a parallel-jaw grip holds by friction alone while standing still:
/// two pads each pressing with `grip_force` [N], Coulomb coefficient `friction` (the object's
/// times the pads', as the simulation combines them), gravity `g` [m/s^2]: 2 friction grip_force / g.
/// Moving it takes more (its acceleration adds to g).
double frictionHoldMass(double friction, double grip_force, double g);

}  // namespace dashbed::core
