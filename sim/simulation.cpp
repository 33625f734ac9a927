#include "sim/simulation.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include <Eigen/Eigenvalues>

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyGearConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "core/kinematics.h"

namespace dashbed::sim {
namespace {

using core::Pose;

// Collision filter bits: static scenery, objects, then one bit per robot so that a robot's
// links never collide with each other (the planner keeps the arm out of self-collision) but
// do collide with other robots.
constexpr int kStaticBit = 1 << 0;
constexpr int kObjectBit = 1 << 1;
constexpr int robotBit(int r) { return 1 << (2 + r); }
static_assert(2 + core::kMaxRobots < 32, "a collision filter bit per robot");
constexpr int kAllBits = -1;

// Collision margin of convex shapes [m]. Bullet's default (4 cm) rounds boxes visibly;
// 1 mm keeps the contact geometry within a millimetre of the true shapes while leaving
// the GJK/EPA pair code a positive margin to work with.
constexpr double kMargin = 0.001;

// Turn rate below which an object counts as at rest for sleeping [rad/s]: a 4 cm cube's corners
// then move at most 1 mm/s, a tenth of the default rest speed.
constexpr double kSleepTurnRate = 0.05;

// Ratio of the finger coupling in Bullet's gear convention (velocity_a + ratio * velocity_b = 0):
// -1 makes the two finger joints move equally (tests/sim checks it).
constexpr double kFingerGearRatio = -1.0;
// Positional correction of the finger coupling per step. Bullet's gear row corrects
// position_a + ratio * position_b (here the difference of the two fingers) towards zero with a
// positive value; without it a difference made while the coupling's impulse limit is reached
// (an object pulled out of a closed hand at a handoff) stays for good, and an open hand then
// comes down on the next cube with one finger millimetres inside the other's side of it.
// Bullet leaves erp * difference below about 0.36 mm uncorrected: 0.8 keeps the fingers within
// half a millimetre of each other (tests/sim checks it).
constexpr double kFingerGearErp = 0.8;

btVector3 toBt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d fromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

btTransform toBt(const Pose& X) {
  const Eigen::Matrix3d& R = X.linear();
  btMatrix3x3 basis(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
  return btTransform(basis, toBt(X.translation()));
}

Pose fromBt(const btTransform& T) {
  Pose X = Pose::Identity();
  const btMatrix3x3& b = T.getBasis();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) X.linear()(r, c) = b[r][c];
  }
  X.translation() = fromBt(T.getOrigin());
  return X;
}

/// A rigid body of the multibody: one movable-joint link (or the root) and the links fixed to it.
struct MergedBody {
  int head_link = -1;                   // model link heading the body
  std::vector<int> links;               // model links merged into it
  double mass = 0.0;
  Pose X_HB = Pose::Identity();         // Bullet body frame (CoM, principal axes) in the head link frame
  Eigen::Vector3d inertia_diag = Eigen::Vector3d::Zero();
};

/// Mass, CoM and principal inertia of the merged links, in the head link frame.
void computeInertia(const core::RobotModel& model, MergedBody& body) {
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  for (int l : body.links) {
    const auto& link = model.links()[l];
    if (link.mass <= 0.0) continue;
    const Pose X_HL = model.fixedTransform(body.head_link, l);
    mass += link.mass;
    com += link.mass * (X_HL * link.X_LCom).translation();
  }
  if (mass <= 0.0) {
    // a massless frame-only body: give it a tiny inertia so Featherstone stays well posed
    body.mass = 1e-3;
    body.inertia_diag = Eigen::Vector3d::Constant(1e-6);
    return;
  }
  com /= mass;
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  for (int l : body.links) {
    const auto& link = model.links()[l];
    if (link.mass <= 0.0) continue;
    const Pose X_HC = model.fixedTransform(body.head_link, l) * link.X_LCom;
    const Eigen::Vector3d d = X_HC.translation() - com;
    // rotate the link's central inertia into the head frame, then shift to the common CoM
    I += X_HC.linear() * link.inertia * X_HC.linear().transpose() +
         link.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
  Eigen::Matrix3d V = eig.eigenvectors();
  if (V.determinant() < 0) V.col(2) = -V.col(2);
  body.mass = mass;
  body.X_HB = Pose::Identity();
  body.X_HB.linear() = V;
  body.X_HB.translation() = com;
  body.inertia_diag = eig.eigenvalues().cwiseMax(1e-7);
}

// The margin of a shape whose smallest half-extent is `half` [m]: kMargin, but at most a
// tenth of it. Bullet keeps a box's outer size and shrinks its core by the margin; a core
// shrunk to nothing (the 2 mm finger pads at 1 mm) yields contact normals in arbitrary
// directions, and those normals, kept by the persistent manifold for the whole grasp, lock
// the fingers against opening.
double marginFor(double half) { return std::min(kMargin, 0.1 * half); }

std::unique_ptr<btBoxShape> boxShape(const Eigen::Vector3d& size) {
  auto box = std::make_unique<btBoxShape>(toBt(size / 2));
  box->setMargin(marginFor(size.minCoeff() / 2));
  return box;
}

std::unique_ptr<btCollisionShape> makeShape(const core::CollisionShape& s) {
  std::unique_ptr<btCollisionShape> shape;
  switch (s.type) {
    case core::ShapeType::kBox:
      return boxShape(s.size);
    case core::ShapeType::kCylinder:
      shape = std::make_unique<btCylinderShapeZ>(btVector3(s.size.x(), s.size.y(), s.size.z() / 2));
      shape->setMargin(marginFor(std::min(s.size.x(), s.size.z() / 2)));
      break;
    case core::ShapeType::kSphere:
      shape = std::make_unique<btSphereShape>(s.size.x());
      shape->setMargin(marginFor(s.size.x()));
      break;
  }
  return shape;
}

}  // namespace

struct Simulation::Impl {
  struct Robot {
    std::unique_ptr<btMultiBody> body;
    std::vector<MergedBody> bodies;             // [0] = base, [k+1] = multibody link k
    std::vector<int> link_to_body;              // model link -> index into bodies
    std::vector<int> q_to_mb_link;              // q index -> multibody link
    std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
    std::vector<std::unique_ptr<btMultiBodyJointMotor>> finger_motors;
    std::vector<int> finger_links;
    std::unique_ptr<btMultiBodyConstraint> gear;
    std::vector<BodyRef> collider_refs;
    std::array<double, 6> arm_torques{};  // the last setArmTorques
  };
  struct Object {
    std::unique_ptr<btRigidBody> body;
    std::unique_ptr<btMotionState> motion_state;
  };

