#include "planner/collision_checker.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include "core/robot_model.h"

namespace dashbed::planner {

void CollisionSettings::validate() const {
  auto fail = [](const std::string& field, const std::string& what) {
    throw std::invalid_argument("collision settings: " + field + " " + what);
  };
  if (!(margin >= 0.0) || !std::isfinite(margin)) fail("margin", "must be finite and >= 0");
  if (!(motion_step > 0.0) || !std::isfinite(motion_step)) fail("motion_step", "must be finite and > 0");
  if (self_pair_samples < 0) fail("self_pair_samples", "must be >= 0");
  if (!(self_pair_always_fraction > 0.0 && self_pair_always_fraction <= 1.0)) {
    fail("self_pair_always_fraction", "must be in (0, 1]");
  }
}

std::vector<RestingObject> startPlacement(const core::World& world) {
  std::vector<RestingObject> placement;
  placement.reserve(world.objects.size());
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    placement.push_back({static_cast<int>(i), world.objects[i].X_WO});
  }
  return placement;
}

namespace detail {
namespace {

using core::Pose;
using core::ShapeType;
using Eigen::Vector3d;
using Solver = fcl::detail::GJKSolver_libccd<double>;
using AabbNode = fcl::detail::NodeBase<fcl::AABBd>;

// Prefilters hand every pair closer than this to FCL; they only reject pairs at least this far
// apart, so FCL's own tolerance (1e-6 m) decides all close calls.
constexpr double kPrefilterTolerance = 1e-5;

// The floor: a large thin box whose top face is the plane z = 0.
constexpr double kFloorExtent = 100.0;
constexpr double kFloorThickness = 0.1;

}  // namespace

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

namespace {

/// A shape placed in W, as the pair tests see it.
struct Placed {
  ShapeType type = ShapeType::kBox;
  const fcl::CollisionGeometryd* geometry = nullptr;
  const Frame* X_W = nullptr;
  const Vector3d* half = nullptr;
  double radius = 0.0;
};

bool spheresApart(const Vector3d& a, double ra, const Vector3d& b, double rb) {
  const double r = ra + rb + kPrefilterTolerance;
  return (a - b).squaredNorm() > r * r;
}

/// Sphere (c, r) against an axis-aligned box.
bool sphereAabbApart(const Vector3d& c, double r, const fcl::AABBd& box) {
  const Vector3d below = (box.min_ - c).cwiseMax(0.0);
  const Vector3d above = (c - box.max_).cwiseMax(0.0);
  const double rr = r + kPrefilterTolerance;
  return (below + above).squaredNorm() > rr * rr;
}

bool sphereAabbApart(const Vector3d& c, double r, const Vector3d& lo, const Vector3d& hi) {
  const Vector3d below = (lo - c).cwiseMax(0.0);
  const Vector3d above = (c - hi).cwiseMax(0.0);
  const double rr = r + kPrefilterTolerance;
  return (below + above).squaredNorm() > rr * rr;
}

/// Sphere (c, r) against the oriented box (X_WB, half extents).
bool sphereObbApart(const Vector3d& c, double r, const Frame& X_WB, const Vector3d& half) {
  const Vector3d p = X_WB.R.transpose() * (c - X_WB.p);
  const Vector3d outside = (p.cwiseAbs() - half).cwiseMax(0.0);
  const double rr = r + kPrefilterTolerance;
  return outside.squaredNorm() > rr * rr;
}

/// Separating-axis test of two oriented boxes (Gottschalk, Lin, Manocha: "OBBTree", SIGGRAPH
/// 1996): true only when some axis separates them by more than kPrefilterTolerance.
bool obbsApart(const Frame& X_WA, const Vector3d& a, const Frame& X_WB, const Vector3d& b) {
  const Eigen::Matrix3d R = X_WA.R.transpose() * X_WB.R;
  const Vector3d t = X_WA.R.transpose() * (X_WB.p - X_WA.p);
  // the epsilon keeps near-parallel edge pairs (cross product ~ 0) from separating falsely
  const Eigen::Matrix3d absR = R.cwiseAbs().array() + 1e-9;
  const double tol = kPrefilterTolerance;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(t[i]) > a[i] + absR.row(i).dot(b) + tol) return true;
  }
  for (int j = 0; j < 3; ++j) {
    if (std::abs(t.dot(R.col(j))) > absR.col(j).dot(a) + b[j] + tol) return true;
  }
  // A_i x B_j; the tolerance is not scaled by |A_i x B_j| <= 1, which keeps the test conservative
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3;
      const int j2 = (j + 2) % 3;
      const double ra = a[i1] * absR(i2, j) + a[i2] * absR(i1, j);
      const double rb = b[j1] * absR(i, j2) + b[j2] * absR(i, j1);
      if (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) > ra + rb + tol) return true;
    }
  }
  return false;
}

/// Half the width of a placed shape's projection on the unit axis u (its support function).
double halfWidth(const Placed& shape, const Vector3d& u) {
  const Eigen::Matrix3d& R = shape.X_W->R;
  const Vector3d& h = *shape.half;
  switch (shape.type) {
    case ShapeType::kBox:
      return h.x() * std::abs(u.dot(R.col(0))) + h.y() * std::abs(u.dot(R.col(1))) +
             h.z() * std::abs(u.dot(R.col(2)));
    case ShapeType::kCylinder: {
      const double along = u.dot(R.col(2));
      return h.z() * std::abs(along) + h.x() * std::sqrt(std::max(0.0, 1.0 - along * along));
    }
    case ShapeType::kSphere:
      return h.x();
  }
  return 0.0;
}

/// True when the axis (any length) separates the shapes by more than kPrefilterTolerance;
/// d is the vector between their centres.
bool separatedAlong(const Placed& a, const Placed& b, const Vector3d& d, const Vector3d& axis) {
  const double norm2 = axis.squaredNorm();
  if (norm2 < 1e-12) return false;
  const Vector3d u = axis / std::sqrt(norm2);
  return std::abs(d.dot(u)) > halfWidth(a, u) + halfWidth(b, u) + kPrefilterTolerance;
}

/// Separating-axis test with the shapes' exact projections, for pairs with a cylinder. The
/// candidate axes: the centre line; each cylinder's axis and the centre line's part across it;
/// each box's face normals; a cylinder's axis crossed with the other shape's axes. A box's
/// bounding box is loose for a cylinder (its corners stick out by 41% of the radius), which
/// would hand many touching-by-construction neighbours to the expensive GJK.
bool roundApart(const Placed& a, const Placed& b) {
  const Vector3d d = b.X_W->p - a.X_W->p;
  // a box's face normals first: against large fixtures they are the separating axes
  for (const Placed* shape : {&a, &b}) {
    if (shape->type != ShapeType::kBox) continue;
    const Eigen::Matrix3d& R = shape->X_W->R;
    for (int i = 0; i < 3; ++i) {
      if (separatedAlong(a, b, d, R.col(i))) return true;
    }
  }
  if (separatedAlong(a, b, d, d)) return true;
  for (const Placed* shape : {&a, &b}) {
    if (shape->type != ShapeType::kCylinder) continue;
    const Vector3d axis = shape->X_W->R.col(2);
    if (separatedAlong(a, b, d, axis) || separatedAlong(a, b, d, d - d.dot(axis) * axis)) return true;
  }
  for (const auto& [cylinder, other] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    if (cylinder->type != ShapeType::kCylinder || other->type == ShapeType::kSphere) continue;
    const Vector3d axis = cylinder->X_W->R.col(2);
    const Eigen::Matrix3d& R = other->X_W->R;
    if (other->type == ShapeType::kCylinder) {
      return separatedAlong(a, b, d, axis.cross(R.col(2)));  // both axes done; the pair is symmetric
    }
    for (int i = 0; i < 3; ++i) {
      if (separatedAlong(a, b, d, axis.cross(R.col(i)))) return true;
    }
  }
  return false;
}

/// True when the point p lies inside the shape, at least kPrefilterTolerance from its surface:
/// a certain intersection that needs no narrow phase.
bool deepInside(const Vector3d& p, const Placed& shape) {
  const Vector3d local = shape.X_W->R.transpose() * (p - shape.X_W->p);
  const Vector3d& h = *shape.half;
  const double tol = kPrefilterTolerance;
  switch (shape.type) {
    case ShapeType::kBox:
      return (local.cwiseAbs() - h).maxCoeff() < -tol;
    case ShapeType::kCylinder:
      return std::abs(local.z()) < h.z() - tol && local.head<2>().norm() < h.x() - tol;
    case ShapeType::kSphere:
      return local.norm() < h.x() - tol;
  }
  return false;
}

