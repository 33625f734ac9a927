#pragma once
// The scratch state of collision queries (CollisionChecker, collision_checker.h), internal to
// the planner: a robot's body poses by forward kinematics, its shapes placed lazily, and the
// checks of one configuration (against the static scene, itself, resting objects, another
// robot) and of motions (straight or curved). One per checker, and one while a scene is built.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "planner/collision/internal/collision_scene_data.h"
#include "planner/collision/internal/collision_shape_tests.h"

namespace dashbed::planner::detail {

using AabbNode = fcl::detail::NodeBase<fcl::AABBd>;

// 1/n! for n = 0..18 (n! is exact in a double up to 18!)
inline constexpr std::array<double, 19> kInverseFactorial = [] {
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
inline void sinCos(double angle, double& sine, double& cosine) {
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
inline void rotateAboutAxis(Frame& X, const Body& body, double angle) {
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

/// A colliding pair a check found: a body of the robot checked (kHeldBody: the object it holds)
/// and the part it hits: a static box, or a body of the same or another robot (or kHeldBody).
struct Hit {
  int body = -1;
  int other = -1;
};
inline constexpr int kHeldBody = -2;

/// A motion being checked: the straight joint-space line from -> to, or a curve between them.
struct MotionRef {
  const Eigen::VectorXd& from;
  const Eigen::VectorXd& to;
  const CurvePiece* curve = nullptr;

  /// The configuration at s in [0, 1].
  void at(double s, Eigen::VectorXd& q) const {
    if (curve != nullptr) {
      curve->at(s, q);
      if (q.size() != from.size()) throw std::invalid_argument("collision check: a curve's at(s, q) gave a q of the wrong size");
      return;
    }
    q.resize(from.size());
    q.noalias() = from + s * (to - from);
  }
  /// Bound on any position's rate in s over its mean rate.
  double peakOverMean() const { return curve != nullptr ? curve->peak_over_mean : 1.0; }
};

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
      box = heldStaticBox(self, placedHeld(slot));
      if (box >= 0) return Hit{kHeldBody, box};
    }
    return std::nullopt;
  }

  /// The first static box (not one of robot `self`'s own) the held object `held` hits, or -1.
  int heldStaticBox(int self, const Placed& held) {
    const StaticData& statics = scene->statics;
    int box = -1;
    forStaticNear(held.X_W->p, held.radius, [&](int k) {
      if (statics.owner[k] == self || !shapesCollide(held, placedStatic(k))) return false;
      box = k;
      return true;
    });
    return box;
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

  /// Places `robot` in `slot` at the n + 1 samples of `motion`, in bisection order, calling
  /// visit(s) (s in [0, 1] along the motion) after each; stops when visit returns true. True
  /// when stopped.
  template <class Visit>
  bool sweep(Slot& slot, const RobotData& robot, const MotionRef& motion, const std::optional<HeldObject>& held,
             int n, Visit&& visit) {
    for (const int i : bisectionOrder(n)) {
      const double s = static_cast<double>(i) / n;
      motion.at(s, q_a);
      forward(slot, robot, q_a, held);
      if (visit(s)) return true;
    }
    return false;
  }
};

}  // namespace dashbed::planner::detail