  btDefaultCollisionConfiguration collision_config;
  btCollisionDispatcher dispatcher{&collision_config};
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &collision_config};

  std::vector<std::unique_ptr<btCollisionShape>> shapes;  // owns every shape (children too)
  std::vector<std::unique_ptr<btRigidBody>> statics;
  std::vector<Robot> robots;
  std::vector<Object> objects;
  std::vector<BodyRef> refs;  // indexed by btCollisionObject user index

  int addRef(const BodyRef& ref) {
    refs.push_back(ref);
    return static_cast<int>(refs.size()) - 1;
  }

  btCollisionShape* own(std::unique_ptr<btCollisionShape> shape) {
    shapes.push_back(std::move(shape));
    return shapes.back().get();
  }

  // Bullet keeps a friction-anchored contact point while its friction stays inside the cone
  // (so a static contact does not creep), with its local points fixed but its normal and
  // friction directions stored in world coordinates. A grasped box that turns with the hand
  // would keep the normals of the moment it was grasped: after a quarter turn they point along
  // the pads, and those rows hold the fingers shut when the gripper opens. Turning them with
  // body B keeps them fixed in B's frame, as the points are.
  std::vector<btMatrix3x3> last_basis;  // per collision object (user index), at the last step

  void turnAnchoredContacts() {
    last_basis.resize(refs.size(), btMatrix3x3::getIdentity());
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      const btCollisionObject* b = manifold->getBody1();
      const btMatrix3x3 turn = b->getWorldTransform().getBasis() * last_basis[b->getUserIndex()].transpose();
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        if ((point.m_contactPointFlags & BT_CONTACT_FLAG_FRICTION_ANCHOR) == 0) continue;
        point.m_normalWorldOnB = turn * point.m_normalWorldOnB;
        point.m_lateralFrictionDir1 = turn * point.m_lateralFrictionDir1;
        point.m_lateralFrictionDir2 = turn * point.m_lateralFrictionDir2;
      }
    }
    const btCollisionObjectArray& all = world.getCollisionObjectArray();
    for (int i = 0; i < all.size(); ++i) last_basis[all[i]->getUserIndex()] = all[i]->getWorldTransform().getBasis();
  }

  void configureSolver(const core::PhysicsSettings& physics);
  void addFloor(double friction);
  void addFixtures(const std::vector<core::FixtureSpec>& fixtures, double friction);
  void addObjects(const std::vector<core::ObjectSpec>& specs, double rest_speed);
  void addRobot(int r, const core::PlacedRobot& placed, double pad_friction, double time_step);
  void addMultiBody(Robot& robot, const core::PlacedRobot& placed);
  void addColliders(Robot& robot, int r, const core::RobotModel& model, double pad_friction);
  /// Finger servos, and the gear that keeps the two fingers together.
  void addFingerActuators(Robot& robot, const core::RobotModel& model, double time_step);

};

