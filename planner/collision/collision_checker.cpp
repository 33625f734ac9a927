// CollisionChecker (collision_checker.h): the queries on a CollisionScene.
#include "planner/collision/collision_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "planner/collision/internal/collision_checker_state.h"
#include "planner/collision/internal/collision_scene_data.h"
#include "planner/collision/internal/collision_sweep.h"

namespace dashbed::planner {

using core::ShapeType;
using detail::Body;
using detail::RobotData;
using detail::Shape;
using detail::requireConfiguration;
using detail::requireHeld;
using detail::requireObjects;
using detail::requireRobot;
using Eigen::Vector3d;

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

bool CollisionChecker::heldObjectFree(int robot, int object, const core::Pose& X_WO) {
  const detail::SceneData& scene = *scene_->data_;
  requireRobot(scene, robot);
  requireHeld(scene, HeldObject{object});
  const detail::ObjectData& data = scene.objects[object];
  const detail::Frame X_W(X_WO);
  return state_->heldStaticBox(robot, {ShapeType::kBox, data.box_grown.get(), &X_W, &data.half_grown, data.radius_grown}) < 0;
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
// [m] capsules farther apart than this hold shapes that are apart (a margin for rounding)
constexpr double kCapsulesApart = 1e-6;
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
  placePair(robot_a, q_a, held_a, robot_b, q_b, held_b);
  auto& slot_a = state_->slots[robot_a];
  auto& slot_b = state_->slots[robot_b];
  // the capsules hold the shapes: robots whose capsules keep apart are free, only the others
  // are checked shape against shape
  const double clearance = slotsClearance(*state_, slot_a, slot_b, std::numeric_limits<double>::infinity());
  if (clearance > kCapsulesApart) return clearance;
  return state_->interRobotHit(slot_a, slot_b) ? -1.0 : clearance;
}

std::pair<int, double> CollisionChecker::motionSamples(int robot, const detail::MotionRef& motion,
                                                      const std::optional<HeldObject>& held) const {
  const double peak = motion.peakOverMean();
  if (!(peak >= 1.0) || !std::isfinite(peak)) {
    throw std::invalid_argument("collision check: a curve's peak_over_mean must be finite and at least 1");
  }
  if (motion.curve != nullptr && !motion.curve->at) throw std::invalid_argument("collision check: a curve needs at(s, q)");
  // validates the ends and the held object
  const double travel = peak * scene_->motionTravel(robot, motion.from, motion.to, held);
  const int n = detail::stepsFor(travel, scene_->settings().motion_step);
  return {n, travel / n};
}

bool CollisionChecker::motionFree(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                  std::span<const RestingObject> objects, const std::optional<HeldObject>& held) {
  return motionFree(robot, detail::MotionRef{q_from, q_to}, objects, held);
}

bool CollisionChecker::motionFree(int robot, const CurvePiece& piece, std::span<const RestingObject> objects,
                                  const std::optional<HeldObject>& held) {
  return motionFree(robot, detail::MotionRef{piece.from, piece.to, &piece}, objects, held);
}

bool CollisionChecker::motionFree(int robot, const detail::MotionRef& motion, std::span<const RestingObject> objects,
                                  const std::optional<HeldObject>& held) {
  const std::optional<std::vector<char>> hits = motionHits(robot, motion, objects, held, {true, true});
  return hits && std::none_of(hits->begin(), hits->end(), [](char hit) { return hit != 0; });
}

std::vector<char> CollisionChecker::motionObjectHits(int robot, const Eigen::VectorXd& q_from,
                                                     const Eigen::VectorXd& q_to,
                                                     std::span<const RestingObject> objects,
                                                     const std::optional<HeldObject>& held) {
  return *motionHits(robot, detail::MotionRef{q_from, q_to}, objects, held, {false, false});
}

std::vector<char> CollisionChecker::motionObjectHits(int robot, const CurvePiece& piece,
                                                     std::span<const RestingObject> objects,
                                                     const std::optional<HeldObject>& held) {
  return *motionHits(robot, detail::MotionRef{piece.from, piece.to, &piece}, objects, held, {false, false});
}

std::optional<std::vector<char>> CollisionChecker::motionCheck(int robot, const Eigen::VectorXd& q_from,
                                                               const Eigen::VectorXd& q_to,
                                                               std::span<const RestingObject> objects,
                                                               const std::optional<HeldObject>& held) {
  return motionHits(robot, detail::MotionRef{q_from, q_to}, objects, held, {true, false});
}

std::optional<std::vector<char>> CollisionChecker::motionHits(int robot, const detail::MotionRef& motion,
                                                              std::span<const RestingObject> objects,
                                                              const std::optional<HeldObject>& held,
                                                              const detail::SweepRequest& request) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  const auto [n, step_travel] = motionSamples(robot, motion, held);
  requireObjects(scene, objects);
  return detail::sweepMotion(*state_, data, motion, held, n, step_travel, objects, request);
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
  return !state.sweep(slot_a, a, detail::MotionRef{q_a_from, q_a_to}, held_a, n, [&](double s) {
    state.q_b.noalias() = q_b_from + s * (q_b_to - q_b_from);
    state.forward(slot_b, b, state.q_b, held_b);
    return state.interRobotHit(slot_a, slot_b).has_value();
  });
}