template <class ShapeA>
bool narrowPhaseAs(const Solver& solver, const ShapeA& a, const Pose& X_WA, const Placed& b) {
  const Pose X_WB = b.X_W->pose();
  switch (b.type) {
    case ShapeType::kBox:
      return solver.shapeIntersect(a, X_WA, static_cast<const fcl::Boxd&>(*b.geometry), X_WB, nullptr);
    case ShapeType::kCylinder:
      return solver.shapeIntersect(a, X_WA, static_cast<const fcl::Cylinderd&>(*b.geometry), X_WB,
                                   nullptr);
    case ShapeType::kSphere:
      return solver.shapeIntersect(a, X_WA, static_cast<const fcl::Sphered&>(*b.geometry), X_WB,
                                   nullptr);
  }
  return true;
}

/// FCL's primitive intersection test, as fcl::collide runs it for two shapes.
bool narrowPhase(const Solver& solver, const Placed& a, const Placed& b) {
  const Pose X_WA = a.X_W->pose();
  switch (a.type) {
    case ShapeType::kBox:
      return narrowPhaseAs(solver, static_cast<const fcl::Boxd&>(*a.geometry), X_WA, b);
    case ShapeType::kCylinder:
      return narrowPhaseAs(solver, static_cast<const fcl::Cylinderd&>(*a.geometry), X_WA, b);
    case ShapeType::kSphere:
      return narrowPhaseAs(solver, static_cast<const fcl::Sphered&>(*a.geometry), X_WA, b);
  }
  return true;
}

int unitAxisId(const Vector3d& axis) {
  for (int i = 0; i < 3; ++i) {
    if (axis == Vector3d::Unit(i)) return i;
  }
  return -1;
}

// 1/n! for n = 0..18 (n! is exact in a double up to 18!)
constexpr std::array<double, 19> kInverseFactorial = [] {
  std::array<double, 19> table{};
  double factorial = 1.0;
  for (int n = 0; n < 19; ++n) {
    if (n > 1) factorial *= n;
    table[n] = 1.0 / factorial;
  }
  return table;
}();

/// sin and cos of `angle` [rad] for |angle| < 1e5, within about 1 ulp of libm and several times
/// faster than its sincos on this path: the angle is reduced by the nearest multiple k of
/// pi/2 (split into a 33-bit head, so k * head is exact, and a tail), Taylor series of sin and
/// cos to r^17 and r^18 on [-pi/4, pi/4] (truncation error < 1e-19), then k's quadrant swaps
/// and negates them.
void sinCos(double angle, double& sine, double& cosine) {
  constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double kHalfPiHead = 0x1.921fb544p+0;
  constexpr double kHalfPiTail = 0x1.0b4611a626331p-34;
  constexpr double kRoundToInteger = 0x1.8p52;  // adding and subtracting it rounds to nearest
  const double k = (angle * kTwoOverPi + kRoundToInteger) - kRoundToInteger;
  const double r = (angle - k * kHalfPiHead) - k * kHalfPiTail;
  const double r2 = r * r;
  constexpr const std::array<double, 19>& f = kInverseFactorial;
  const double s =
      r + r * r2 * (-f[3] + r2 * (f[5] + r2 * (-f[7] + r2 * (f[9] + r2 * (-f[11] + r2 * (f[13] + r2 * (-f[15] + r2 * f[17])))))));
  const double c =
      1.0 + r2 * (-f[2] + r2 * (f[4] + r2 * (-f[6] + r2 * (f[8] + r2 * (-f[10] + r2 * (f[12] + r2 * (-f[14] + r2 * (f[16] - r2 * f[18]))))))));
  switch (static_cast<long long>(k) & 3) {
    case 0: sine = s; cosine = c; return;
    case 1: sine = c; cosine = -s; return;
    case 2: sine = -s; cosine = -c; return;
    default: sine = -c; cosine = s; return;
  }
}

/// Post-multiplies the rotation of X by a rotation of `angle` about the body's joint axis.
void rotateAboutAxis(Frame& X, const Body& body, double angle) {
  double s = 0.0;
  double c = 1.0;
  sinCos(angle, s, c);
  Eigen::Matrix3d& R = X.R;
  switch (body.axis_id) {
    case 0: {
      const Vector3d c1 = R.col(1);
      const Vector3d c2 = R.col(2);
      R.col(1) = c * c1 + s * c2;
      R.col(2) = c * c2 - s * c1;
      return;
    }
    case 1: {
      const Vector3d c0 = R.col(0);
      const Vector3d c2 = R.col(2);
      R.col(0) = c * c0 - s * c2;
      R.col(2) = s * c0 + c * c2;
      return;
    }
    case 2: {
      const Vector3d c0 = R.col(0);
      const Vector3d c1 = R.col(1);
      R.col(0) = c * c0 + s * c1;
      R.col(1) = c * c1 - s * c0;
      return;
    }
    default:
      X.R = X.R * Eigen::AngleAxisd(angle, body.axis).toRotationMatrix();
  }
}

}  // namespace

/// A colliding pair a check found: a body of the robot checked (kHeldBody: the object it holds)
/// and the part it hits: a static box, or a body of the same or another robot (or kHeldBody).
struct Hit {
  int body = -1;
  int other = -1;
};
constexpr int kHeldBody = -2;

/// The mutable state of the queries: one per checker (and one for building the scene).
struct CheckerState {
  /// One robot's configuration being checked: body poses, lazily placed shapes, held object.
  struct Slot {
    const RobotData* robot = nullptr;
    std::vector<Frame> X_WB;
    std::vector<Vector3d> c_WB;  // body sphere centres
    std::vector<Frame> X_WS;
    std::vector<std::uint32_t> shape_stamp;
    std::uint32_t stamp = 0;
    Eigen::VectorXd q;  // the configuration X_WB was computed for
    bool holding = false;
    int held_object = -1;
    bool held_static = true;
    Frame X_WH;
    Vector3d lo = Vector3d::Zero();  // bounds of all body spheres (and the held object)
    Vector3d hi = Vector3d::Zero();
  };

  const SceneData* scene = nullptr;
  CollisionChecker::Counters* counters = nullptr;
  Solver solver;
  std::vector<Slot> slots;  // one per robot
  std::vector<Slot> standing;  // the other robots of a motionClearOf query
  std::vector<char> known_free;  // [sample] of a motionClearOf query: found free already
  std::vector<const AabbNode*> stack;
  std::vector<int> order;  // bisection order of sample indices for `order_n` intervals
  int order_n = -1;
  std::vector<std::pair<int, int>> queue;
  Eigen::VectorXd q_a;
  Eigen::VectorXd q_b;
  std::vector<Frame> X_WO;  // poses of the resting objects of the current query

  CheckerState(const SceneData& scene_data, CollisionChecker::Counters& counter_sink)
      : scene(&scene_data), counters(&counter_sink), slots(scene_data.robots.size()) {
    solver.collision_tolerance = 1e-6;  // fcl::CollisionRequest's default gjk_tolerance
  }

  // ---- configuration ----

  void forward(Slot& slot, const RobotData& robot, const Eigen::VectorXd& q,
               const std::optional<HeldObject>& held) {
    ++counters->configurations;
    if (slot.robot != &robot) {
      slot.robot = &robot;
      slot.X_WB.assign(robot.bodies.size(), Frame());
      slot.c_WB.assign(robot.bodies.size(), Vector3d::Zero());
      slot.X_WS.assign(robot.shapes.size(), Frame());
      slot.shape_stamp.assign(robot.shapes.size(), 0);
      slot.stamp = 0;
      slot.q.resize(0);
    }
    // the body poses depend on q only: a robot checked again where it stands keeps them
    if (slot.q.size() != q.size() || slot.q != q) {
      slot.q = q;
      placeBodies(slot, robot, q);
    }
    slot.holding = held.has_value();
    if (slot.holding) {
      slot.held_object = held->object;
      slot.held_static = held->check_static;
      slot.X_WH = slot.X_WB[robot.tcp_body] * robot.X_BT * Frame(held->X_TO);
    } else {
      slot.held_object = -1;
    }
  }

  void placeBodies(Slot& slot, const RobotData& robot, const Eigen::VectorXd& q) {
    if (++slot.stamp == 0) {
      std::fill(slot.shape_stamp.begin(), slot.shape_stamp.end(), 0);
      slot.stamp = 1;
    }
    for (std::size_t i = 0; i < robot.bodies.size(); ++i) {
      const Body& body = robot.bodies[i];
      Frame& X = slot.X_WB[i];
      if (body.parent < 0) {
        X = robot.X_WBase;
      } else {
        X = slot.X_WB[body.parent] * body.X_PJ;
        const double value = q[body.q_index];
        if (body.joint_type == core::JointType::kRevolute) {
          rotateAboutAxis(X, body, value);
        } else if (body.joint_type == core::JointType::kPrismatic) {
          X.p += X.R * (body.axis * value);
        }
      }
      slot.c_WB[i] = X * body.p_BC;
    }
  }

  const Frame& shapePose(Slot& slot, int s) {
    if (slot.shape_stamp[s] != slot.stamp) {
      const Shape& shape = slot.robot->shapes[s];
      slot.X_WS[s] = slot.X_WB[shape.body] * shape.X_BS;
      slot.shape_stamp[s] = slot.stamp;
    }
    return slot.X_WS[s];
  }