/// Gravity and the constraint solver's settings.
void Simulation::Impl::configureSolver(const core::PhysicsSettings& physics) {
  world.setGravity(toBt(physics.gravity));
  btContactSolverInfo& info = world.getSolverInfo();
  info.m_numIterations = physics.solver_iterations;
  // stop iterating once the contact impulses have converged (resting scenes converge fast)
  info.m_leastSquaresResidualThreshold = 1e-9;
  info.m_minimumSolverBatchSize = 1;
  // two friction directions per contact hold a grasped box against torsion about the
  // closing axis as well as against gravity
  info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
}

/// The floor at z = 0: a large thin box rather than a plane, whose infinite bounds would pair it
/// with every robot link in the broadphase.
void Simulation::Impl::addFloor(double friction) {
  btCollisionShape* floor = own(boxShape(Eigen::Vector3d(20.0, 20.0, 0.1)));
  auto body = std::make_unique<btRigidBody>(0.0, nullptr, floor);
  body->setWorldTransform(btTransform(btMatrix3x3::getIdentity(), btVector3(0, 0, -0.05)));
  body->setFriction(friction);
  body->setUserIndex(addRef({BodyRef::Kind::kFloor, -1, -1}));
  world.addRigidBody(body.get(), kStaticBit, kAllBits ^ kStaticBit);
  statics.push_back(std::move(body));
}

/// Fixtures: static boxes (one box directly, several as a compound).
void Simulation::Impl::addFixtures(const std::vector<core::FixtureSpec>& fixtures, double friction) {
  for (std::size_t f = 0; f < fixtures.size(); ++f) {
    const core::FixtureSpec& fixture = fixtures[f];
    btCollisionShape* shape = nullptr;
    btTransform X_WS = btTransform::getIdentity();
    if (fixture.boxes.size() == 1) {
      shape = own(boxShape(fixture.boxes[0].size));
      X_WS = toBt(fixture.boxes[0].X_WB);
    } else {
      auto* compound = static_cast<btCompoundShape*>(own(std::make_unique<btCompoundShape>()));
      for (const core::Box& box : fixture.boxes) {
        btCollisionShape* child = own(boxShape(box.size));
        compound->addChildShape(toBt(box.X_WB), child);
      }
      shape = compound;
    }
    auto body = std::make_unique<btRigidBody>(0.0, nullptr, shape);
    body->setWorldTransform(X_WS);
    body->setFriction(friction);
    body->setUserIndex(addRef({BodyRef::Kind::kFixture, static_cast<int>(f), -1}));
    world.addRigidBody(body.get(), kStaticBit, kAllBits ^ kStaticBit);
    statics.push_back(std::move(body));
  }
}

