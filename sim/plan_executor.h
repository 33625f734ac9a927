#pragma once
// PlanExecutor: drives a Simulation through a plan — every step it samples each robot's
// reference trajectory, runs the arm's PD and the Hand-E controller, applies their outputs
// and advances the physics. Robots without a trajectory hold their home configuration.

#include <memory>
#include <optional>
#include <vector>

#include "controllers/hande_controller.h"
#include "controllers/joint_pd.h"
#include "core/trajectory_interpolator.h"
#include "core/plan.h"
#include "sim/simulation.h"

namespace dashbed::sim {

/// Per-robot tracking statistics accumulated while executing.
struct TrackingStats {
  double max_tracking_error = 0.0;  ///< [rad] max over the arm joints and steps
  int max_error_joint = -1;         ///< arm joint (0..5) of the max error
  double max_error_time = 0.0;      ///< [s] plan time of the max error
  long saturated_steps = 0;         ///< steps with some arm joint at its effort limit
  long steps = 0;
  double max_effort_ratio = 0.0;
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
  void step();

  /// The arm reference of robot r at the current time.
  core::JointReference reference(int r) const;
  const controllers::HandeController& gripper(int r) const { return grippers_[r]; }
  const TrackingStats& tracking(int r) const { return stats_[r]; }
  /// The payload robot r's arm controller compensates now (see step), if any.
  const std::optional<core::Payload>& payload(int r) const { return payloads_[r]; }

 private:
  Simulation& sim_;
  double offset_;
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

  /// The object robot r closes on at plan time t: that of its pick, or of a handoff it
  /// receives, under way at t; -1 for none.
  int objectClosedOn(int r, double t) const;
  /// Robot r's payload: object o as it sits in r's gripper now.
  core::Payload payloadOf(int r, int o) const;
  const core::Plan& plan_;
};

}  // namespace dashbed::sim
