#pragma once
// RobotModel: the immutable kinematic and inertial description of one robot, read from URDF.
//
// Links are stored in topological order (root first); every non-root link has exactly one
// parent joint. The configuration vector q holds one value per movable joint in link order:
// for the UR5e + Hand-E that is the six arm joints then the two finger joints.

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/pose.h"

namespace dashbed::core {

enum class JointType { kFixed, kRevolute, kPrismatic };

struct JointModel {
  std::string name;
  JointType type = JointType::kFixed;
  int parent_link = -1;
  int child_link = -1;
  Pose X_PJ = Pose::Identity();  ///< joint frame in the parent link frame (URDF origin)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit axis in the joint frame
  int q_index = -1;       ///< index in q; -1 for fixed joints
  double lower = 0.0;     ///< position limit [rad or m]
  double upper = 0.0;
  double max_velocity = 0.0;  ///< [rad/s or m/s]
  double max_effort = 0.0;    ///< [Nm or N]
};

enum class ShapeType { kBox, kCylinder, kSphere };

/// A convex collision primitive in its link frame. Box: size = edge lengths; cylinder
/// (along local z): size = (radius, radius, length); sphere: size = (r, r, r).
struct CollisionShape {
  std::string name;  ///< URDF collision name ("pad" marks finger pads)
  ShapeType type = ShapeType::kBox;
  Pose X_LS = Pose::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

struct VisualMesh {
  std::filesystem::path file;  ///< absolute path
  Pose X_LV = Pose::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::Vector4d rgba{0.7, 0.7, 0.7, 1.0};
};

struct LinkModel {
  std::string name;
  int parent_joint = -1;  ///< -1 for the root
  double mass = 0.0;      ///< [kg]; 0 for pure frames
  Pose X_LCom = Pose::Identity();  ///< inertial frame in the link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the CoM, in the inertial frame
  std::vector<CollisionShape> collisions;
  std::vector<VisualMesh> visuals;
};

class RobotModel {
 public:
  /// Reads a URDF file. Throws std::runtime_error naming the file on parse errors, on
  /// unsupported joint types or geometry, or if the tree has no unique root.
  static RobotModel fromUrdfFile(const std::filesystem::path& urdf_file);

  const std::string& name() const { return name_; }
  const std::vector<LinkModel>& links() const { return links_; }
  const std::vector<JointModel>& joints() const { return joints_; }
  /// Movable joints in q order.
  const std::vector<int>& movableJoints() const { return movable_joints_; }
  int numPositions() const { return static_cast<int>(movable_joints_.size()); }

  /// Index of a link or joint by name; -1 if absent.
  int linkIndex(std::string_view name) const;
  int jointIndex(std::string_view name) const;
  /// Like linkIndex but throws std::out_of_range naming the link when it is absent.
  int requireLink(std::string_view name) const;

  /// Pose of link `descendant` in link `ancestor` when all joints between them are fixed.
  /// Throws std::invalid_argument if a movable joint lies between them.
  Pose fixedTransform(int ancestor, int descendant) const;

 private:
  std::string name_;
  std::vector<LinkModel> links_;
  std::vector<JointModel> joints_;
  std::vector<int> movable_joints_;
};

}  // namespace dashbed::core