/// Objects: dynamic boxes. One that has stayed slower than the monitor's rest speed (and
/// kSleepTurnRate) for Bullet's deactivation time, 2 s, sleeps: it is neither integrated nor
/// paired with the table until the bounds of something awake overlap its own (Bullet's
/// simulation islands), which wakes it before anything touches it.
void Simulation::Impl::addObjects(const std::vector<core::ObjectSpec>& specs, double rest_speed) {
  for (std::size_t o = 0; o < specs.size(); ++o) {
    const core::ObjectSpec& spec = specs[o];
    btCollisionShape* box = own(boxShape(spec.size));
    btVector3 inertia;
    box->calculateLocalInertia(spec.mass, inertia);
    Object object;
    object.motion_state = std::make_unique<btDefaultMotionState>(toBt(spec.X_WO));
    btRigidBody::btRigidBodyConstructionInfo ci(spec.mass, object.motion_state.get(), box, inertia);
    ci.m_friction = spec.friction;
    ci.m_restitution = 0.0;
    object.body = std::make_unique<btRigidBody>(ci);
    object.body->setSleepingThresholds(rest_speed, kSleepTurnRate);
    // friction anchors keep a static-friction contact from creeping between steps
    object.body->setCollisionFlags(object.body->getCollisionFlags() | btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    object.body->setUserIndex(addRef({BodyRef::Kind::kObject, static_cast<int>(o), -1}));
    world.addRigidBody(object.body.get(), kObjectBit, kAllBits);
    objects.push_back(std::move(object));
  }
}

/// Robot r: its links grouped into rigid bodies, a fixed-base multibody, a collider per body,
/// and the finger servos and gear.
void Simulation::Impl::addRobot(int r, const core::PlacedRobot& placed, double pad_friction, double time_step) {
  const core::RobotModel& model = *placed.model;
  Robot robot;
  // group links into bodies: the root and each movable joint's child head a body
  robot.link_to_body.assign(model.links().size(), -1);
  robot.bodies.emplace_back().head_link = 0;
  robot.q_to_mb_link.assign(model.numPositions(), -1);
  for (std::size_t l = 0; l < model.links().size(); ++l) {
    const int j = model.links()[l].parent_joint;
    if (j < 0) {
      robot.link_to_body[l] = 0;
    } else if (model.joints()[j].type == core::JointType::kFixed) {
      robot.link_to_body[l] = robot.link_to_body[model.joints()[j].parent_link];
    } else {
      robot.q_to_mb_link[model.joints()[j].q_index] = static_cast<int>(robot.bodies.size()) - 1;
      robot.link_to_body[l] = static_cast<int>(robot.bodies.size());
      robot.bodies.emplace_back().head_link = static_cast<int>(l);
    }
    robot.bodies[robot.link_to_body[l]].links.push_back(static_cast<int>(l));
  }
  for (MergedBody& body : robot.bodies) computeInertia(model, body);
  addMultiBody(robot, placed);
  addColliders(robot, r, model, pad_friction);
  addFingerActuators(robot, model, time_step);
  robots.push_back(std::move(robot));
}

/// The multibody of a robot whose links are grouped into `robot.bodies`: one Bullet link per
/// movable joint, at the placed base.
void Simulation::Impl::addMultiBody(Robot& robot, const core::PlacedRobot& placed) {
  const core::RobotModel& model = *placed.model;
  const int num_links = static_cast<int>(robot.bodies.size()) - 1;
  const MergedBody& base = robot.bodies[0];
  robot.body = std::make_unique<btMultiBody>(num_links, base.mass, toBt(base.inertia_diag), /*fixedBase=*/true,
                                             /*canSleep=*/false);
  robot.body->setBaseWorldTransform(toBt(placed.spec->X_WBase * base.X_HB));
  for (int k = 0; k < num_links; ++k) {
    const MergedBody& child = robot.bodies[k + 1];
    const int joint_index = model.links()[child.head_link].parent_joint;
    const core::JointModel& joint = model.joints()[joint_index];
    const int parent_body = robot.link_to_body[joint.parent_link];
    const MergedBody& parent = robot.bodies[parent_body];
    // joint frame in the parent's and in the child's Bullet body frame (at q = 0 the joint
    // frame is the child link frame)
    const Pose X_BpJ = parent.X_HB.inverse() * model.fixedTransform(parent.head_link, joint.parent_link) * joint.X_PJ;
    const Pose X_BcJ = child.X_HB.inverse();
    const btQuaternion rot_parent_to_this =
        toBt(X_BcJ).getRotation() * toBt(X_BpJ).getRotation().inverse();
    const btVector3 axis = toBt(Eigen::Vector3d(X_BcJ.linear() * joint.axis));
    const btVector3 pivot_in_parent = toBt(X_BpJ.translation());
    const btVector3 pivot_to_com = toBt(Eigen::Vector3d(-X_BcJ.translation()));
    if (joint.type == core::JointType::kRevolute) {
      robot.body->setupRevolute(k, child.mass, toBt(child.inertia_diag), parent_body - 1, rot_parent_to_this, axis,
                                pivot_in_parent, pivot_to_com, true);
    } else {
      robot.body->setupPrismatic(k, child.mass, toBt(child.inertia_diag), parent_body - 1, rot_parent_to_this, axis,
                                 pivot_in_parent, pivot_to_com, true);
    }
    // no artificial damping or friction in the joints (UR's ROS 2 description has none)
    robot.body->getLink(k).m_jointDamping = 0.0;
    robot.body->getLink(k).m_jointFriction = 0.0;
  }
  robot.body->finalizeMultiDof();
  robot.body->setLinearDamping(0.0);
  robot.body->setAngularDamping(0.0);
  robot.body->setUseGyroTerm(true);
  robot.body->setHasSelfCollision(false);
  world.addMultiBody(robot.body.get());
}

/// Colliders: one compound per body, the pads' bodies with the pad friction.
void Simulation::Impl::addColliders(Robot& robot, int r, const core::RobotModel& model, double pad_friction) {
  // colliders: one compound per body
  for (std::size_t b = 0; b < robot.bodies.size(); ++b) {
    const MergedBody& body = robot.bodies[b];
    auto* compound = static_cast<btCompoundShape*>(own(std::make_unique<btCompoundShape>()));
    bool finger = false;
    for (int l : body.links) {
      for (const core::CollisionShape& cs : model.links()[l].collisions) {
        finger = finger || cs.name == "pad";
        const Pose X_BS = body.X_HB.inverse() * model.fixedTransform(body.head_link, l) * cs.X_LS;
        compound->addChildShape(toBt(X_BS), own(makeShape(cs)));
      }
    }
    if (compound->getNumChildShapes() == 0) continue;
    const int mb_link = static_cast<int>(b) - 1;
    auto collider = std::make_unique<btMultiBodyLinkCollider>(robot.body.get(), mb_link);
    collider->setCollisionShape(compound);
    // finger bodies carry the rubber pads: their friction is the pad friction
    collider->setFriction(finger ? pad_friction : 0.5);
    if (finger) collider->setCollisionFlags(collider->getCollisionFlags() | btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    collider->setUserIndex(addRef({BodyRef::Kind::kRobot, r, body.head_link}));
    // the base stands on its table: it is fixed, so its contacts with the scenery mean nothing
    const int mask = (mb_link < 0 ? (kAllBits ^ kStaticBit) : kAllBits) ^ robotBit(r);
    world.addCollisionObject(collider.get(), robotBit(r), mask);
    if (mb_link < 0) {
      robot.body->setBaseCollider(collider.get());
    } else {
      robot.body->getLink(mb_link).m_collider = collider.get();
    }
    robot.colliders.push_back(std::move(collider));
  }
}

void Simulation::Impl::addFingerActuators(Robot& robot, const core::RobotModel& model, double time_step) {
  // The joints get no limit constraints: the Hand-E controller stops the
  // fingers at the ends of their stroke, plans are validated against the arm limits before
  // they run and the tracking check reports deviations — and every constraint row costs an
  // articulated-body solve in each solver iteration.
  for (int qi = 0; qi < model.numPositions(); ++qi) {
    const core::JointModel& joint = model.joints()[model.movableJoints()[qi]];
    if (joint.type != core::JointType::kPrismatic) continue;
    const int mb_link = robot.q_to_mb_link[qi];
    auto motor = std::make_unique<btMultiBodyJointMotor>(robot.body.get(), mb_link, 0.0, 0.0);
    world.addMultiBodyConstraint(motor.get());
    robot.finger_motors.push_back(std::move(motor));
    robot.finger_links.push_back(mb_link);
  }
  // the Hand-E's fingers are driven by one actuator through a rack, so they always move
  // together: a gear constraint keeps the two finger joints equal (it transmits force
  // between the fingers only, it touches no object)
  if (robot.finger_links.size() == 2) {
    auto gear = std::make_unique<btMultiBodyGearConstraint>(
        robot.body.get(), robot.finger_links[0], robot.body.get(), robot.finger_links[1], btVector3(0, 0, 0),
        btVector3(0, 0, 0), btMatrix3x3::getIdentity(), btMatrix3x3::getIdentity());
    gear->setGearRatio(kFingerGearRatio);
    gear->setErp(kFingerGearErp);
    gear->setMaxAppliedImpulse(2.0 * controllers::kHandeMaxForce * time_step);
    world.addMultiBodyConstraint(gear.get());
    robot.gear = std::move(gear);
  }
}

Simulation::Simulation(const core::World& world, const core::RobotSet& robots)
    : world_(world), robots_(robots), time_step_(world.physics.time_step), impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.configureSolver(world.physics);
  s.addFloor(world.physics.fixture_friction);
  s.addFixtures(world.fixtures, world.physics.fixture_friction);
  s.addObjects(world.objects, world.checks.rest_speed);
  for (std::size_t r = 0; r < robots.size(); ++r) {
    s.addRobot(static_cast<int>(r), robots[r], world.physics.pad_friction, time_step_);
    const core::RobotModel& model = *robots[r].model;
    Eigen::VectorXd q = Eigen::VectorXd::Zero(model.numPositions());
    for (int i = 0; i < 6; ++i) q[i] = robots[r].spec->home[i];
    for (int i = 6; i < model.numPositions(); ++i) q[i] = model.joints()[model.movableJoints()[i]].upper;
    setJointPositions(static_cast<int>(r), q);
    setFingerServo(static_cast<int>(r), {0.0, 0.0});
  }
}

Simulation::~Simulation() {
  Impl& s = *impl_;
  // remove in reverse order of creation before the owners are destroyed
  for (auto& robot : s.robots) {
    for (auto& motor : robot.finger_motors) s.world.removeMultiBodyConstraint(motor.get());
    if (robot.gear) s.world.removeMultiBodyConstraint(robot.gear.get());
    for (auto& collider : robot.colliders) s.world.removeCollisionObject(collider.get());
    s.world.removeMultiBody(robot.body.get());
  }
  for (auto& object : s.objects) s.world.removeRigidBody(object.body.get());
  for (auto& body : s.statics) s.world.removeRigidBody(body.get());
}

void Simulation::step() {
  impl_->turnAnchoredContacts();
  impl_->world.stepSimulation(time_step_, 0, time_step_);
  time_ = static_cast<double>(++steps_) * time_step_;
}

Eigen::VectorXd Simulation::jointPositions(int r) const {
  const auto& robot = impl_->robots.at(r);
  Eigen::VectorXd q(robot.q_to_mb_link.size());
  for (std::size_t i = 0; i < robot.q_to_mb_link.size(); ++i) q[i] = robot.body->getJointPos(robot.q_to_mb_link[i]);
  return q;
}

Eigen::VectorXd Simulation::jointVelocities(int r) const {
  const auto& robot = impl_->robots.at(r);
  Eigen::VectorXd qd(robot.q_to_mb_link.size());
  for (std::size_t i = 0; i < robot.q_to_mb_link.size(); ++i) qd[i] = robot.body->getJointVel(robot.q_to_mb_link[i]);
  return qd;
}

void Simulation::setJointPositions(int r, const Eigen::VectorXd& q) {
  auto& robot = impl_->robots.at(r);
  for (std::size_t i = 0; i < robot.q_to_mb_link.size(); ++i) {
    robot.body->setJointPos(robot.q_to_mb_link[i], q[static_cast<Eigen::Index>(i)]);
    robot.body->setJointVel(robot.q_to_mb_link[i], 0.0);
  }
  // refresh the cached link transforms and the colliders so the broadphase sees the new configuration
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  robot.body->forwardKinematics(scratch_q, scratch_m);
  robot.body->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);
}

