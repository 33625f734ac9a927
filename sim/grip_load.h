#pragma once
// How close a two-pad grip comes to slipping: the friction load the held object's motion puts on
// the pads against what their contact patches can resist.
//
// The pads must give the object the wrench its motion and gravity need. Along the closing axis
// the two pads' normal forces carry it; across it, only friction: a tangential force F_t and a
// torque tau_n about the closing axis (an off-centre or swinging object twists in the grip).
// What the patches resist sliding is F_max = mu (N_l + N_r) and tau_max = mu (N_l rho_l + N_r
// rho_r), the torsional friction of uniformly pressed patches whose points lie on average rho
// from their centre (the overlap of pad and object face: a compliant rubber pad presses about
// evenly). Force and torque load combine on the ellipse of the limit surface,
// use = sqrt((F_t / F_max)^2 + (tau_n / tau_max)^2) (Howe and Cutkosky, "Practical force-motion
// models for sliding manipulation", IJRR 15(6), 1996); the grip holds while use < 1, and its
// margin is 1 / use.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/pose.h"
#include "core/robot_model.h"

namespace dashbed::sim {

/// A pad's gripping face: origin at its centre, z the normal into the gripped object, x and y
/// along the face with half extents `half` [m].
struct PadFace {
  core::Pose X_WF = core::Pose::Identity();
  Eigen::Vector2d half = Eigen::Vector2d::Zero();
};

/// The gripping face of the pad box `pad` of a finger link at X_WL: the box's -x face (the
/// URDF's pads grip with their inner face x = 0, the pad behind it).
PadFace padFace(const core::Pose& X_WL, const core::CollisionShape& pad);

/// Where a pad's face meets the face of a box object (pose X_WO, edge lengths `size`) turned
/// towards it: the overlap of the two rectangles in the object face's plane, its area, its mean
/// radius and its centroid (world), the centre of pressure of a uniformly pressed patch.
struct Patch {
  double area = 0.0;         ///< [m^2]
  double mean_radius = 0.0;  ///< mean distance of its points from its centroid [m]
  Eigen::Vector3d centre_W = Eigen::Vector3d::Zero();
};
Patch padPatch(const PadFace& face, const core::Pose& X_WO, const Eigen::Vector3d& size);

/// One pad's contact with the held object.
struct PadContact {
  double normal_force = 0.0;                           ///< [N]
  double area = 0.0;                                   ///< contact patch [m^2]
  double mean_radius = 0.0;                            ///< mean distance of the patch from its centre [m]
  Eigen::Vector3d centre_W = Eigen::Vector3d::Zero();  ///< centre of pressure (world)
};

/// The held object at one instant, in the world frame.
struct HeldMotion {
  double mass = 0.0;                                        ///< [kg]
  Eigen::Matrix3d inertia_W = Eigen::Matrix3d::Zero();      ///< about its centre of mass [kg m^2]
  Eigen::Vector3d com_W = Eigen::Vector3d::Zero();          ///< [m]
  Eigen::Vector3d acceleration_W = Eigen::Vector3d::Zero(); ///< of the centre of mass [m/s^2]
  Eigen::Vector3d angular_velocity_W = Eigen::Vector3d::Zero();      ///< [rad/s]
  Eigen::Vector3d angular_acceleration_W = Eigen::Vector3d::Zero();  ///< [rad/s^2]
};

struct GripLoad {
  double tangential_force = 0.0;  ///< F_t [N]
  double torsion = 0.0;           ///< |tau_n| [Nm]
  double use = 0.0;               ///< on the limit-surface ellipse: 1 = sliding
};

/// The load of `motion` on the grip of pads `left` and `right` closing along `closing_W` (unit),
/// with Coulomb coefficient `mu` between pads and object, under `gravity_W`. A grip whose pads
/// press with nothing has use infinity when loaded.
GripLoad gripLoad(const PadContact& left, const PadContact& right, const Eigen::Vector3d& closing_W, double mu,
                  const HeldMotion& motion, const Eigen::Vector3d& gravity_W);

}  // namespace dashbed::sim
