#pragma once
// PlanExecutor: drives a Simulation through a plan — every step it samples each robot's
// reference trajectory, runs the arm's PD and the Hand-E controller, applies their outputs
// and advances the physics. Robots without a trajectory hold their home configuration.

#include <memory>
#include <optional>
#include <vector>

#include "controllers/collision_detection.h"
#include "controllers/hande_controller.h"
#include "controllers/joint_pd.h"
#include "core/trajectory_interpolator.h"
#include "core/plan.h"
#include "sim/simulation.h"

namespace dashbed::sim {

/// Per-robot tracking statistics accumulated while executing.
struct TrackingStats {
  double max_tracking_error = 0.0;  ///< [rad] max over the arm joints and steps
  long saturated_steps = 0;         ///< steps with some arm joint at its effort limit
  long steps = 0;
  double max_effort_ratio = 0.0;
};

/// A protective stop: robot `robot`'s collision detection tripped at plan time `t`.
struct ProtectiveStop {
  int robot = -1;
  double t = 0.0;                        ///< [s] plan time
  controllers::ProtectiveStopTrip trip;  ///< what crossed which limit
  Eigen::Vector3d tcp_W = Eigen::Vector3d::Zero();  ///< the TCP then (world)
};

class PlanExecutor {
 public:
  /// `plan` must refer to robots of the simulation's world (validatePlan); both must outlive
  /// the executor. Plan time 0 is simulation time `plan_time_offset` (a settle pre-roll during
  /// which the robots hold their first points). Throws std::invalid_argument for a robot name
  /// the world lacks.
  PlanExecutor(Simulation& sim, const core::Plan& plan, double plan_time_offset = 0.0);

  /// Plan time now [s].
  double planTime() const;
  ~PlanExecutor();

  /// Applies the controls for the current time and advances one time step. Each arm
  /// controller is told its payload, as a UR controller is with set_payload: when its gripper
  /// closes on the object of a pick or of a handoff it receives (per the plan's actions), the
  /// object's mass and inertia (world file) where the object sits in the gripper then; in a
  /// handoff the receiver takes it over when the giver opens. Opening drops it.
  /// Before the step each arm joint's distance from its reference is held to
  /// checks.tracking_error_limit (a UR stops when its position deviates from the path); after
  /// it each arm's collision detection judges the external load. The first trip is a
  /// protective stop of the cell: from then on every robot holds the configuration it has and
  /// no gripper command is carried out.
  void step();

  /// The cell's protective stop, once one happened.
  const std::optional<ProtectiveStop>& protectiveStop() const { return stop_; }

  /// The arm reference of robot r at the current time.
  core::JointReference reference(int r) const;
  const controllers::HandeController& gripper(int r) const { return grippers_[r]; }
  const TrackingStats& tracking(int r) const { return stats_[r]; }
  /// Robot r's collision detection (its largest estimates so far).
  const controllers::CollisionDetector& collisionDetection(int r) const { return detectors_[r]; }
  /// The payload robot r's arm controller compensates now (see step), if any.
  const std::optional<core::Payload>& payload(int r) const { return payloads_[r]; }

 private:
  Simulation& sim_;
  double offset_;
  double deviation_limit_;  // [rad] path deviation that stops the cell (world checks.tracking_error_limit)
  std::vector<std::optional<core::TrajectoryInterpolator>> trajectories_;  // per robot
  std::vector<core::JointReference> holds_;  // per robot, used without a trajectory
  std::vector<std::unique_ptr<controllers::JointPdController>> arm_controllers_;
  std::vector<controllers::HandeController> grippers_;
  std::vector<core::GripperCommand> gripper_commands_;  // sorted by time
  std::size_t next_command_ = 0;
  std::vector<TrackingStats> stats_;
  std::vector<int> tcp_;                               // per robot, model link
  std::vector<int> gripping_;                          // per robot: object closed on (its payload), or -1
  std::vector<std::optional<core::Payload>> payloads_;  // per robot
  std::vector<controllers::CollisionDetector> detectors_;  // per robot
  std::optional<ProtectiveStop> stop_;

  /// The object robot r closes on at plan time t: that of its pick, or of a handoff it
  /// receives, under way at t; -1 for none.
  int objectClosedOn(int r, double t) const;
  /// Robot r's payload: object o as it sits in r's gripper now.
  core::Payload payloadOf(int r, int o) const;
  /// Stops the cell: every robot holds where it is from the next step on.
  void stopCell(int r, const controllers::ProtectiveStopTrip& trip);
  const core::Plan& plan_;
};

}  // namespace dashbed::sim