void Simulation::setArmTorques(int r, const std::array<double, 6>& tau) {
  auto& robot = impl_->robots.at(r);
  for (int i = 0; i < 6; ++i) robot.body->addJointTorque(robot.q_to_mb_link[i], tau[i]);
  robot.arm_torques = tau;
}

const std::array<double, 6>& Simulation::armTorques(int r) const { return impl_->robots.at(r).arm_torques; }

void Simulation::setFingerServo(int r, const controllers::FingerServo& servo) {
  for (auto& motor : impl_->robots.at(r).finger_motors) {
    motor->setVelocityTarget(servo.velocity);
    motor->setMaxAppliedImpulse(servo.max_force * time_step_);
  }
}

Pose Simulation::linkPose(int r, int link) const {
  const core::PlacedRobot& placed = robots_[r];
  return placed.spec->X_WBase * core::linkPoses(*placed.model, jointPositions(r))[link];
}

Pose Simulation::linkPoseFromPhysics(int r, int link) const {
  const auto& robot = impl_->robots.at(r);
  const MergedBody& body = robot.bodies.at(robot.link_to_body.at(link));
  const int mb_link = robot.link_to_body[link] - 1;
  const btTransform X_WB = mb_link < 0 ? robot.body->getBaseWorldTransform()
                                       : robot.body->getLink(mb_link).m_cachedWorldTransform;
  return fromBt(X_WB) * body.X_HB.inverse() * robots_[r].model->fixedTransform(body.head_link, link);
}

