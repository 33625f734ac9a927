#pragma once
// Simulation: one Bullet (double precision) multibody world holding the robots, fixtures and
// objects of a World. Each Simulation owns everything it uses; nothing is static, so many
// simulations run side by side in threads.
//
// Robots are btMultiBody trees built from the RobotModel (links joined by fixed joints are
// merged into one body); the six arm joints take torques (setArmTorques) and the two finger
// joints are force-limited velocity servos (setFingerServo). Objects are free rigid boxes,
// held by a gripper only through contact friction.

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "controllers/hande_controller.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::sim {

/// What a collision body is.
struct BodyRef {
  enum class Kind { kFloor, kFixture, kObject, kRobot };
  Kind kind = Kind::kFloor;
  int index = -1;  ///< fixture, object or robot index in the World
  int link = -1;   ///< robots: the model link heading the body (e.g. the finger link)
  bool operator==(const BodyRef&) const = default;
};

/// A touching pair of bodies after the last step.
struct Contact {
  BodyRef a;
  BodyRef b;
  double normal_force = 0.0;   ///< [N] summed over the contact points of the pair
  double min_distance = 0.0;   ///< [m] most negative = deepest penetration
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();  ///< a contact point (world)
};

class Simulation {
 public:
  /// Builds the scene; robots at their home configuration with open grippers, objects at
  /// their start poses. `world` and `robots` must outlive the simulation.
  Simulation(const core::World& world, const core::RobotSet& robots);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Advances by one fixed time step (world physics.time_step).
  void step();
  double time() const { return time_; }
  double timeStep() const { return time_step_; }

  const core::World& world() const { return world_; }
  const core::RobotSet& robots() const { return robots_; }

  /// All joint positions / velocities of robot r in its model's q order (arm, then fingers).
  Eigen::VectorXd jointPositions(int r) const;
  Eigen::VectorXd jointVelocities(int r) const;
  /// Teleports robot r to configuration q (all joints) at rest. For setting up scenes only.
  void setJointPositions(int r, const Eigen::VectorXd& q);

  /// Torques [Nm] on the six arm joints for the next step (the caller clamps them).
  void setArmTorques(int r, const std::array<double, 6>& tau);
  /// The arm torques last set [Nm] (zero before any).
  const std::array<double, 6>& armTorques(int r) const;
  /// Servo command applied to both finger joints of robot r from the next step on.
  void setFingerServo(int r, const controllers::FingerServo& servo);

  /// Pose of a model link of robot r in the world (from the simulated joint positions).
  core::Pose linkPose(int r, int link) const;
  /// The same pose read from Bullet's own body transforms (independent of core::linkPoses;
  /// tests use it to cross-check the two kinematic models).
  core::Pose linkPoseFromPhysics(int r, int link) const;

  core::Pose objectPose(int o) const;
  Eigen::Vector3d objectLinearVelocity(int o) const;
  Eigen::Vector3d objectAngularVelocity(int o) const;
  /// Moves object o (at rest) to a new pose, e.g. a perturbed start.
  void setObjectPose(int o, const core::Pose& X_WO);

  /// Touching pairs after the last step (distance below 1 mm), in a deterministic order.
  std::vector<Contact> contacts() const;
  /// Runs collision detection alone, without a step: contacts() then reports the scene as set
  /// by setJointPositions and setObjectPose (for checking a plan's geometry; no forces).
  void detectContacts();

 private:
  struct Impl;
  const core::World& world_;
  const core::RobotSet& robots_;
  double time_step_;
  std::int64_t steps_ = 0;  ///< steps taken: time_ is steps_ * time_step_, without a sum's drift
  double time_ = 0.0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dashbed::sim
