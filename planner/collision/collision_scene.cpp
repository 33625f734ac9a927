// CollisionScene (collision_checker.h): the robots' bodies and shapes from their models, the
// static boxes with each robot's pedestal, the object boxes, the self-collision pairs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "planner/collision/collision_checker.h"
#include "planner/collision/internal/collision_checker_state.h"
#include "planner/collision/internal/collision_scene_data.h"

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

namespace {

using core::Pose;
using core::ShapeType;
using Eigen::Vector3d;
using detail::Body;
using detail::RobotData;
using detail::Shape;

// The floor: a large thin box whose top face is the plane z = 0.
constexpr double kFloorExtent = 100.0;
constexpr double kFloorThickness = 0.1;

int unitAxisId(const Vector3d& axis) {
  for (int i = 0; i < 3; ++i) {
    if (axis == Vector3d::Unit(i)) return i;
  }
  return -1;
}

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
      body.axis_id = unitAxisId(joint.axis);
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

}  // namespace

namespace detail {

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

}  // namespace detail

using detail::requireRobot;
using detail::requireConfiguration;
using detail::requireHeld;

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
  floor.X_WB.translation() = Vector3d(0.0, 0.0, -kFloorThickness / 2.0);
  floor.size = Vector3d(kFloorExtent, kFloorExtent, kFloorThickness);
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
  return detail::stepsFor(motionTravel(robot, q_from, q_to, held), data_->settings.motion_step);
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

}  // namespace dashbed::planner