  Placed placedShape(Slot& slot, int s) {
    const Shape& shape = slot.robot->shapes[s];
    return {shape.type, shape.geometry.get(), &shapePose(slot, s), &shape.half, shape.radius};
  }

  Placed placedHeld(const Slot& slot) const {
    const ObjectData& object = scene->objects[slot.held_object];
    return {ShapeType::kBox, object.box_grown.get(), &slot.X_WH, &object.half_grown, object.radius_grown};
  }

  Placed placedStatic(int k) const {
    const StaticData& statics = scene->statics;
    return {ShapeType::kBox, statics.geometry[k].get(), &statics.frames[k], &statics.half[k],
            statics.radius[k]};
  }

  // ---- pair tests ----

  /// Prefilters, then FCL. True when the shapes intersect.
  bool shapesCollide(const Placed& a, const Placed& b) {
    if (spheresApart(a.X_W->p, a.radius, b.X_W->p, b.radius)) return false;
    if (a.type == ShapeType::kBox && b.type == ShapeType::kBox) {
      if (obbsApart(*a.X_W, *a.half, *b.X_W, *b.half)) return false;
    } else if (a.type == ShapeType::kSphere && b.type == ShapeType::kBox) {
      if (sphereObbApart(a.X_W->p, a.radius, *b.X_W, *b.half)) return false;
    } else if (b.type == ShapeType::kSphere && a.type == ShapeType::kBox) {
      if (sphereObbApart(b.X_W->p, b.radius, *a.X_W, *a.half)) return false;
    } else if (a.type != ShapeType::kSphere || b.type != ShapeType::kSphere) {
      if (roundApart(a, b)) return false;
    }
    // one centre deep inside the other shape: they intersect for sure
    if (deepInside(a.X_W->p, b) || deepInside(b.X_W->p, a)) return true;
    ++counters->narrow_phase;
    return narrowPhase(solver, a, b);
  }

  /// Body `b` of `slot` against the placed shape `other` (bounding sphere first).
  bool bodyHits(Slot& slot, int b, const Placed& other) {
    const Body& body = slot.robot->bodies[b];
    if (body.radius < 0.0) return false;
    if (spheresApart(slot.c_WB[b], body.radius, other.X_W->p, other.radius)) return false;
    for (int s = body.shape_begin; s < body.shape_end; ++s) {
      if (shapesCollide(placedShape(slot, s), other)) return true;
    }
    return false;
  }

  bool bodiesCollide(Slot& slot_a, int a, Slot& slot_b, int b) {
    const Body& body_a = slot_a.robot->bodies[a];
    const Body& body_b = slot_b.robot->bodies[b];
    if (body_a.radius < 0.0 || body_b.radius < 0.0) return false;
    if (spheresApart(slot_a.c_WB[a], body_a.radius, slot_b.c_WB[b], body_b.radius)) return false;
    for (int sa = body_a.shape_begin; sa < body_a.shape_end; ++sa) {
      const Placed pa = placedShape(slot_a, sa);
      if (spheresApart(pa.X_W->p, pa.radius, slot_b.c_WB[b], body_b.radius)) continue;
      for (int sb = body_b.shape_begin; sb < body_b.shape_end; ++sb) {
        if (shapesCollide(pa, placedShape(slot_b, sb))) return true;
      }
    }
    return false;
  }

  /// Visits the static boxes whose AABB the sphere (c, r) reaches, through FCL's dynamic AABB
  /// tree; stops and returns true as soon as `visit(k)` does.
  template <class Visit>
  bool forStaticNear(const Vector3d& c, double r, Visit&& visit) {
    const AabbNode* root = scene->statics.manager.getTree().getRoot();
    if (root == nullptr) return false;
    stack.clear();
    stack.push_back(root);
    while (!stack.empty()) {
      const AabbNode* node = stack.back();
      stack.pop_back();
      if (sphereAabbApart(c, r, node->bv)) continue;
      if (node->isLeaf()) {
        const auto* object = static_cast<const fcl::CollisionObjectd*>(node->data);
        const int k = static_cast<int>(reinterpret_cast<std::intptr_t>(object->getUserData()));
        if (visit(k)) return true;
      } else {
        stack.push_back(node->children[0]);
        stack.push_back(node->children[1]);
      }
    }
    return false;
  }

  // ---- checks of one configuration ----

  /// The first body (or the held object) found against the static scene, with the box it hits.
  std::optional<Hit> staticHit(Slot& slot) {
    const RobotData& robot = *slot.robot;
    const StaticData& statics = scene->statics;
    const int self = static_cast<int>(slot.robot - scene->robots.data());
    int box = -1;
    for (int b : robot.static_order) {
      const Body& body = robot.bodies[b];
      const Vector3d& c = slot.c_WB[b];
      const bool hit = forStaticNear(c, body.radius, [&](int k) {
        if (statics.owner[k] == self || sphereObbApart(c, body.radius, statics.frames[k], statics.half[k])) return false;
        const Placed fixture = placedStatic(k);
        for (int s = body.shape_begin; s < body.shape_end; ++s) {
          if (shapesCollide(placedShape(slot, s), fixture)) {
            box = k;
            return true;
          }
        }
        return false;
      });
      if (hit) return Hit{b, box};
    }
    if (slot.holding && slot.held_static) {
      const Placed held = placedHeld(slot);
      const bool hit = forStaticNear(slot.X_WH.p, held.radius, [&](int k) {
        if (statics.owner[k] == self || !shapesCollide(held, placedStatic(k))) return false;
        box = k;
        return true;
      });
      if (hit) return Hit{kHeldBody, box};
    }
    return std::nullopt;
  }

  /// The first pair of the robot's bodies (or a body and the held object) found colliding.
  std::optional<Hit> selfHit(Slot& slot) {
    const RobotData& robot = *slot.robot;
    for (const auto& [a, b] : robot.self_pairs) {
      if (bodiesCollide(slot, a, slot, b)) return Hit{a, b};
    }
    if (slot.holding) {
      const Placed held = placedHeld(slot);
      for (std::size_t b = robot.bodies.size(); b-- > 0;) {
        if (robot.bodies[b].finger) continue;
        if (bodyHits(slot, static_cast<int>(b), held)) return Hit{static_cast<int>(b), kHeldBody};
      }
    }
    return std::nullopt;
  }

  bool objectCollision(Slot& slot, std::span<const RestingObject> objects) {
    const RobotData& robot = *slot.robot;
    X_WO.resize(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const RestingObject& resting = objects[i];
      if (slot.holding && resting.object == slot.held_object) continue;
      const ObjectData& data = scene->objects[resting.object];
      X_WO[i] = Frame(resting.X_WO);
      const Placed object{ShapeType::kBox, data.box.get(), &X_WO[i], &data.half, data.radius};
      for (std::size_t b = robot.bodies.size(); b-- > 0;) {
        if (bodyHits(slot, static_cast<int>(b), object)) return true;
      }
      if (slot.holding && shapesCollide(placedHeld(slot), object)) return true;
    }
    return false;
  }

  /// One resting object against the robot's bodies and its held object (as objectCollision).
  bool oneObjectCollision(Slot& slot, const RestingObject& resting, Frame& X_WO_resting) {
    if (slot.holding && resting.object == slot.held_object) return false;
    const RobotData& robot = *slot.robot;
    const ObjectData& data = scene->objects[resting.object];
    const Placed object{ShapeType::kBox, data.box.get(), &X_WO_resting, &data.half, data.radius};
    for (std::size_t b = robot.bodies.size(); b-- > 0;) {
      if (bodyHits(slot, static_cast<int>(b), object)) return true;
    }
    return slot.holding && shapesCollide(placedHeld(slot), object);
  }

  bool robotCollision(Slot& slot, std::span<const RestingObject> objects) {
    return staticHit(slot) || selfHit(slot) || objectCollision(slot, objects);
  }

  static void updateBounds(Slot& slot, const ObjectData* held) {
    const RobotData& robot = *slot.robot;
    slot.lo = Vector3d::Constant(std::numeric_limits<double>::infinity());
    slot.hi = -slot.lo;
    for (std::size_t b = 0; b < robot.bodies.size(); ++b) {
      const double r = robot.bodies[b].radius;
      if (r < 0.0) continue;
      slot.lo = slot.lo.cwiseMin(slot.c_WB[b] - Vector3d::Constant(r));
      slot.hi = slot.hi.cwiseMax(slot.c_WB[b] + Vector3d::Constant(r));
    }
    if (held != nullptr) {
      const Vector3d c = slot.X_WH.p;
      slot.lo = slot.lo.cwiseMin(c - Vector3d::Constant(held->radius_grown));
      slot.hi = slot.hi.cwiseMax(c + Vector3d::Constant(held->radius_grown));
    }
  }