Pose Simulation::objectPose(int o) const { return fromBt(impl_->objects.at(o).body->getWorldTransform()); }

Eigen::Vector3d Simulation::objectLinearVelocity(int o) const {
  return fromBt(impl_->objects.at(o).body->getLinearVelocity());
}

Eigen::Vector3d Simulation::objectAngularVelocity(int o) const {
  return fromBt(impl_->objects.at(o).body->getAngularVelocity());
}

void Simulation::setObjectPose(int o, const Pose& X_WO) {
  btRigidBody& body = *impl_->objects.at(o).body;
  body.setWorldTransform(toBt(X_WO));
  body.getMotionState()->setWorldTransform(toBt(X_WO));
  body.setLinearVelocity(btVector3(0, 0, 0));
  body.setAngularVelocity(btVector3(0, 0, 0));
  body.clearForces();
}

void Simulation::detectContacts() { impl_->world.performDiscreteCollisionDetection(); }

std::vector<Contact> Simulation::contacts() const {
  constexpr double kTouching = 0.001;  // [m] points closer than this count as touching
  std::vector<Contact> out;
  btDispatcher& dispatcher = impl_->dispatcher;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    Contact contact;
    bool touching = false;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() > kTouching) continue;
      if (!touching || point.getDistance() < contact.min_distance) {
        contact.min_distance = point.getDistance();
        contact.point_W = fromBt(point.getPositionWorldOnB());
      }
      touching = true;
      contact.normal_force += point.getAppliedImpulse() / time_step_;
    }
    if (!touching) continue;
    contact.a = impl_->refs.at(manifold->getBody0()->getUserIndex());
    contact.b = impl_->refs.at(manifold->getBody1()->getUserIndex());
    // order each pair and the list so reports do not depend on manifold order
    const auto key = [](const BodyRef& ref) { return std::tuple(static_cast<int>(ref.kind), ref.index, ref.link); };
    if (key(contact.b) < key(contact.a)) std::swap(contact.a, contact.b);
    out.push_back(contact);
  }
  std::sort(out.begin(), out.end(), [](const Contact& x, const Contact& y) {
    const auto key = [](const BodyRef& ref) { return std::tuple(static_cast<int>(ref.kind), ref.index, ref.link); };
    return std::tuple_cat(key(x.a), key(x.b)) < std::tuple_cat(key(y.a), key(y.b));
  });
  return out;
}

}  // namespace dashbed::sim