bool CollisionChecker::motionClearOf(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                     const std::optional<HeldObject>& held,
                                     std::span<const StandingRobot> others) {
  return motionClearOf(robot, detail::MotionRef{q_from, q_to}, held, others);
}

bool CollisionChecker::motionClearOf(int robot, const CurvePiece& piece, const std::optional<HeldObject>& held,
                                     std::span<const StandingRobot> others) {
  return motionClearOf(robot, detail::MotionRef{piece.from, piece.to, &piece}, held, others);
}

bool CollisionChecker::motionClearOf(int robot, const detail::MotionRef& motion, const std::optional<HeldObject>& held,
                                     std::span<const StandingRobot> others) {
  const detail::SceneData& scene = *scene_->data_;
  const RobotData& data = requireRobot(scene, robot);
  // a standing robot takes one step: motionsFree would check this many samples (a curve's
  // samples are motionFree's)
  const auto [n, step_travel] = motionSamples(robot, motion, held);
  auto& state = *state_;
  state.standing.resize(others.size());
  for (std::size_t k = 0; k < others.size(); ++k) {
    const StandingRobot& other = others[k];
    const RobotData& data_other = requireRobot(scene, other.robot);
    if (other.robot == robot) throw std::invalid_argument("collision check: motionClearOf needs other robots");
    requireConfiguration(data_other, other.q, "q of a standing robot");
    requireHeld(scene, other.held);
    state.forward(state.standing[k], data_other, other.q, other.held);
    detail::CheckerState::updateBounds(state.standing[k], other.held ? &scene.objects[other.held->object] : nullptr);
  }
  // motionsFree's samples in its order, except that after a free sample the samples to which
  // the robot's points travel less than its clearance from every standing robot are free as
  // well and are not evaluated: the same answer, most samples skipped. The clearance: the gaps
  // between the robots' bounds, then robotsClearance of those whose bounds overlap (while the
  // clearance so far would still skip a sample, and until one skips too few to pay for itself).
  // The bounds and the capsules hold the shapes: a standing robot whose bounds or capsules keep
  // apart is free, only the others are checked shape against shape.
  std::vector<char>& known_free = state.known_free;
  known_free.assign(static_cast<std::size_t>(n) + 1, 0);
  auto& slot = state.slots[robot];
  const detail::ObjectData* held_data = held ? &scene.objects[held->object] : nullptr;
  bool measure = true;
  for (const int i : state.bisectionOrder(n)) {
    if (known_free[i]) continue;
    motion.at(static_cast<double>(i) / n, state.q_a);
    state.forward(slot, data, state.q_a, held);
    detail::CheckerState::updateBounds(slot, held_data);
    double clearance = std::numeric_limits<double>::infinity();
    for (const auto& other : state.standing) {
      const double gap = boxesGap({slot.lo, slot.hi}, {other.lo, other.hi});
      if (gap > 0.0) clearance = std::min(clearance, gap);
    }
    for (auto& other : state.standing) {
      if (boxesGap({slot.lo, slot.hi}, {other.lo, other.hi}) > 0.0) continue;
      if (clearance >= step_travel + kClearanceSlack) {  // a clearance would still skip samples
        clearance = measure ? slotsClearance(state, slot, other, clearance) : 0.0;
        if (clearance > kCapsulesApart) continue;
      }
      if (state.interRobotHit(slot, other)) return false;
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