  /// Robot against robot. Both slots hold evaluated configurations.
  /// The first pair found colliding: a body of A's robot (or its held object) and one of B's.
  std::optional<Hit> interRobotHit(Slot& A, Slot& B) {
    const ObjectData* held_a = A.holding ? &scene->objects[A.held_object] : nullptr;
    const ObjectData* held_b = B.holding ? &scene->objects[B.held_object] : nullptr;
    updateBounds(A, held_a);
    updateBounds(B, held_b);
    // one object held by both (a handoff): it may touch both robots' fingers
    const bool shared = A.holding && B.holding && A.held_object == B.held_object;
    const RobotData& ra = *A.robot;
    const RobotData& rb = *B.robot;
    for (std::size_t a = ra.bodies.size(); a-- > 0;) {  // distal bodies first
      const Body& body_a = ra.bodies[a];
      if (body_a.radius < 0.0 || sphereAabbApart(A.c_WB[a], body_a.radius, B.lo, B.hi)) continue;
      for (std::size_t b = rb.bodies.size(); b-- > 0;) {
        if (!body_a.moves && !rb.bodies[b].moves) continue;
        if (bodiesCollide(A, static_cast<int>(a), B, static_cast<int>(b))) return Hit{static_cast<int>(a), static_cast<int>(b)};
      }
      if (held_b != nullptr && !(shared && body_a.finger) &&
          bodyHits(A, static_cast<int>(a), placedHeld(B))) {
        return Hit{static_cast<int>(a), kHeldBody};
      }
    }
    if (held_a != nullptr) {
      const Placed held = placedHeld(A);
      if (!sphereAabbApart(A.X_WH.p, held.radius, B.lo, B.hi)) {
        for (std::size_t b = rb.bodies.size(); b-- > 0;) {
          if (shared && rb.bodies[b].finger) continue;
          if (bodyHits(B, static_cast<int>(b), held)) return Hit{kHeldBody, static_cast<int>(b)};
        }
        if (held_b != nullptr && !shared && shapesCollide(held, placedHeld(B))) return Hit{kHeldBody, kHeldBody};
      }
    }
    return std::nullopt;
  }

  // ---- motions ----

  /// Sample indices 1..n-1 midpoint first (breadth-first bisection), then 0 and n.
  const std::vector<int>& bisectionOrder(int n) {
    if (n == order_n) return order;
    order.clear();
    queue.clear();
    queue.emplace_back(0, n);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto [lo, hi] = queue[head];
      if (hi - lo < 2) continue;
      const int mid = lo + (hi - lo) / 2;
      order.push_back(mid);
      queue.emplace_back(lo, mid);
      queue.emplace_back(mid, hi);
    }
    order.push_back(0);
    order.push_back(n);
    order_n = n;
    return order;
  }

  /// Places `robot` in `slot` at the n + 1 samples of the straight motion q_from -> q_to, in
  /// bisection order, calling visit(s) (s in [0, 1] along the motion) after each; stops when
  /// visit returns true. True when stopped.
  template <class Visit>
  bool sweep(Slot& slot, const RobotData& robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
             const std::optional<HeldObject>& held, int n, Visit&& visit) {
    q_a.resize(q_from.size());
    for (const int i : bisectionOrder(n)) {
      const double s = static_cast<double>(i) / n;
      q_a.noalias() = q_from + s * (q_to - q_from);
      forward(slot, robot, q_a, held);
      if (visit(s)) return true;
    }
    return false;
  }
};

}  // namespace detail

// ================================================================================================
// CollisionScene

namespace {

using core::Pose;
using core::ShapeType;
using Eigen::Vector3d;
using detail::Body;
using detail::RobotData;
using detail::Shape;

std::shared_ptr<fcl::CollisionGeometryd> makeGeometry(ShapeType type, const Vector3d& half) {
  switch (type) {
    case ShapeType::kBox:
      return std::make_shared<fcl::Boxd>(2.0 * half);
    case ShapeType::kCylinder:
      return std::make_shared<fcl::Cylinderd>(half.x(), 2.0 * half.z());
    case ShapeType::kSphere:
      return std::make_shared<fcl::Sphered>(half.x());
  }
  return nullptr;
}

/// Half extents of a URDF shape's bounding box after growing it by `margin`.
Vector3d grownHalfExtents(const core::CollisionShape& shape, double margin) {
  switch (shape.type) {
    case ShapeType::kBox:
      return shape.size / 2.0 + Vector3d::Constant(margin);
    case ShapeType::kCylinder:
      return {shape.size.x() + margin, shape.size.x() + margin, shape.size.z() / 2.0 + margin};
    case ShapeType::kSphere:
      return Vector3d::Constant(shape.size.x() + margin);
  }
  return Vector3d::Zero();
}

double boundingRadius(ShapeType type, const Vector3d& half) {
  switch (type) {
    case ShapeType::kBox:
      return half.norm();
    case ShapeType::kCylinder:
      return std::hypot(half.x(), half.z());
    case ShapeType::kSphere:
      return half.x();
  }
  return 0.0;
}

/// Groups the model's links into rigid bodies and places their grown shapes.
RobotData buildRobot(const core::PlacedRobot& placed, double margin) {
  const core::RobotModel& model = *placed.model;
  RobotData robot;
  robot.model = &model;
  robot.X_WBase = detail::Frame(placed.spec->X_WBase);
  robot.num_positions = model.numPositions();
  const auto& links = model.links();
  const auto& joints = model.joints();
  robot.body_of_link.assign(links.size(), -1);

  // bodies: the root, and one per movable joint; a link joins its parent's body over a fixed joint
  std::vector<int> body_root_link;
  for (std::size_t l = 0; l < links.size(); ++l) {
    const int j = links[l].parent_joint;
    if (j >= 0 && joints[j].type == core::JointType::kFixed) {
      robot.body_of_link[l] = robot.body_of_link[joints[j].parent_link];
      continue;
    }
    Body body;
    body.name = links[l].name;
    if (j >= 0) {
      const core::JointModel& joint = joints[j];
      const int parent_body = robot.body_of_link[joint.parent_link];
      body.parent = parent_body;
      body.q_index = joint.q_index;
      body.joint_type = joint.type;
      body.X_PJ = detail::Frame(model.fixedTransform(body_root_link[parent_body], joint.parent_link) * joint.X_PJ);
      body.axis = joint.axis;
      body.axis_id = detail::unitAxisId(joint.axis);
      body.stroke = std::max(std::abs(joint.lower), std::abs(joint.upper));
      body.moves = true;
    }
    robot.body_of_link[l] = static_cast<int>(robot.bodies.size());
    body_root_link.push_back(static_cast<int>(l));
    robot.bodies.push_back(std::move(body));
  }

  // shapes, grouped by body
  for (std::size_t b = 0; b < robot.bodies.size(); ++b) {
    Body& body = robot.bodies[b];
    body.shape_begin = static_cast<int>(robot.shapes.size());
    for (std::size_t l = 0; l < links.size(); ++l) {
      if (robot.body_of_link[l] != static_cast<int>(b)) continue;
      const Pose X_BL = model.fixedTransform(body_root_link[b], static_cast<int>(l));
      for (const core::CollisionShape& urdf_shape : links[l].collisions) {
        Shape shape;
        shape.type = urdf_shape.type;
        shape.half = grownHalfExtents(urdf_shape, margin);
        shape.radius = boundingRadius(shape.type, shape.half);
        shape.X_BS = detail::Frame(X_BL * urdf_shape.X_LS);
        shape.geometry = makeGeometry(shape.type, shape.half);
        shape.body = static_cast<int>(b);
        shape.link = static_cast<int>(l);
        robot.shapes.push_back(std::move(shape));
      }
    }
    body.shape_end = static_cast<int>(robot.shapes.size());
    // bounding sphere of the shapes' spheres, centred at their centroid
    if (body.shape_end > body.shape_begin) {
      Vector3d centre = Vector3d::Zero();
      for (int s = body.shape_begin; s < body.shape_end; ++s) centre += robot.shapes[s].X_BS.p;
      centre /= body.shape_end - body.shape_begin;
      double radius = 0.0;
      for (int s = body.shape_begin; s < body.shape_end; ++s) {
        radius = std::max(radius, (robot.shapes[s].X_BS.p - centre).norm() + robot.shapes[s].radius);
      }
      body.p_BC = centre;
      body.radius = radius;
    }
  }

  // TCP, fingers
  robot.tcp_link = model.linkIndex("tcp");
  if (robot.tcp_link < 0) {
    throw std::invalid_argument("collision scene: robot model '" + model.name() + "' has no link 'tcp'");
  }
  robot.tcp_body = robot.body_of_link[robot.tcp_link];
  robot.X_BT = detail::Frame(model.fixedTransform(body_root_link[robot.tcp_body], robot.tcp_link));
  for (Body& body : robot.bodies) body.finger = body.parent >= 0 && body.parent == robot.tcp_body;

  // reach bounds, children first (bodies are in topological order)
  for (std::size_t i = robot.bodies.size(); i-- > 0;) {
    Body& body = robot.bodies[i];
    for (int s = body.shape_begin; s < body.shape_end; ++s) {
      body.reach = std::max(body.reach, robot.shapes[s].X_BS.p.norm() + robot.shapes[s].radius);
    }
    if (body.parent >= 0) {
      Body& parent = robot.bodies[body.parent];
      const double offset = body.X_PJ.p.norm() +
                            (body.joint_type == core::JointType::kPrismatic ? body.stroke : 0.0);
      parent.reach = std::max(parent.reach, offset + body.reach);
    }
  }
  for (int b = robot.tcp_body, chain = -1; b >= 0; chain = b, b = robot.bodies[b].parent) {
    Body& body = robot.bodies[b];
    if (chain < 0) {
      body.tcp_chain = robot.X_BT.p.norm();
    } else {
      const Body& child = robot.bodies[chain];
      body.tcp_chain = child.X_PJ.p.norm() +
                       (child.joint_type == core::JointType::kPrismatic ? child.stroke : 0.0) +
                       child.tcp_chain;
    }
  }

  // moving bodies against the static scene, distal ones first (most likely to hit something)
  for (std::size_t i = robot.bodies.size(); i-- > 0;) {
    if (robot.bodies[i].moves && robot.bodies[i].radius >= 0.0) robot.static_order.push_back(static_cast<int>(i));
  }

  robot.q_lower.assign(robot.num_positions, 0.0);
  robot.q_upper.assign(robot.num_positions, 0.0);
  for (int j : model.movableJoints()) {
    robot.q_lower[joints[j].q_index] = joints[j].lower;
    robot.q_upper[joints[j].q_index] = joints[j].upper;
  }
  return robot;
}

/// Boxes around what of a robot no joint moves (its base) and around what a vertical revolute
/// joint on it sweeps (a UR shoulder turning on its base): the robot's pedestal, which the other
/// robots treat as static geometry. A cylinder coaxial with that joint keeps its radius.
std::vector<core::Box> pedestalBoxes(const detail::RobotData& robot) {
  std::vector<core::Box> boxes;
  for (const detail::Body& body : robot.bodies) {
    if (body.parent >= 0 && (robot.bodies[body.parent].moves || body.joint_type != core::JointType::kRevolute)) continue;
    const detail::Frame X_WJ = body.parent < 0 ? robot.X_WBase : robot.X_WBase * body.X_PJ;  // the root's parent is the base
    const Vector3d axis_W = X_WJ.R * body.axis;
    if (body.parent >= 0 && std::abs(axis_W.z()) < 1.0 - 1e-9) continue;
    for (int s = body.shape_begin; s < body.shape_end; ++s) {
      const detail::Shape& shape = robot.shapes[s];
      core::Box box;
      if (body.parent < 0) {
        box.X_WB = (X_WJ * shape.X_BS).pose();
        box.size = 2.0 * shape.half;
      } else {
        const double along = shape.X_BS.p.dot(body.axis);
        const double radial = (shape.X_BS.p - along * body.axis).norm();
        const bool coaxial = shape.type == ShapeType::kCylinder && std::abs(shape.X_BS.R.col(2).dot(body.axis)) > 1.0 - 1e-9;
        const double r = radial + (coaxial ? shape.half.x() : shape.radius);
        const double h = coaxial ? shape.half.z() : shape.radius;
        box.X_WB = Pose::Identity();
        box.X_WB.translation() = X_WJ * (along * body.axis);
        box.size = Vector3d(2.0 * r, 2.0 * r, 2.0 * h);
      }
      boxes.push_back(box);
    }
  }
  return boxes;
}


}  // namespace

