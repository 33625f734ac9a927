#pragma once
// PlanExecutor: drives a Simulation through a plan — every step it samples each robot's
// reference trajectory, runs the arm's PD and the Hand-E controller, applies their outputs
// and advances the physics. Robots without a trajectory hold their home configuration.

#include <memory>
#include <optional>
#include <vector>

#include "controllers/hande_controller.h"
#include "controllers/joint_pd.h"
#include "controllers/trajectory_interpolator.h"
#include "core/plan.h"
#include "sim/simulation.h"

namespace dashbed::sim {

/// Per-robot tracking statistics accumulated while executing.
struct TrackingStats {
  double max_tracking_error = 0.0;  ///< [rad] max over the arm joints and steps
  std::array<double, 6> max_joint_error{};  ///< [rad] per joint
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

  /// Applies the controls for the current time and advances one time step.
  void step();

  /// The arm reference of robot r at the current time.
  controllers::JointReference reference(int r) const;
  const controllers::HandeController& gripper(int r) const { return grippers_[r]; }
  const TrackingStats& tracking(int r) const { return stats_[r]; }

 private:
  Simulation& sim_;
  double offset_;
  std::vector<std::optional<controllers::TrajectoryInterpolator>> trajectories_;  // per robot
  std::vector<controllers::JointReference> holds_;  // per robot, used without a trajectory
  std::vector<std::unique_ptr<controllers::JointPdController>> arm_controllers_;
  std::vector<controllers::HandeController> grippers_;
  std::vector<core::GripperCommand> gripper_commands_;  // sorted by time
  std::size_t next_command_ = 0;
  std::vector<TrackingStats> stats_;
};

}  // namespace dashbed::sim
