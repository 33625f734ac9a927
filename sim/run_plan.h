#pragma once
// Executing a plan in simulation with the monitor: the `dashbed sim` job as a function.

#include <functional>
#include <string>

#include "core/plan.h"
#include "core/robot_set.h"
#include "sim/monitor.h"
#include "sim/report.h"
#include "sim/simulation.h"

namespace dashbed::sim {

class PlanExecutor;

/// What an observer of a run sees after each step.
struct StepState {
  const Simulation& simulation;
  const PlanExecutor& executor;  ///< the references, the grippers' controllers
  const Monitor& monitor;        ///< the checks so far and their events
  double plan_time;              ///< [s]
};

/// Called after every simulation step.
using StepObserver = std::function<void(const StepState&)>;

/// `first`, then `then`, after every step (either may be empty).
StepObserver chained(StepObserver first, StepObserver then);

struct RunOptions {
  /// Simulated time after the plan's end, so the last placement can settle and be judged [s].
  /// Default: the world's checks.settle_time + 0.5 s.
  double tail_time = -1.0;
  /// Called after every step (renderers and samplers hook in here).
  StepObserver on_step;
};

/// Builds a simulation of `world`, lets the objects settle for physics.settle_time with the
/// robots holding still, executes the plan under the monitor and returns the report, with the
/// plan's hardware readiness (core::checkReadiness) in it. A plan with gripper commands and no
/// actions is judged on the actions inferActions finds (sim/action_inference.h).
Report runPlan(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
               const std::string& plan_file, const RunOptions& options = {});

}  // namespace dashbed::sim