namespace {

/// Finds the body pairs the self-collision check can skip (see the header) and orders the
/// others by how often they collided in the samples, most often first.
void computeSelfPairs(const detail::SceneData& scene, RobotData& robot, const core::RobotSpec& spec) {
  const CollisionSettings& settings = scene.settings;
  const int nb = static_cast<int>(robot.bodies.size());
  robot.self_checked.assign(static_cast<std::size_t>(nb * nb), 0);
  robot.self_pairs.clear();
  robot.ignored.clear();

  struct Candidate {
    int a;
    int b;
    bool home = false;
    int hits = 0;
  };
  std::vector<Candidate> candidates;
  for (int a = 0; a < nb; ++a) {
    for (int b = a + 1; b < nb; ++b) {
      if (robot.bodies[a].radius < 0.0 || robot.bodies[b].radius < 0.0) continue;
      if (robot.bodies[b].parent == a || robot.bodies[a].parent == b) {
        robot.ignored.push_back({robot.bodies[a].name, robot.bodies[b].name, "adjacent"});
        continue;
      }
      candidates.push_back({a, b});
    }
  }

  CollisionChecker::Counters counters;
  detail::CheckerState state(scene, counters);
  const int robot_index = static_cast<int>(&robot - scene.robots.data());
  auto& slot = state.slots[robot_index];
  const int n = robot.num_positions;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n && i < static_cast<int>(spec.home.size()); ++i) q[i] = spec.home[i];
  // home with the other joints (the fingers) at their upper, then lower limit: open, closed
  for (const bool open : {true, false}) {
    for (int i = static_cast<int>(spec.home.size()); i < n; ++i) q[i] = open ? robot.q_upper[i] : robot.q_lower[i];
    state.forward(slot, robot, q, std::nullopt);
    for (Candidate& c : candidates) {
      if (state.bodiesCollide(slot, c.a, slot, c.b)) c.home = true;
    }
  }
  std::mt19937_64 rng(settings.self_pair_seed);
  for (int k = 0; k < settings.self_pair_samples; ++k) {
    for (int i = 0; i < n; ++i) {
      q[i] = std::uniform_real_distribution<double>(robot.q_lower[i], robot.q_upper[i])(rng);
    }
    state.forward(slot, robot, q, std::nullopt);
    for (Candidate& c : candidates) {
      if (state.bodiesCollide(slot, c.a, slot, c.b)) ++c.hits;
    }
  }

  std::vector<Candidate> checked;
  for (const Candidate& c : candidates) {
    const double fraction =
        settings.self_pair_samples > 0 ? static_cast<double>(c.hits) / settings.self_pair_samples : 0.0;
    if (c.home) {
      robot.ignored.push_back({robot.bodies[c.a].name, robot.bodies[c.b].name, "home"});
    } else if (settings.self_pair_samples > 0 && fraction >= settings.self_pair_always_fraction) {
      std::ostringstream reason;
      reason << "always (" << fraction << ")";
      robot.ignored.push_back({robot.bodies[c.a].name, robot.bodies[c.b].name, reason.str()});
    } else {
      checked.push_back(c);
    }
  }
  std::stable_sort(checked.begin(), checked.end(),
                   [](const Candidate& x, const Candidate& y) { return x.hits > y.hits; });
  for (const Candidate& c : checked) {
    robot.self_pairs.emplace_back(c.a, c.b);
    robot.self_checked[static_cast<std::size_t>(c.a * nb + c.b)] = 1;
    robot.self_checked[static_cast<std::size_t>(c.b * nb + c.a)] = 1;
  }
}

const RobotData& requireRobot(const detail::SceneData& scene, int robot) {
  if (robot < 0 || robot >= static_cast<int>(scene.robots.size())) {
    throw std::invalid_argument("collision check: robot index " + std::to_string(robot) + " out of range");
  }
  return scene.robots[robot];
}

void requireConfiguration(const RobotData& robot, const Eigen::VectorXd& q, const char* what) {
  if (q.size() != robot.num_positions) {
    throw std::invalid_argument(std::string("collision check: ") + what + " has " + std::to_string(q.size()) +
                                " entries, robot model '" + robot.model->name() + "' expects " +
                                std::to_string(robot.num_positions));
  }
  if (!q.allFinite()) {
    throw std::invalid_argument(std::string("collision check: ") + what + " is not finite");
  }
}

void requireObjects(const detail::SceneData& scene, std::span<const RestingObject> objects) {
  for (const RestingObject& resting : objects) {
    if (resting.object < 0 || resting.object >= static_cast<int>(scene.objects.size())) {
      throw std::invalid_argument("collision check: resting object index " + std::to_string(resting.object) +
                                  " out of range");
    }
  }
}

void requireHeld(const detail::SceneData& scene, const std::optional<HeldObject>& held) {
  if (held && (held->object < 0 || held->object >= static_cast<int>(scene.objects.size()))) {
    throw std::invalid_argument("collision check: held object index " + std::to_string(held->object) +
                                " out of range");
  }
}

}  // namespace

