#pragma once
// The data of a CollisionScene (collision_checker.h), internal to the planner: the robots'
// rigid bodies and grown shapes, the object boxes and the static boxes in their broad phase.
// collision_scene.cpp builds it; the queries (collision_checker_state.h,
// collision_checker.cpp) read it.

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>

#include "core/robot_model.h"
#include "planner/collision/collision_checker.h"

namespace dashbed::planner::detail {

using core::Pose;
using core::ShapeType;
using Eigen::Vector3d;

/// A rigid transform as rotation and translation: 12 numbers, cheaper to compose than the
/// 4x4 matrix of an Eigen::Isometry3d.
struct Frame {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Vector3d p = Vector3d::Zero();

  Frame() = default;
  explicit Frame(const Pose& X) : R(X.linear()), p(X.translation()) {}
  Frame operator*(const Frame& other) const {
    Frame out;
    out.R.noalias() = R * other.R;
    out.p.noalias() = R * other.p;
    out.p += p;
    return out;
  }
  Vector3d operator*(const Vector3d& x) const { return R * x + p; }
  Pose pose() const {
    Pose X = Pose::Identity();
    X.linear() = R;
    X.translation() = p;
    return X;
  }
};

/// A convex primitive of a robot body, grown by the margin, in the body frame.
struct Shape {
  ShapeType type = ShapeType::kBox;
  Vector3d half = Vector3d::Zero();  // half extents of its bounding box in the shape frame
  double radius = 0.0;               // bounding sphere about the shape frame's origin
  Frame X_BS;
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  int body = -1;
  int link = -1;
};

/// Links joined by fixed joints: one rigid body, moved by the joint to its parent body.
struct Body {
  std::string name;
  int parent = -1;  // parent body; -1 for the root
  int q_index = -1;
  core::JointType joint_type = core::JointType::kFixed;
  Frame X_PJ;  // joint frame in the parent body's frame
  Vector3d axis = Vector3d::UnitZ();
  int axis_id = -1;         // 0, 1, 2 when the axis is +x, +y, +z (fast rotation), else -1
  double stroke = 0.0;      // prismatic: largest |q| within the limits
  int shape_begin = 0;
  int shape_end = 0;
  Vector3d p_BC = Vector3d::Zero();  // bounding sphere of the body's shapes
  double radius = -1.0;              // < 0: the body has no shapes
  bool moves = false;                // some joint moves it (false for the root)
  bool finger = false;               // moved relative to the TCP body by one joint
  double reach = 0.0;       // bound on |p - origin| over the subtree's points and configurations
  double tcp_chain = -1.0;  // TCP ancestors: bound on the distance origin -> TCP; else -1
};

struct RobotData {
  const core::RobotModel* model = nullptr;
  Frame X_WBase;
  std::vector<Body> bodies;  // parents before children
  std::vector<Shape> shapes;
  std::vector<int> body_of_link;
  int tcp_link = -1;
  int tcp_body = -1;
  Frame X_BT;  // TCP in its body's frame
  std::vector<int> static_order;  // moving bodies with shapes, distal first
  std::vector<std::pair<int, int>> self_pairs;  // checked body pairs, most often colliding first
  std::vector<char> self_checked;               // body x body
  std::vector<IgnoredSelfPair> ignored;
  int num_positions = 0;
  std::vector<double> q_lower;
  std::vector<double> q_upper;
};

struct ObjectData {
  Vector3d half = Vector3d::Zero();
  Vector3d half_grown = Vector3d::Zero();
  double radius = 0.0;
  double radius_grown = 0.0;
  std::shared_ptr<fcl::Boxd> box;
  std::shared_ptr<fcl::Boxd> box_grown;
};

struct StaticData {
  std::vector<core::Box> boxes;
  std::vector<int> owner;     // the robot whose pedestal a box is, or -1
  std::vector<std::string> name;  // for messages: "fixture 'table'", "the floor", ...
  std::vector<Frame> frames;  // the boxes' poses
  std::vector<Vector3d> half;
  std::vector<double> radius;
  std::vector<std::shared_ptr<fcl::Boxd>> geometry;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
};

struct SceneData {
  CollisionSettings settings;
  const core::RobotSet* robot_set = nullptr;
  std::vector<RobotData> robots;
  std::vector<ObjectData> objects;
  StaticData statics;
};

/// The queries' argument checks: each throws std::invalid_argument naming what is wrong.
const RobotData& requireRobot(const SceneData& scene, int robot);
void requireConfiguration(const RobotData& robot, const Eigen::VectorXd& q, const char* what);
void requireObjects(const SceneData& scene, std::span<const RestingObject> objects);
void requireHeld(const SceneData& scene, const std::optional<HeldObject>& held);

/// Intervals a motion whose points travel at most `travel` [m] is split into so that none
/// travels more than `step` between samples (>= 1).
inline int stepsFor(double travel, double step) {
  const double steps = std::ceil(travel / step - 1e-9);
  return std::max(1, static_cast<int>(std::min(steps, 1e9)));
}

}  // namespace dashbed::planner::detail