CollisionScene::CollisionScene(const core::World& world, const core::RobotSet& robots,
                               const CollisionSettings& settings)
    : data_(std::make_unique<detail::SceneData>()) {
  settings.validate();
  if (robots.size() != world.robots.size()) {
    throw std::invalid_argument("collision scene: the robot set was not made from this world");
  }
  detail::SceneData& data = *data_;
  data.settings = settings;
  data.robot_set = &robots;

  for (std::size_t r = 0; r < robots.size(); ++r) {
    data.robots.push_back(buildRobot(robots[r], settings.margin));
  }
  for (std::size_t r = 0; r < robots.size(); ++r) {
    computeSelfPairs(data, data.robots[r], *robots[r].spec);
  }

  // static geometry in FCL's dynamic AABB tree: the fixtures' boxes, the floor, and each
  // robot's pedestal (static for the other robots)
  detail::StaticData& statics = data.statics;
  for (const core::FixtureSpec& fixture : world.fixtures) {
    statics.boxes.insert(statics.boxes.end(), fixture.boxes.begin(), fixture.boxes.end());
    statics.name.insert(statics.name.end(), fixture.boxes.size(), "fixture '" + fixture.name + "'");
  }
  core::Box floor;
  floor.X_WB = Pose::Identity();
  floor.X_WB.translation() = Vector3d(0.0, 0.0, -detail::kFloorThickness / 2.0);
  floor.size = Vector3d(detail::kFloorExtent, detail::kFloorExtent, detail::kFloorThickness);
  statics.boxes.push_back(floor);
  statics.name.emplace_back("the floor");
  statics.owner.assign(statics.boxes.size(), -1);
  for (std::size_t r = 0; r < data.robots.size(); ++r) {
    for (const core::Box& box : pedestalBoxes(data.robots[r])) {
      statics.boxes.push_back(box);
      statics.owner.push_back(static_cast<int>(r));
      statics.name.push_back("the base of robot '" + robots[r].spec->name + "'");
    }
  }
  for (std::size_t k = 0; k < statics.boxes.size(); ++k) {
    const core::Box& box = statics.boxes[k];
    statics.frames.emplace_back(box.X_WB);
    statics.half.push_back(box.size / 2.0);
    statics.radius.push_back(box.size.norm() / 2.0);
    statics.geometry.push_back(std::make_shared<fcl::Boxd>(box.size));
    auto object = std::make_unique<fcl::CollisionObjectd>(statics.geometry.back(), box.X_WB);
    object->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(k)));
    statics.manager.registerObject(object.get());
    statics.objects.push_back(std::move(object));
  }
  statics.manager.setup();

  for (const core::ObjectSpec& spec : world.objects) {
    detail::ObjectData object;
    object.half = spec.size / 2.0;
    object.half_grown = object.half + Vector3d::Constant(settings.margin);
    object.radius = object.half.norm();
    object.radius_grown = object.half_grown.norm();
    object.box = std::make_shared<fcl::Boxd>(2.0 * object.half);
    object.box_grown = std::make_shared<fcl::Boxd>(2.0 * object.half_grown);
    data.objects.push_back(std::move(object));
  }
}

CollisionScene::~CollisionScene() = default;

const core::RobotSet& CollisionScene::robots() const { return *data_->robot_set; }

const CollisionSettings& CollisionScene::settings() const { return data_->settings; }
int CollisionScene::numRobots() const { return static_cast<int>(data_->robots.size()); }
int CollisionScene::numObjects() const { return static_cast<int>(data_->objects.size()); }
int CollisionScene::numPositions(int robot) const { return requireRobot(*data_, robot).num_positions; }
Eigen::VectorXd CollisionScene::configuration(int robot, const core::ArmConfig& q, double finger) const {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(numPositions(robot), finger);
  for (std::size_t j = 0; j < q.size(); ++j) x[static_cast<Eigen::Index>(j)] = q[j];
  return x;
}
const std::vector<core::Box>& CollisionScene::staticBoxes() const { return data_->statics.boxes; }

namespace {
int requireLink(const RobotData& robot, int link) {
  if (link < 0 || link >= static_cast<int>(robot.body_of_link.size())) {
    throw std::invalid_argument("collision scene: link index " + std::to_string(link) + " out of range");
  }
  return robot.body_of_link[link];
}
}  // namespace

bool CollisionScene::selfPairChecked(int robot, int link_a, int link_b) const {
  const RobotData& data = requireRobot(*data_, robot);
  const int a = requireLink(data, link_a);
  const int b = requireLink(data, link_b);
  return data.self_checked[static_cast<std::size_t>(a) * data.bodies.size() + static_cast<std::size_t>(b)] != 0;
}

std::vector<IgnoredSelfPair> CollisionScene::ignoredSelfPairs(int robot) const {
  return requireRobot(*data_, robot).ignored;
}

bool CollisionScene::linkMoves(int robot, int link) const {
  const RobotData& data = requireRobot(*data_, robot);
  return data.bodies[requireLink(data, link)].moves;
}

bool CollisionScene::linkHoldsObjects(int robot, int link) const {
  const RobotData& data = requireRobot(*data_, robot);
  return data.bodies[requireLink(data, link)].finger;
}

int CollisionScene::tcpLink(int robot) const { return requireRobot(*data_, robot).tcp_link; }

double CollisionScene::jointTravelRadius(int robot, int q_index) const {
  const RobotData& data = requireRobot(*data_, robot);
  for (const Body& body : data.bodies) {
    if (body.q_index == q_index) return body.joint_type == core::JointType::kPrismatic ? 1.0 : body.reach;
  }
  throw std::invalid_argument("collision scene: no joint with configuration index " + std::to_string(q_index));
}

int CollisionScene::motionSteps(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                const std::optional<HeldObject>& held) const {
  const double travel = motionTravel(robot, q_from, q_to, held);
  const double steps = std::ceil(travel / data_->settings.motion_step - 1e-9);
  return std::max(1, static_cast<int>(std::min(steps, 1e9)));
}

double CollisionScene::motionTravel(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                    const std::optional<HeldObject>& held) const {
  const RobotData& data = requireRobot(*data_, robot);
  requireConfiguration(data, q_from, "q_from");
  requireConfiguration(data, q_to, "q_to");
  requireHeld(*data_, held);
  // a held object reaches |p_TO| + its bounding radius beyond the TCP
  const double held_extent =
      held ? held->X_TO.translation().norm() + data_->objects[held->object].radius_grown : 0.0;
  double travel = 0.0;  // bound on any point's travel over the whole motion [m]
  for (const Body& body : data.bodies) {
    if (body.q_index < 0) continue;
    double weight = 1.0;  // prismatic: points move by |dq|
    if (body.joint_type == core::JointType::kRevolute) {
      weight = body.reach;
      if (held && body.tcp_chain >= 0.0) weight = std::max(weight, body.tcp_chain + held_extent);
    }
    travel += weight * std::abs(q_to[body.q_index] - q_from[body.q_index]);
  }
  return travel;
}

// ================================================================================================
// CollisionChecker

CollisionChecker::CollisionChecker(const CollisionScene& scene)
    : scene_(&scene), state_(std::make_unique<detail::CheckerState>(*scene.data_, counters_)) {}

CollisionChecker::~CollisionChecker() = default;

bool CollisionChecker::robotFree(int robot, const Eigen::VectorXd& q, std::span<const RestingObject> objects,
                                 const std::optional<HeldObject>& held) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  requireConfiguration(data, q, "q");
  requireHeld(scene, held);
  requireObjects(scene, objects);
  auto& slot = state_->slots[robot];
  state_->forward(slot, data, q, held);
  return !state_->robotCollision(slot, objects);
}

std::string CollisionChecker::robotContact(int robot, const Eigen::VectorXd& q) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  requireConfiguration(data, q, "q");
  auto& slot = state_->slots[robot];
  state_->forward(slot, data, q, std::nullopt);
  if (const std::optional<detail::Hit> hit = state_->staticHit(slot)) {
    return "its " + data.bodies[hit->body].name + " and " + scene.statics.name[hit->other];
  }
  if (const std::optional<detail::Hit> hit = state_->selfHit(slot)) {
    return "its " + data.bodies[hit->body].name + " and its " + data.bodies[hit->other].name;
  }
  return "";
}

std::string CollisionChecker::robotsContact(int robot_a, const Eigen::VectorXd& q_a, int robot_b,
                                            const Eigen::VectorXd& q_b) {
  placePair(robot_a, q_a, std::nullopt, robot_b, q_b, std::nullopt);
  const std::optional<detail::Hit> hit = state_->interRobotHit(state_->slots[robot_a], state_->slots[robot_b]);
  if (!hit) return "";
  const detail::SceneData& scene = *scene_->data_;
  return "its " + scene.robots[robot_a].bodies[hit->body].name + " and robot '" +
         (*scene.robot_set)[static_cast<std::size_t>(robot_b)].spec->name + "''s " +
         scene.robots[robot_b].bodies[hit->other].name;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> CollisionChecker::robotBounds(int robot, const Eigen::VectorXd& q,
                                                                         const std::optional<HeldObject>& held) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  requireConfiguration(data, q, "q");
  requireHeld(scene, held);
  auto& slot = state_->slots[robot];
  state_->forward(slot, data, q, held);
  detail::CheckerState::updateBounds(slot, held ? &scene.objects[held->object] : nullptr);
  return {slot.lo, slot.hi};
}

bool CollisionChecker::robotsFree(int robot_a, const Eigen::VectorXd& q_a, const std::optional<HeldObject>& held_a,
                                  int robot_b, const Eigen::VectorXd& q_b,
                                  const std::optional<HeldObject>& held_b) {
  placePair(robot_a, q_a, held_a, robot_b, q_b, held_b);
  return !state_->interRobotHit(state_->slots[robot_a], state_->slots[robot_b]);
}

void CollisionChecker::placePair(int robot_a, const Eigen::VectorXd& q_a, const std::optional<HeldObject>& held_a,
                                 int robot_b, const Eigen::VectorXd& q_b, const std::optional<HeldObject>& held_b) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& a = requireRobot(scene, robot_a);
  const RobotData& b = requireRobot(scene, robot_b);
  if (robot_a == robot_b) throw std::invalid_argument("collision check: robot against robot needs two different robots");
  requireConfiguration(a, q_a, "q_a");
  requireConfiguration(b, q_b, "q_b");
  requireHeld(scene, held_a);
  requireHeld(scene, held_b);
  state_->forward(state_->slots[robot_a], a, q_a, held_a);
  state_->forward(state_->slots[robot_b], b, q_b, held_b);
}

namespace {

/// A capsule in W: the points within `r` of the segment p + s d, s in [0, 1].
struct Capsule {
  Eigen::Vector3d p;
  Eigen::Vector3d d;
  double r;
};

/// A capsule holding a placed shape: a cylinder's axis, a box's longest axis (radius: the
/// half diagonal across it), a sphere's centre.
Capsule capsuleAround(ShapeType type, const detail::Frame& X_WS, const Vector3d& half) {
  switch (type) {
    case ShapeType::kCylinder: {
      const Vector3d axis = X_WS.R.col(2) * half.z();
      return {X_WS.p - axis, 2.0 * axis, half.x()};
    }
    case ShapeType::kBox: {
      int i = 0;
      half.maxCoeff(&i);
      const Vector3d axis = X_WS.R.col(i) * half[i];
      const double r = std::hypot(half[(i + 1) % 3], half[(i + 2) % 3]);
      return {X_WS.p - axis, 2.0 * axis, r};
    }
    case ShapeType::kSphere:
      break;
  }
  return {X_WS.p, Vector3d::Zero(), half.x()};
}

/// Distance between the segments p1 + s d1 and p2 + t d2 (s, t in [0, 1]): the closest points
/// by minimising over s and t with clamping.
double segmentDistance(const Vector3d& p1, const Vector3d& d1, const Vector3d& p2, const Vector3d& d2) {
  constexpr double kTiny = 1e-18;
  const Vector3d r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= kTiny && e <= kTiny) {
    return r.norm();
  }
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2);
      const double denom = a * e - b * b;
      s = denom > kTiny * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return (p1 + s * d1 - (p2 + t * d2)).norm();
}

// A sample skipped by its clearance (motionClearOf) keeps this much of it in hand [m]: rounding.
constexpr double kClearanceSlack = 1e-4;
// motionClearOf measures robotsClearance while it skips at least this many samples
constexpr double kWorthMeasuring = 8.0;

/// robotsClearance of two evaluated slots found free, at most `cap` [m] (pairs of capsule groups
/// no nearer than that are not measured).
double slotsClearance(detail::CheckerState& state, detail::CheckerState::Slot& slot_a,
                      detail::CheckerState::Slot& slot_b, double cap) {
  const detail::SceneData& scene = *state.scene;
  // Per robot, groups of capsules holding its shapes: one per body with shapes (with the
  // body's bounding sphere, to skip groups that cannot come closer than the best so far), and
  // one for the held object.
  struct Group {
    Vector3d c;
    double r;
    bool moves;
    std::size_t begin, end;  // into the capsules
  };
  const auto collect = [&](detail::CheckerState::Slot& slot, std::vector<Group>& groups, std::vector<Capsule>& capsules) {
    groups.clear();
    capsules.clear();
    const RobotData& robot = *slot.robot;
    for (std::size_t b = 0; b < robot.bodies.size(); ++b) {
      const Body& body = robot.bodies[b];
      if (body.radius < 0.0) continue;
      const std::size_t begin = capsules.size();
      for (int k = body.shape_begin; k < body.shape_end; ++k) {
        const Shape& shape = robot.shapes[k];
        capsules.push_back(capsuleAround(shape.type, state.shapePose(slot, k), shape.half));
      }
      groups.push_back({slot.c_WB[b], body.radius, body.moves, begin, capsules.size()});
    }
    if (slot.holding) {
      const detail::ObjectData& object = scene.objects[slot.held_object];
      capsules.push_back(capsuleAround(ShapeType::kBox, slot.X_WH, object.half_grown));
      groups.push_back({slot.X_WH.p, object.radius_grown, true, capsules.size() - 1, capsules.size()});
    }
  };
  std::vector<Group> groups_a, groups_b;
  std::vector<Capsule> capsules_a, capsules_b;
  groups_a.reserve(16);
  groups_b.reserve(16);
  capsules_a.reserve(32);
  capsules_b.reserve(32);
  collect(slot_a, groups_a, capsules_a);
  collect(slot_b, groups_b, capsules_b);
  // the group pairs' sphere gaps (pairs of which neither moves: none); the nearest pair is
  // measured first, so that the gap found prunes the others from the start (a minimum does not
  // depend on the order)
  std::vector<double> sphere_gaps(groups_a.size() * groups_b.size(), std::numeric_limits<double>::infinity());
  std::size_t nearest = 0;
  for (std::size_t gx = 0; gx < groups_a.size(); ++gx) {
    for (std::size_t gy = 0; gy < groups_b.size(); ++gy) {
      const Group& x = groups_a[gx];
      const Group& y = groups_b[gy];
      if (!x.moves && !y.moves) continue;
      const std::size_t k = gx * groups_b.size() + gy;
      sphere_gaps[k] = (x.c - y.c).norm() - x.r - y.r;
      if (sphere_gaps[k] < sphere_gaps[nearest]) nearest = k;
    }
  }
  double gap = cap;
  const auto measure = [&](std::size_t k) {
    const Group& x = groups_a[k / groups_b.size()];
    const Group& y = groups_b[k % groups_b.size()];
    for (std::size_t i = x.begin; i < x.end; ++i) {
      const Capsule& u = capsules_a[i];
      for (std::size_t j = y.begin; j < y.end; ++j) {
        const Capsule& v = capsules_b[j];
        gap = std::min(gap, segmentDistance(u.p, u.d, v.p, v.d) - u.r - v.r);
      }
    }
  };
  if (!sphere_gaps.empty() && sphere_gaps[nearest] < gap) measure(nearest);
  for (std::size_t k = 0; k < sphere_gaps.size(); ++k) {
    if (k != nearest && sphere_gaps[k] < gap) measure(k);
  }
  return std::max(gap, 0.0);
}

}  // namespace

double boxesGap(const std::pair<Eigen::Vector3d, Eigen::Vector3d>& a, const std::pair<Eigen::Vector3d, Eigen::Vector3d>& b) {
  return (a.first - b.second).cwiseMax(b.first - a.second).cwiseMax(0.0).norm();
}

double CollisionChecker::robotsClearance(int robot_a, const Eigen::VectorXd& q_a,
                                         const std::optional<HeldObject>& held_a, int robot_b,
                                         const Eigen::VectorXd& q_b, const std::optional<HeldObject>& held_b) {
  if (!robotsFree(robot_a, q_a, held_a, robot_b, q_b, held_b)) return -1.0;
  return slotsClearance(*state_, state_->slots[robot_a], state_->slots[robot_b],
                        std::numeric_limits<double>::infinity());
}

bool CollisionChecker::motionFree(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                  std::span<const RestingObject> objects, const std::optional<HeldObject>& held) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  const int n = scene_->motionSteps(robot, q_from, q_to, held);  // validates the arguments
  requireObjects(scene, objects);
  auto& state = *state_;
  auto& slot = state.slots[robot];
  return !state.sweep(slot, data, q_from, q_to, held, n, [&](double) { return state.robotCollision(slot, objects); });
}

std::vector<char> CollisionChecker::motionObjectHits(int robot, const Eigen::VectorXd& q_from,
                                                     const Eigen::VectorXd& q_to,
                                                     std::span<const RestingObject> objects,
                                                     const std::optional<HeldObject>& held) {
  return *motionHits(robot, q_from, q_to, objects, held, false);
}

std::optional<std::vector<char>> CollisionChecker::motionCheck(int robot, const Eigen::VectorXd& q_from,
                                                               const Eigen::VectorXd& q_to,
                                                               std::span<const RestingObject> objects,
                                                               const std::optional<HeldObject>& held) {
  return motionHits(robot, q_from, q_to, objects, held, true);
}

std::optional<std::vector<char>> CollisionChecker::motionHits(int robot, const Eigen::VectorXd& q_from,
                                                              const Eigen::VectorXd& q_to,
                                                              std::span<const RestingObject> objects,
                                                              const std::optional<HeldObject>& held,
                                                              bool check_robot) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  const int n = scene_->motionSteps(robot, q_from, q_to, held);  // validates the arguments
  requireObjects(scene, objects);
  std::vector<char> hits(objects.size(), 0);
  if (objects.empty() && !check_robot) return hits;
  auto& state = *state_;
  auto& slot = state.slots[robot];
  std::vector<detail::Frame> poses;
  poses.reserve(objects.size());
  for (const RestingObject& resting : objects) poses.emplace_back(resting.X_WO);
  const detail::ObjectData* held_data = held ? &scene.objects[held->object] : nullptr;
  // An object is tested at a sample only when its bounding sphere reaches the box around the
  // robot's body spheres (and held object) there: otherwise every sphere test of
  // oneObjectCollision rejects it. The slack keeps rounding on the safe side.
  constexpr double kSlack = 1e-6;
  // objects apart from the box at the first sample grown by the motion's travel bound (no
  // sphere centre moves farther) are never reached
  std::vector<std::size_t> near;
  near.reserve(objects.size());
  bool first = true;
  bool collides = false;
  std::size_t left = 0;
  // stops at a collision with the static scene or itself, or when nothing is left to find
  state.sweep(slot, data, q_from, q_to, held, n, [&](double) {
    if (check_robot && (state.staticHit(slot) || state.selfHit(slot))) return collides = true;
    if (first || left > 0) detail::CheckerState::updateBounds(slot, held_data);
    if (first) {
      first = false;
      const double travel = n * scene.settings.motion_step + 1e-4;
      for (std::size_t k = 0; k < objects.size(); ++k) {
        if (held && objects[k].object == held->object) continue;  // never a hit
        const detail::ObjectData& object = scene.objects[objects[k].object];
        if (!detail::sphereAabbApart(poses[k].p, object.radius + travel + kSlack, slot.lo, slot.hi)) near.push_back(k);
      }
      left = near.size();
      if (left == 0 && !check_robot) return true;
    }
    for (const std::size_t k : near) {
      if (left == 0) break;
      if (hits[k]) continue;
      const detail::ObjectData& object = scene.objects[objects[k].object];
      if (detail::sphereAabbApart(poses[k].p, object.radius + kSlack, slot.lo, slot.hi)) continue;
      if (!state.oneObjectCollision(slot, objects[k], poses[k])) continue;
      hits[k] = 1;
      if (--left == 0 && !check_robot) return true;
    }
    return false;
  });
  if (collides) return std::nullopt;
  return hits;
}

bool CollisionChecker::motionsFree(int robot_a, const Eigen::VectorXd& q_a_from, const Eigen::VectorXd& q_a_to,
                                   const std::optional<HeldObject>& held_a, int robot_b,
                                   const Eigen::VectorXd& q_b_from, const Eigen::VectorXd& q_b_to,
                                   const std::optional<HeldObject>& held_b) {
  const detail::SceneData& scene = *scene_->data_;
  if (robot_a == robot_b) throw std::invalid_argument("collision check: motionsFree needs two different robots");
  const RobotData& a = requireRobot(scene, robot_a);
  const RobotData& b = requireRobot(scene, robot_b);
  const int n = std::max(scene_->motionSteps(robot_a, q_a_from, q_a_to, held_a),
                         scene_->motionSteps(robot_b, q_b_from, q_b_to, held_b));
  auto& state = *state_;
  auto& slot_a = state.slots[robot_a];
  auto& slot_b = state.slots[robot_b];
  state.q_b.resize(q_b_from.size());
  return !state.sweep(slot_a, a, q_a_from, q_a_to, held_a, n, [&](double s) {
    state.q_b.noalias() = q_b_from + s * (q_b_to - q_b_from);
    state.forward(slot_b, b, state.q_b, held_b);
    return state.interRobotHit(slot_a, slot_b).has_value();
  });
}

bool CollisionChecker::motionClearOf(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                     const std::optional<HeldObject>& held,
                                     std::span<const StandingRobot> others) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  // a standing robot takes one step: motionsFree would check this many samples
  const int n = scene_->motionSteps(robot, q_from, q_to, held);  // validates the arguments
  auto& state = *state_;
  state.standing.resize(others.size());
  for (std::size_t k = 0; k < others.size(); ++k) {
    const StandingRobot& other = others[k];
    const RobotData& data_other = requireRobot(scene, other.robot);
    if (other.robot == robot) throw std::invalid_argument("collision check: motionClearOf needs other robots");
    requireConfiguration(data_other, other.q, "q of a standing robot");
    requireHeld(scene, other.held);
    state.forward(state.standing[k], data_other, other.q, other.held);
  }
  // motionsFree's samples in its order, except that after a free sample the samples to which
  // the robot's points travel less than its clearance from every standing robot are free as
  // well and are not evaluated: the same answer, most samples skipped. The clearance: the gaps
  // between the robots' bounds, then robotsClearance of those whose bounds overlap (while the
  // clearance so far would still skip a sample, and until one skips too few to pay for itself)
  const double step_travel = scene_->motionTravel(robot, q_from, q_to, held) / n;
  std::vector<char>& known_free = state.known_free;
  known_free.assign(static_cast<std::size_t>(n) + 1, 0);
  auto& slot = state.slots[robot];
  state.q_a.resize(q_from.size());
  bool measure = true;
  for (const int i : state.bisectionOrder(n)) {
    if (known_free[i]) continue;
    state.q_a.noalias() = q_from + (static_cast<double>(i) / n) * (q_to - q_from);
    state.forward(slot, data, state.q_a, held);
    double clearance = std::numeric_limits<double>::infinity();
    for (auto& other : state.standing) {
      if (state.interRobotHit(slot, other)) return false;
      const double gap = boxesGap({slot.lo, slot.hi}, {other.lo, other.hi});
      if (gap > 0.0) clearance = std::min(clearance, gap);
    }
    for (auto& other : state.standing) {
      if (clearance < step_travel + kClearanceSlack) break;  // skips nothing
      if (boxesGap({slot.lo, slot.hi}, {other.lo, other.hi}) > 0.0) continue;
      clearance = measure ? slotsClearance(state, slot, other, clearance) : 0.0;
    }
    // robotsClearance costs more than the checks of the few samples it skips near the others:
    // measured no more in this motion
    if (measure && clearance < kWorthMeasuring * step_travel) measure = false;
    // samples j with |j - i| * step_travel + slack < clearance
    const double reach = std::ceil((clearance - kClearanceSlack) / std::max(step_travel, 1e-12)) - 1.0;
    const int r = static_cast<int>(std::clamp(reach, 0.0, static_cast<double>(n)));
    std::fill(known_free.begin() + std::max(0, i - r), known_free.begin() + std::min(n, i + r) + 1, 1);
  }
  return true;
}

namespace {

void requirePath(const TimedPath& path, const char* name) {
  if (path.t.empty() || path.t.size() != path.q.size()) {
    throw std::invalid_argument(std::string("collision check: ") + name +
                                " needs as many times as configurations, and at least one");
  }
  for (std::size_t i = 0; i < path.t.size(); ++i) {
    if (!std::isfinite(path.t[i]) || (i > 0 && !(path.t[i] > path.t[i - 1]))) {
      throw std::invalid_argument(std::string("collision check: ") + name + " times must increase (at index " +
                                  std::to_string(i) + ")");
    }
  }
}

/// The path's configuration at time t (held before the start and after the end).
Eigen::VectorXd pathAt(const TimedPath& path, double t) {
  if (t <= path.t.front()) return path.q.front();
  if (t >= path.t.back()) return path.q.back();
  const auto upper = std::upper_bound(path.t.begin(), path.t.end(), t);
  const std::size_t i = static_cast<std::size_t>(upper - path.t.begin());
  const double s = (t - path.t[i - 1]) / (path.t[i] - path.t[i - 1]);
  return path.q[i - 1] + s * (path.q[i] - path.q[i - 1]);
}

}  // namespace

bool CollisionChecker::timedPathsFree(int robot_a, const TimedPath& path_a, const std::optional<HeldObject>& held_a,
                                      int robot_b, const TimedPath& path_b,
                                      const std::optional<HeldObject>& held_b) {
  requirePath(path_a, "path_a");
  requirePath(path_b, "path_b");
  std::vector<double> times = path_a.t;
  times.insert(times.end(), path_b.t.begin(), path_b.t.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  if (times.size() == 1) {
    return robotsFree(robot_a, path_a.q.front(), held_a, robot_b, path_b.q.front(), held_b);
  }
  for (std::size_t i = 0; i + 1 < times.size(); ++i) {
    if (!motionsFree(robot_a, pathAt(path_a, times[i]), pathAt(path_a, times[i + 1]), held_a, robot_b,
                     pathAt(path_b, times[i]), pathAt(path_b, times[i + 1]), held_b)) {
      return false;
    }
  }
  return true;
}

}  // namespace dashbed::planner
